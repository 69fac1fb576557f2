// A model as the stepper sees it: DOFs (relative to the ground) of three kinds, linear M, C, K,
// the influence matrix of a two-component ground acceleration, and nonlinear elements.
#pragma once

#include <Eigen/Dense>
#include <array>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "solver/core/element.h"

namespace isopound {

// What a DOF measures. Translations are in m (their residuals in N); a rotation in rad (its
// residual a moment in N m).
enum class DofKind { kTranslationX, kTranslationY, kRotation };

struct Dof {
  std::string label;  // e.g. "building/base", "building/floor 2"
  int structure = 0;  // index into Model::structures
  int level = 0;      // 0 = base slab (or the lowest DOF), 1.. = floors
  DofKind kind = DofKind::kTranslationX;
  // Length (m) through which the DOF's errors are measured: 1 for a translation; for a rotation
  // e.g. the floor's radius of gyration r, so that an angle error e reads as a displacement r e
  // and a moment residual M as a force M / r (the adaptive error test and Newton's residual test
  // then compare like with like).
  double length = 1.0;
};

// Ground acceleration (m/s^2) in the model's x and y directions; a bare number is along x.
struct GroundAcceleration {
  double x = 0.0, y = 0.0;
  GroundAcceleration(double ax = 0.0, double ay = 0.0) : x(ax), y(ay) {}  // NOLINT: implicit
};

// Bookkeeping for outputs: which DOFs belong to a structure, bottom to top, and its stories.
struct StructureInfo {
  std::string name;
  std::vector<int> level_dofs;  // DOF index of each level, bottom to top
  bool has_base = false;        // level_dofs[base_level] is an isolated base slab
  // Index into level_dofs of the isolated slab when has_base: 0 when the isolators stand on the
  // ground, k when they stand on floor k of a fixed-base substructure (levels in elevation
  // order: floors 1..k, the slab, floors k+1..n). 0 for a fixed-base structure.
  int base_level = 0;
  double isolation_height = 0.0;      // m, the slab above floor base_level (base_level > 0)
  std::vector<double> story_heights;  // per floor: storey f links floor f and the level below
  int isolator_element = -1;          // index into Model::elements, or -1
  // Elements that push the base level from outside the structure (a moat wall, a neighbour's
  // base slab): their force on the isolated slab is part of the base shear, with the isolator's
  // (the force through the isolation layer).
  std::vector<int> base_contact_elements;
  // A structure in plan (3D): the y DOF of each level (level_dofs holds the x DOFs); empty in 2D.
  // Its base shear is then taken from the equilibrium of the whole structure, -sum over the
  // levels of (M a_abs) in x and y minus the contacts above the base (upper_contact_elements),
  // since its bearings may be linear springs inside K.
  std::vector<int> level_dofs_y;
  std::vector<int> upper_contact_elements;
  // Per story: index into Model::elements of its hysteretic law, or -1 (a linear spring in K).
  std::vector<int> story_elements;
  // Per story of a 2D building with façade columns: the element indices of its left and right
  // column lines (a ColumnLine, or the StruckColumn that replaced it); empty without columns.
  std::vector<std::array<int, 2>> facade_columns;
  // An elastic storey whose peak drift ratio exceeds this is outside the elastic model's range:
  // reports flag it (outputs only; 0: never). The model input sets it (default 1 %).
  double elastic_limit_drift_ratio = 0.0;

  // Index into level_dofs of floor f (1-based): the isolated slab, when above the ground, sits
  // between floors base_level and base_level + 1 and is no floor.
  int floor_level(int floor) const { return has_base && floor > base_level ? floor : floor - 1; }
  // Index into level_dofs of the level below storey `floor` (the isolated slab for the first
  // storey above it), -1 for the ground.
  int below_floor_level(int floor) const { return floor_level(floor) - 1; }
  // The isolated slab's DOF (has_base only).
  int base_dof() const { return level_dofs[static_cast<std::size_t>(base_level)]; }
  // The DOF under the isolation layer: floor base_level's, or -1 (the ground).
  int isolator_bottom_dof() const {
    return has_base && base_level > 0 ? level_dofs[static_cast<std::size_t>(base_level) - 1] : -1;
  }
};

// A derived response in plan, for outputs only: two components, each a linear combination of DOF
// values (a point of a rigid floor: u - y theta, v + x theta; a column's drift: the difference of
// that between two floors). The analysis reports peaks of x, y and of the resultant sqrt(x^2 +
// y^2) taken at each instant.
struct PlanProbe {
  enum class Quantity { kDisplacement, kAbsoluteAcceleration };
  std::string label;  // e.g. "building/floor 1/CM", "building/story 2/A1"
  Quantity quantity = Quantity::kDisplacement;
  std::vector<std::pair<int, double>> x_terms, y_terms;  // (DOF index, coefficient)
  double length = 0.0;  // > 0: also the peak of resultant / length (a drift ratio)
};

struct Model {
  Eigen::MatrixXd mass;       // M, kg (symmetric positive definite)
  Eigen::MatrixXd damping;    // C, N s/m (linear viscous)
  Eigen::MatrixXd stiffness;  // K, N/m (linear springs)
  // Equation of motion: M a + C v + K u + f_nl(u, v) = -M [influence influence_y] (a_x, a_y)^T:
  // the influence matrix (n x 2) by columns, each the DOFs' rigid-body displacement for a unit
  // ground displacement in x (influence) and in y (influence_y; empty: not excited along y).
  Eigen::VectorXd influence;
  Eigen::VectorXd influence_y;
  std::vector<std::unique_ptr<Element>> elements;
  std::vector<Dof> dofs;
  std::vector<StructureInfo> structures;
  std::vector<PlanProbe> probes;

  int size() const { return static_cast<int>(dofs.size()); }
  // Grows M, C, K and the influence columns to n DOFs; the new entries are zero.
  void grow(int n) {
    for (Eigen::MatrixXd* m : {&mass, &damping, &stiffness}) {
      const Eigen::Index old = m->rows();
      m->conservativeResize(n, n);
      m->bottomRows(n - old).setZero();
      m->rightCols(n - old).setZero();
    }
    for (Eigen::VectorXd* iota : {&influence, &influence_y}) {
      const Eigen::Index old = iota->size();
      iota->conservativeResize(n);
      iota->tail(n - old).setZero();
    }
  }
  // M times the influence matrix, n x 2 (a zero y column for a model not excited along y).
  Eigen::MatrixXd ground_load_matrix() const {
    Eigen::MatrixXd m_iota = Eigen::MatrixXd::Zero(size(), 2);
    m_iota.col(0) = mass * influence;
    if (influence_y.size() == size()) m_iota.col(1) = mass * influence_y;
    return m_iota;
  }
  // Total translational mass (along x), kg.
  double total_mass() const { return influence.dot(mass * influence); }
};

}  // namespace isopound
