// A bearing between the ground (or a lower rigid diaphragm: a building isolated above a storey)
// and a rigid diaphragm at plan position p = (x, y) relative to the diaphragms' DOF origin:
// deformation d = T (q - q_lower) = (u - y theta, v + x theta) relative to the lower diaphragm,
// force F(d) on the slab and -F(d) on the lower diaphragm.
#pragma once

#include <Eigen/Dense>
#include <memory>
#include <string>

#include "solver/core/element.h"
#include "solver/materials/biaxial_material.h"
#include "solver/materials/bouc_wen_coupled.h"

namespace isopound {

// DOF indices of the diaphragm the bearing carries; -1 for a DOF the model does not have
// (a 2D building has only ux: dof_uy = dof_theta = -1, and the bearing acts along x only).
struct DiaphragmDofs {
  int ux = -1, uy = -1, theta = -1;
};

// Generalised force on the diaphragm: f = T^T F with T = [[1, 0, -y], [0, 1, x]] (x, y the
// bearing's position in the diaphragm DOFs' frame); tangent T^T (K + velocity_factor K_v) T.
//
// Outputs. Planar (only ux present): "force", "deformation", "z" along x, signed, as the 2D
// UniaxialLink (so reports and study selectors such as isolator.force read both alike).
// In plan: "force", "deformation", "z" are the resultants |F|, |d|, |z|, followed by
// "force_x", "force_y", "deformation_x", "deformation_y", "z_x", "z_y".
class BearingLink final : public Element {
 public:
  // lower: the diaphragm under the bearing (DiaphragmDofs{}: the ground).
  BearingLink(std::string label, DiaphragmDofs dofs, Eigen::Vector2d p_OB,
              std::unique_ptr<BiaxialMaterial> law, DiaphragmDofs lower = {});

  void set_trial(const Eigen::VectorXd& u, const Eigen::VectorXd& v) override;
  // Bearings with the coupled Bouc-Wen law form batches (Element::batch_key): their n = 2
  // closed forms overlap (CoupledBoucWenMaterial::set_trials), and the forces and tangents of
  // the bearings under one 3D diaphragm are summed in registers, in the same order.
  const void* batch_key() const override;
  void set_trial_batch(Element* const* elements, int count, const Eigen::VectorXd& u,
                       const Eigen::VectorXd& v) override;
  void add_force_batch(Element* const* elements, int count, Eigen::VectorXd& f) const override;
  void add_tangent_batch(Element* const* elements, int count, Eigen::MatrixXd& K,
                         double velocity_factor) const override;
  void add_stiffness_product_batch(Element* const* elements, int count, const Eigen::VectorXd& x,
                                   Eigen::VectorXd& y) const override;
  void outputs_batch(Element* const* elements, int count, double* out) const override;
  void add_energy_batch(Element* const* elements, int count, const Eigen::VectorXd& v,
                        double& power, double& stored) const override;
  void add_force(Eigen::VectorXd& f) const override;
  void add_tangent(Eigen::MatrixXd& K, double velocity_factor) const override;
  bool has_stiffness_product() const override { return true; }
  bool has_events() const override { return false; }
  void add_stiffness_product(const Eigen::VectorXd& x, Eigen::VectorXd& y) const override;
  bool add_dofs(std::vector<int>& dofs) const override {
    for (const int d : {dofs_.ux, dofs_.uy, dofs_.theta, lower_.ux, lower_.uy, lower_.theta})
      if (d >= 0) dofs.push_back(d);
    return true;
  }
  // The law's symmetry; a planar bearing (one DOF) always gives a symmetric 1x1 block.
  bool symmetric_tangent() const override { return planar_ || law_->symmetric_tangent(); }
  double power(const Eigen::VectorXd& v) const override;
  double stored_energy() const override;
  void commit() override;
  void revert() override;

  int output_count() const override { return planar_ ? 3 : 9; }
  std::string output_name(int i) const override;
  std::string output_unit(int i) const override;
  double output(int i) const override;
  void outputs(double* out) const override;
  const std::string& label() const override { return label_; }

  const BiaxialMaterial& law() const { return *law_; }
  const Eigen::Vector2d& position() const { return p_OB_; }
  // Bearing deformation (m) and its rate from the DOFs: d = T (u - u_lower) over the DOFs
  // present.
  Eigen::Vector2d deformation_of(const Eigen::VectorXd& u) const;

 private:
  // f(law) with the law's concrete type when it is the coupled Bouc-Wen (a final class, so its
  // calls are direct and inline: the bearing is called ~200 times a step), else virtually.
  // f += T^T F over the DOFs present.
  void scatter(const Eigen::Vector2d& F, Eigen::VectorXd& f) const;
  template <class F>
  decltype(auto) with_law(F&& f) const {
    return coupled_ ? f(*coupled_) : f(*law_);
  }

  // The batch's bearings on one 3D diaphragm at a time: block(ux, run, n) for each run of
  // consecutive such bearings sharing (ux, ux + 1, ux + 2), single(link) for any other bearing.
  template <class Single, class Block>
  static void for_each_diaphragm_run(Element* const* elements, int count, Single&& single,
                                     Block&& block);
  // f(ux .. ux + 2) += T^T force_of(link) over a run's bearings on one diaphragm, summed in
  // registers in run order (the sums scatter() makes bearing by bearing).
  template <class ForceOf>
  static void scatter_run(Element* const* run, int n, int ux, Eigen::VectorXd& f,
                          ForceOf&& force_of);
  // T^T k T's entries for this bearing's k, column by column (see add_tangent).
  void diaphragm_tangent(const Eigen::Matrix2d& k, double kt[9]) const;
  Eigen::Matrix2d law_tangent(double velocity_factor) const;
  // outputs() from the law's force, deformation and hysteretic variables.
  void write_outputs(const Eigen::Vector2d& F, const Eigen::Vector2d& d, const Eigen::Vector2d& z,
                     double* out) const;
  // The same with the resultants squared (|F|^2, |d|^2, |z|^2): the caller takes their roots.
  void write_outputs_squared(const Eigen::Vector2d& F, const Eigen::Vector2d& d,
                             const Eigen::Vector2d& z, double* out) const;

  std::string label_;
  DiaphragmDofs dofs_;
  DiaphragmDofs lower_;  // the diaphragm under the bearing; all -1: the ground
  bool has_lower_;
  Eigen::Vector2d p_OB_;
  std::unique_ptr<BiaxialMaterial> law_;
  CoupledBoucWenMaterial* coupled_;  // law_ when it is one, else null
  bool planar_;
  // The three DOFs are present and consecutive (a 3D diaphragm) and the bearing stands on the
  // ground: the diaphragm-run fast paths; a bearing on a lower diaphragm takes the general ones.
  bool consecutive_;
};

}  // namespace isopound
