// A slab striking one column of another 3D structure between its floors (issue 26, 3D): the
// column a HingedColumn per principal axis (uncoupled: along axis 1 it bends with I22, along
// axis 2 with I11), both with the lateral node at height a; the node (x, y) massless and condensed
// at every trial, f_col,node(n) + f_contact,node(n, n') = 0; the slab's plan polygon against the
// column's section (a rectangle moving with the node and turning with its twist) a PolygonContact
// (the slab-to-slab area law, friction and passivity bookkeeping). The column's ends move with the
// floors at its plan position: d = (u - y theta, v + x theta), in its axes R^T d. The section
// turns with the column's twist at the node, linear between the floors (uniform torsion between
// two rigid diaphragms): theta_n = (1 - w) theta_lower + w theta_upper, w = a / L; the contact's
// moment on the section goes to the floors with the same weights (so a slab at a floor meets the
// section as it would meet that floor). In contact the node's rate along the normal makes the
// approach rate the backward difference of the penetration depth D (-separation) since
// max(D_commit, 0), so that the Kelvin-Voigt dashpot starts from zero force at touch (a massless
// node takes the slab's approach at once) and the node's residual is continuous; for the same
// reason the damping uses the mean-depth indentation A_c / w (docs/floor-to-column.md).
#pragma once

#include <array>
#include <limits>
#include <string>
#include <vector>

#include "solver/core/element.h"
#include "solver/elements/episode_work.h"
#include "solver/elements/hinged_column.h"
#include "solver/elements/polygon_contact.h"

namespace isopound {

struct StruckColumn3DSpec {
  // Along axis 1 (I = I22) and axis 2 (I = I11): same E, L, a; M_y and H per axis.
  std::array<HingedColumnSection, 2> axis;
  double shear_capacity = 0.0;           // V_n, N, of the resultant shear (0: no shear check)
  Vec2 p_W;                              // the column's plan position, m
  double orientation = 0.0;              // rad, axis 1 from x
  std::array<int, 3> slab{-1, -1, -1};   // the striking slab's (u, v, theta) DOFs
  std::array<int, 3> lower{-1, -1, -1};  // the floor under the struck storey (-1: the ground)
  std::array<int, 3> upper{-1, -1, -1};  // the floor above it
  std::vector<Vec2> slab_plan_W;  // the slab at rest, convex (DOF origin at the plan origin), m
  // A non-convex slab (L, T, U): its outline at rest (slab_plan_W is then its convex hull), whose
  // overlap with the section is found by a one-slot PlanPair (plan_pair.h); empty when convex.
  std::vector<Vec2> slab_outline_W;
  std::vector<Vec2> section_W;  // the column's section at rest (column_rectangle), m
  double slab_mass = 0.0;       // kg
  // kg: r_lower m_lower + r_upper m_upper, the floors seen through a point load on a column
  // fixed at both ends (+inf with the ground under it: its reactions go there)
  double struck_mass = 0.0;
};

class StruckColumn3D final : public Element {
 public:
  StruckColumn3D(std::string label, const StruckColumn3DSpec& spec,
                 const PolygonContactConfig& law);

  bool add_dofs(std::vector<int>& dofs) const override;
  void set_trial(const Eigen::VectorXd& u, const Eigen::VectorXd& v) override;
  void add_force(Eigen::VectorXd& f) const override;
  void add_tangent(Eigen::MatrixXd& K, double velocity_factor) const override;
  bool has_stiffness_product() const override { return true; }
  void add_stiffness_product(const Eigen::VectorXd& x, Eigen::VectorXd& y) const override;
  bool symmetric_tangent() const override { return false; }
  double power(const Eigen::VectorXd& v) const override;
  double stored_energy() const override;
  void commit() override;
  void revert() override;

  void begin_step(double h, bool freeze_status) override;
  // The contact's, but an event whose fraction the contact interpolates linearly from the step's
  // ends (no-tension clamp, approach/restitution, stick -> slip) is found on the node solved
  // along the step (event_at): behind a dashpot the node relaxes within the step, far from
  // linearly, and the linear guess fell short again and again (hundreds of cuts of 1e-8 s).
  double event_fraction() override;
  bool settle_event() override { return contact_.settle_event(); }
  // The contact's: behind its dashpot the node's rate is the backward difference, L-stable, so
  // its relaxation time c / (k_contact + k_column) (tiny next to a floor) need not be resolved.
  double step_limit() const override { return contact_.step_limit(); }

  // The contact's outputs first, then: shear (resultant, the larger of the two segments),
  // shear_failed (latched once |V| >= V_n), per axis 1 and 2 the hinge moments at bottom, node
  // and top and their ductilities 1 + |p| / theta_y (theta_y = M_y L / (6 E I)), local drift
  // along x and y (node minus the chord between the floors) and the hinges' dissipated energy.
  int output_count() const override { return contact_.output_count() + kColumnOutputs; }
  std::string output_name(int i) const override;
  std::string output_unit(int i) const override;
  OutputKind output_kind(int i) const override;
  double output(int i) const override;
  const std::string& label() const override { return label_; }

  const PolygonContact& contact() const { return contact_; }
  const StruckColumn3DSpec& spec() const { return spec_; }
  // The node's plan displacement (x, y), m, at the trial state.
  Vec2 node_displacement() const { return {zl_(3), zl_(4)}; }
  const ColumnState& column_state(int axis) const { return state_[axis]; }
  // The node's net force (column + contact), N, and the column's force scale (the sum of the
  // magnitudes of its end and node forces, both axes), N, at the trial state: the node is
  // balanced when the first is at the round-off of the second.
  Vec2 node_force() const { return {fl_(3), fl_(4)}; }
  double column_force() const {
    return state_[0].force.cwiseAbs().sum() + state_[1].force.cwiseAbs().sum();
  }
  double shear() const;
  Vec2 local_drift() const;
  double hinge_dissipated_energy() const;
  // Passivity of the whole element (column, node and contact) per contact episode: what the
  // floors' and the slab's DOFs put into it, W = ∫ v·f dt (trapezoid over accepted steps), less
  // what it stores (the columns' and the contact's elastic energy). Over an episode (onset to
  // separation) W − E_stored may only grow; the largest net work the element did on the
  // structures over one (J; ≤ 0 for a passive element, −inf before any episode), and that over
  // the episode's gross ∫ |v·f| dt. The contact's own episode measure (contact().
  // max_episode_net_work) takes the node's rate behind the dashpot (the depth rule, not dx/dt):
  // the physical one is this.
  int episodes() const { return episode_work_.episodes(); }
  double max_episode_net_work() const { return episode_work_.max_net_work(); }
  double max_episode_net_work_relative() const { return episode_work_.max_net_work_relative(); }

 private:
  static constexpr int kColumnOutputs = 17;
  // Local coordinates z: slab (u, v, theta) 0-2, node (x, y) 3-4, lower 5-7, upper 8-10, and
  // the section's twist 11, a function of 7 and 10 (not a coordinate of its own).
  static constexpr int kLocal = 12;
  static constexpr int kTwist = 11;
  using MatL = Eigen::Matrix<double, kLocal, kLocal>;
  using Map3xL = Eigen::Matrix<double, 3, kLocal>;

  void gather(const Eigen::VectorXd& u, const Eigen::VectorXd& v);
  // The node balanced for the floors and slab in zl_, zdl_ (set_trial after gather).
  void solve_node();
  // The contact's event indicator with the floors and slab at fraction theta of the step
  // (linear between the committed and trial states) and the node solved there.
  double indicator_at(double theta, const Eigen::VectorXd& z1, const Eigen::VectorXd& zd1,
                      double h);
  // Column states and contact at the node's trial position z_(3..4); the node's residual and
  // (given a slope) the column's 2 x 2 part of its derivative.
  Eigen::Vector2d node_residual(Eigen::Matrix2d* slope);
  // The local tangent (column + contact, node velocity by its rule) into kz_; the condensed one
  // on the 9 floor/slab coordinates into kc_.
  void condensed_tangent(double velocity_factor) const;
  // d(node rate)/d(node) times h, by the trial's rule.
  Eigen::Matrix2d node_rate_slope() const;
  // The contact at its present state acts through a dashpot on the node.
  bool contact_damped() const;
  // The floors' lateral displacement (or rate) at the column, plan frame: (1 - w) d_l + w d_u.
  Eigen::Vector2d chord(const Eigen::VectorXd& z, double w) const;
  int global_dof(int local) const;  // -1: the ground
  // The section's twist (and rate) from the floors' into z(kTwist); a force on it to the floors.
  void set_twist();
  void spread_twist_force();

  std::string label_;
  StruckColumn3DSpec spec_;
  std::array<HingedColumn, 2> column_;
  double twist_weight_ = 0.0;      // w = a / L of the upper floor's twist in the section's
  double force_per_length_ = 0.0;  // N/m: the stiffer axis's elastic stiffness at the node
  std::array<Map3xL, 2> map_;      // (lower, node, upper) of axis i from z
  PolygonContact contact_;
  double h_ = 0.0;
  Eigen::Vector2d node_commit_ = Eigen::Vector2d::Zero(), rate_commit_ = Eigen::Vector2d::Zero();
  Eigen::Vector2d offset_commit_ = Eigen::Vector2d::Zero();  // node minus the elastic shape, m
  std::array<HingeRotations, 2> plastic_commit_{HingeRotations::Zero(), HingeRotations::Zero()};
  std::array<ColumnState, 2> state_;
  bool damped_commit_ = false;
  // The trial's node rate along the contact normal by the depth rule (node_residual), and the
  // normal; the committed depth max(D, 0), m.
  bool depth_rule_ = false;
  Eigen::Vector2d normal_ = Eigen::Vector2d::Zero();
  double depth_commit_ = 0.0;
  bool shear_failed_ = false, shear_failed_commit_ = false;
  double hinge_energy_ = 0.0;
  double work_ = 0.0, gross_work_ = 0.0, power_commit_ = 0.0;  // J, J, W (committed)
  bool closed_commit_ = false;
  double episode_dissipated_ = 0.0, episode_gross_ = 0.0;  // W − E_stored, gross: at the onset
  EpisodeWork episode_work_;
  // Local displacement, rate and force (the contact works on vectors of kLocal; allocated once).
  Eigen::VectorXd zl_, zdl_, fl_;
  Eigen::VectorXd z_commit_, zd_commit_;  // the committed zl_, zdl_
  mutable Eigen::MatrixXd kk_, kd_;
  mutable MatL kz_;
  mutable Eigen::Matrix<double, 9, 9> kc_;
};

}  // namespace isopound
