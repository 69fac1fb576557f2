// A yielding column between two rigid diaphragms (issue 23): the lateral deformation of the
// column's plan point p, d_W = T(p) (q_upper - q_lower) with T = [[1, 0, -y], [0, 1, x]] and
// q = (u, v, theta) of each diaphragm (the lower one may be the ground), turned into the column's
// section axes d_L = R^T d_W (axis 1 at `orientation` from x) and normalised per axis,
// x_i = d_L,i / d_y,i. A biaxial law with unit stiffness, yield force and yield displacement acts
// on x; the column shear is V_L,i = V_y,i F_i(x) (V_y,i = k_i d_y,i), so the interaction is the
// law's circle in (V_1 / V_y,1, V_2 / V_y,2). Forces on the diaphragms: f_upper = T^T R V_L,
// f_lower = -f_upper; tangent B^T R diag(V_y) K diag(1/d_y) R^T B with B = [T, -T].
// Only the lateral shear lives here: the column's torsion G J / h stays in the stiffness matrix.
#pragma once

#include <Eigen/Dense>
#include <memory>
#include <string>

#include "solver/core/element.h"
#include "solver/elements/bearing_link.h"
#include "solver/materials/biaxial_material.h"
#include "solver/materials/bouc_wen_coupled.h"

namespace isopound {

// The column's geometry and yield point, SI, in the model's plan frame.
struct ColumnLinkGeometry {
  Eigen::Vector2d p_O;          // plan point relative to both diaphragms' DOF origin, m
  double orientation = 0.0;     // rad, section axis 1 from x
  Eigen::Vector2d yield_drift;  // d_y,i per section axis, m (> 0)
  Eigen::Vector2d yield_shear;  // V_y,i per section axis, N (> 0)
};

// Outputs: "shear" |V| (N), "drift" |d| (m), "ductility" max_i |d_L,i| / d_y,i, "shear_x",
// "shear_y" (plan frame, the sign of F = k d with d = upper - lower), "drift_x", "drift_y",
// "z_1", "z_2" (the law's hysteretic variables), "yielded" (0 until the
// first committed state with ductility >= 1, then 1: its peak's time is the time of first
// yield), "hysteretic_energy" (J: the law's work, trapezoidal over committed states, minus its
// recoverable energy).
class ColumnLink final : public Element {
 public:
  // unit_law: K_el = 1, F_y = 1, u_y = 1 (dimensionless); alpha its post-yield ratio (for the
  // split of its recoverable energy over the axes, see stored_energy()).
  ColumnLink(std::string label, DiaphragmDofs upper, DiaphragmDofs lower,
             const ColumnLinkGeometry& geometry, std::unique_ptr<BiaxialMaterial> unit_law,
             double alpha);

  void set_trial(const Eigen::VectorXd& u, const Eigen::VectorXd& v) override;
  void add_force(Eigen::VectorXd& f) const override;
  void add_tangent(Eigen::MatrixXd& K, double velocity_factor) const override;
  bool add_dofs(std::vector<int>& dofs) const override;
  bool has_stiffness_product() const override { return true; }
  void add_stiffness_product(const Eigen::VectorXd& x, Eigen::VectorXd& y) const override;
  bool symmetric_tangent() const override;
  bool has_events() const override { return false; }
  double power(const Eigen::VectorXd& v) const override;
  // sum_i w_i (alpha x_i^2 / 2) + H sum_i w_i z_i^2 / |z|^2 with w_i = V_y,i d_y,i and H the
  // unit law's recoverable hysteretic energy (c |z|^2 for both the bilinear and the Bouc-Wen
  // law, so the split over the axes is exact); w_1 = w_2: w times the unit law's energy.
  double stored_energy() const override;
  void commit() override;
  void revert() override;

  int output_count() const override;
  std::string output_name(int i) const override;
  std::string output_unit(int i) const override;
  OutputKind output_kind(int i) const override;
  double output(int i) const override;
  void outputs(double* out) const override;
  const std::string& label() const override { return label_; }

  // Columns form batches (Element::batch_key): one key for the coupled Bouc-Wen law (its trials
  // taken together, CoupledBoucWenMaterial::set_trials), one for any other law; within a batch,
  // each run of consecutive columns between the same two diaphragms (a storey) sums its forces
  // and tangents in registers, in run order: the single calls' sums, bit for bit.
  const void* batch_key() const override;
  void set_trial_batch(Element* const* elements, int count, const Eigen::VectorXd& u,
                       const Eigen::VectorXd& v) override;
  void add_force_batch(Element* const* elements, int count, Eigen::VectorXd& f) const override;
  void add_tangent_batch(Element* const* elements, int count, Eigen::MatrixXd& K,
                         double velocity_factor) const override;

  // Plan-frame deformation d_W of the column for DOF values u, m.
  Eigen::Vector2d deformation_of(const Eigen::VectorXd& u) const;
  // Column shear in the plan frame (force on the upper diaphragm's side, F = K d sign), N.
  Eigen::Vector2d shear_W() const;
  // Energy dissipated so far (J): committed work minus the recoverable energy.
  double hysteretic_energy() const { return work_commit_ - stored_energy(); }

 private:
  // Plan-frame tangent dF_W / dd_W, N/m.
  Eigen::Matrix2d tangent_W() const;
  // f += T^T F on the upper DOFs, -T^T F on the lower.
  void scatter(const Eigen::Vector2d& F_W, Eigen::VectorXd& f) const;
  // T^T k_W T: the tangent on one diaphragm's (u, v, theta).
  Eigen::Matrix3d diaphragm_tangent() const;
  // block(first, run, n) for each run of consecutive columns with the same six DOFs.
  template <class Block>
  static void for_each_storey_run(Element* const* elements, int count, Block&& block);

  std::string label_;
  int dof_[6];  // upper ux, uy, theta, lower ux, uy, theta (-1: ground or absent)
  double sign_[6];
  ColumnLinkGeometry g_;
  Eigen::Matrix2d R_;  // columns: section axes 1 and 2 in the plan frame
  std::unique_ptr<BiaxialMaterial> law_;
  CoupledBoucWenMaterial* coupled_ = nullptr;  // law_ when it is the coupled Bouc-Wen law
  int dof_count_ = 3;                          // 6 with a lower diaphragm, 3 on the ground
  double alpha_;
  // Committed work of the law, J, and the committed (local) force and deformation.
  double work_commit_ = 0.0;
  Eigen::Vector2d force_commit_ = Eigen::Vector2d::Zero(), drift_commit_ = Eigen::Vector2d::Zero();
  bool yielded_ = false;
};

}  // namespace isopound
