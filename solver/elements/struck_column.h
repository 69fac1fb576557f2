// A slab striking a column line of another structure between its floors (2D): `count` identical
// HingedColumns in parallel between the floors, whose struck node is massless and condensed at
// every trial, f_col,node(u_node) + f_contact,node(u_node, v_node) = 0 (v_node: with no dashpot
// on it, the floors' velocities through the column's tangent; behind a contact's dashpot the
// backward difference (u - u_0) / h), and the slab's contact with the node a Contact1D on
// the pair (slab, node): delta = s (u_slab - u_node) - gap, F >= 0 pushes them apart.
#pragma once

#include <memory>
#include <string>

#include "solver/core/element.h"
#include "solver/elements/contact.h"
#include "solver/elements/hinged_column.h"

namespace isopound {

struct StruckColumnSpec {
  HingedColumnSection column;   // one column
  int count = 1;                // n columns of the facing line, struck together
  double shear_capacity = 0.0;  // V_n of one column, N (0: no shear check)
  int slab = -1;                // the striking level's DOF
  double side = 1.0;            // s = +1: the slab closes the gap moving +x
  int lower = -1;               // the floor below the struck storey (-1: the ground)
  int upper = -1;               // the floor above it
};

class StruckColumn final : public Element {
 public:
  StruckColumn(std::string label, const StruckColumnSpec& spec, double gap,
               std::unique_ptr<ImpactLaw> law, double effective_mass, double steps_per_contact);

  bool add_dofs(std::vector<int>& dofs) const override;
  void set_trial(const Eigen::VectorXd& u, const Eigen::VectorXd& v) override;
  void add_force(Eigen::VectorXd& f) const override;
  void add_tangent(Eigen::MatrixXd& K, double velocity_factor) const override;
  bool has_stiffness_product() const override { return true; }
  void add_stiffness_product(const Eigen::VectorXd& x, Eigen::VectorXd& y) const override;
  double power(const Eigen::VectorXd& v) const override;
  double stored_energy() const override;
  void commit() override;
  void revert() override;

  void begin_step(double h, bool freeze_status) override;
  // The contact's, but a cut ending within 1 ns of the step's end ends at the end (the stepper
  // took the remainder as a step of its own: 1e-14 s).
  double event_fraction() override;
  bool settle_event() override { return contact_.settle_event(); }
  // The contact's limit and, behind a dashpot, the node's relaxation time c / (k_contact +
  // k_node): the backward difference is first order in h over it.
  double step_limit() const override;

  // The contact's outputs (force, penetration, impacts, ...) first, then per column: shear
  // (the larger of the two segments), shear_failed (0/1, latched once |V| >= V_n), the hinge
  // moments at bottom, node and top, their ductilities 1 + |p| / theta_y (theta_y = M_y L /
  // (6 E I), the chord rotation at first yield of the column fixed at both ends), local_drift
  // (node minus the chord between the floors) and the hinges' dissipated energy (all columns).
  int output_count() const override { return contact_.output_count() + kColumnOutputs; }
  std::string output_name(int i) const override;
  std::string output_unit(int i) const override;
  OutputKind output_kind(int i) const override;
  double output(int i) const override;
  const std::string& label() const override { return label_; }

  const Contact1D& contact() const { return contact_; }
  const StruckColumnSpec& spec() const { return spec_; }
  const HingedColumn& column() const { return column_; }
  double node_displacement() const { return u_node_; }
  // Per column at the trial state.
  const ColumnState& column_state() const { return state_; }
  double local_drift() const;
  double shear() const;
  // M_y sum |dp| over the committed steps, all columns, J.
  double hinge_dissipated_energy() const { return hinge_energy_; }

 private:
  static constexpr int kColumnOutputs = 10;
  // Local vectors: 0 slab, 1 lower, 2 upper, 3 node.
  void gather(const Eigen::VectorXd& u, const Eigen::VectorXd& v);
  // Node force (column + contact) and its derivative at the node's trial position.
  double node_residual(double& slope);
  // K on (slab, lower, upper) with the node condensed, into k3_.
  void condensed_tangent(double velocity_factor) const;

  std::string label_;
  StruckColumnSpec spec_;
  HingedColumn column_;
  double count_;
  Contact1D contact_;
  double h_ = 0.0;
  double u_node_ = 0.0, v_node_ = 0.0, u_node_commit_ = 0.0, v_node_commit_ = 0.0;
  double offset_commit_ = 0.0;  // committed node minus the elastic shape between its floors, m
  bool damped_commit_ = false;  // the committed contact acts on the node through a dashpot
  bool hold_velocity_ = false;  // node_residual keeps v_node_ (the restart's velocity solve)
  // Steps shorter than this (s, cut at events) take the node's committed velocity: a difference
  // over them is round-off.
  static constexpr double kShortestDifference = 1e-9;
  static constexpr double kRelaxationSteps = 10.0;  // largest step / relaxation time
  bool by_difference() const { return damped_commit_ && h_ > kShortestDifference; }
  HingeRotations plastic_commit_ = HingeRotations::Zero();
  ColumnState state_;
  bool shear_failed_ = false, shear_failed_commit_ = false;
  double hinge_energy_ = 0.0;
  Eigen::VectorXd ul_, vl_, fl_;
  mutable Eigen::MatrixXd kl_, kc_;
  mutable Eigen::Matrix3d k3_;
};

}  // namespace isopound
