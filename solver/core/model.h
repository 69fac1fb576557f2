// A model as the stepper sees it: DOFs (relative to the ground), linear M, C, K, the ground
// motion influence vector, and nonlinear elements. Several structures may share one model.
#pragma once

#include <Eigen/Dense>
#include <memory>
#include <string>
#include <vector>

#include "solver/core/element.h"

namespace isopound {

struct Dof {
  std::string label;  // e.g. "building/base", "building/floor 2"
  int structure = 0;  // index into Model::structures
  int level = 0;      // 0 = base slab (or the lowest DOF), 1.. = floors
};

// Bookkeeping for outputs: which DOFs belong to a structure, bottom to top, and its stories.
struct StructureInfo {
  std::string name;
  std::vector<int> level_dofs;        // DOF index of each level, bottom to top
  bool has_base = false;              // level_dofs[0] is an isolated base slab
  std::vector<double> story_heights;  // story s links level s-1 (or ground) and level s
  int isolator_element = -1;          // index into Model::elements, or -1
};

struct Model {
  Eigen::MatrixXd mass;       // M, kg (symmetric positive definite)
  Eigen::MatrixXd damping;    // C, N s/m (linear viscous)
  Eigen::MatrixXd stiffness;  // K, N/m (linear springs)
  // Equation of motion: M a + C v + K u + f_nl(u, v) = -M influence a_g(t).
  Eigen::VectorXd influence;
  std::vector<std::unique_ptr<Element>> elements;
  std::vector<Dof> dofs;
  std::vector<StructureInfo> structures;

  int size() const { return static_cast<int>(dofs.size()); }
  // Grows M, C, K and the influence vector to n DOFs; the new rows and columns are zero.
  void grow(int n) {
    for (Eigen::MatrixXd* m : {&mass, &damping, &stiffness}) {
      const Eigen::Index old = m->rows();
      m->conservativeResize(n, n);
      m->bottomRows(n - old).setZero();
      m->rightCols(n - old).setZero();
    }
    const Eigen::Index old = influence.size();
    influence.conservativeResize(n);
    influence.tail(n - old).setZero();
  }
  double total_mass() const { return influence.dot(mass * influence); }
};

}  // namespace isopound
