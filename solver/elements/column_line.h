// A column line between two floors that no slab strikes: `count` identical columns in parallel,
// each a HingedColumn per bending direction (hinged_column.h), fixed at both ends by the floors,
// plastic hinges at both ends (|m_h + H p_h| <= M_y). Along each direction the drift is a linear
// combination of the floors' DOFs, d = sum c_i u_i (2D: u_upper - u_lower, one direction; 3D: a
// column's displacement along each principal axis from both diaphragms' u, v, theta), and the
// force acts back through the same coefficients. The column's node sits at mid-height, where the
// moment of a column swaying between two rigid floors is zero, so its hinge never forms and the
// node is the chord's midpoint: the floors see n 12 E I / L^3 per direction while elastic, the
// hinges at M_y at both ends beyond (directions uncoupled, as in the struck column). A slab that
// strikes such a column replaces it by a struck column (struck_column.h, struck_column3d.h) with
// the same section and hinges, so a building means the same thing with or without a neighbour
// (issue 37).
#pragma once

#include <array>
#include <string>

#include "solver/core/element.h"
#include "solver/elements/hinged_column.h"

namespace isopound {

struct ColumnLineSpec {
  // The drift along one direction, d = sum c_i u[dof_i] (upper floor minus lower; the ground's
  // terms left out), and the column's section bending along it (node placed at mid-height).
  struct Direction {
    HingedColumnSection column;
    std::array<int, 6> dof{};
    std::array<double, 6> coefficient{};
    int terms = 0;
    void add_term(int d, double c) {
      if (d < 0 || c == 0.0) return;
      dof[static_cast<std::size_t>(terms)] = d;
      coefficient[static_cast<std::size_t>(terms++)] = c;
    }
  };
  std::array<Direction, 2> directions;
  int direction_count = 1;
  int count = 1;                // n columns of the line
  double shear_capacity = 0.0;  // V_n of one column, N, of the resultant shear (0: no check)
};

class ColumnLine final : public Element {
 public:
  ColumnLine(std::string label, const ColumnLineSpec& spec);

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
  bool has_events() const override { return false; }

  // Per column: shear (the resultant over directions), shear_failed (0/1, latched once
  // |V| >= V_n), the end moments and their ductilities 1 + |p| / theta_y (theta_y = M_y L /
  // (6 E I); the largest over directions), and the hinges' dissipated energy (all columns): the
  // names of StruckColumn's column outputs.
  int output_count() const override { return kOutputs; }
  std::string output_name(int i) const override;
  std::string output_unit(int i) const override;
  OutputKind output_kind(int i) const override;
  double output(int i) const override;
  const std::string& label() const override { return label_; }

  const ColumnLineSpec& spec() const { return spec_; }
  // M_y sum |dp| over the committed steps, all columns, J.
  double hinge_dissipated_energy() const;

 private:
  static constexpr int kOutputs = 7;
  struct Axis {
    explicit Axis(const HingedColumnSection& section) : column(section) {}
    HingedColumn column;
    HingeRotations plastic_commit = HingeRotations::Zero();
    ColumnState state;
    double force = 0.0, stiffness = 0.0;  // along the drift, node condensed, all columns
    double energy = 0.0;                  // committed hinge dissipation, all columns, J
  };
  double shear() const;
  double end_moment(int hinge) const;
  double ductility(int hinge) const;

  std::string label_;
  ColumnLineSpec spec_;
  std::array<Axis, 2> axes_;
  double count_;
  bool shear_failed_ = false, shear_failed_commit_ = false;
};

}  // namespace isopound
