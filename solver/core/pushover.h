// Static pushover of a Model: K u + f_el(u) = lambda P under displacement control of one
// coordinate c^T u (e.g. the roof displacement, or for a 3D floor its displacement along an
// angle). Mass and damping play no part; the elements and laws are the dynamic run's.
// Each step prescribes c^T u = target k / steps and solves by Newton on the bordered system
// (Batoz & Dhatt 1979): K_t a = P, K_t b = -R, du = b + dlambda a with c^T (u + du) = target,
// so softening (negative tangent) branches are followed. Elements are committed after each step.
#pragma once

#include <Eigen/Dense>
#include <vector>

#include "solver/core/model.h"

namespace isopound {

struct PushoverOptions {
  Eigen::VectorXd pattern;  // P: the lateral load shape (N per unit lambda)
  Eigen::VectorXd control;  // c: the controlled coordinate c^T u (m)
  double target = 0.0;      // final c^T u, m (either sign)
  int steps = 200;
  double tolerance = 1e-10;  // on |R| relative to |lambda P| (and to |P| near lambda = 0)
  int max_iterations = 50;
};

struct PushoverStep {
  double control = 0.0;  // c^T u, m
  double lambda = 0.0;   // load factor
  Eigen::VectorXd u;     // displacements, m
};

// Runs from rest (the elements' committed state). Throws AnalysisError (analysis.h: exit 3) when
// a step does not converge (the curve up to it is in the message's step number), and
// std::runtime_error when the tangent is singular.
std::vector<PushoverStep> run_pushover(Model& model, const PushoverOptions& options);

// The pattern M phi_1 of the model's first mode linearised at rest (element tangents at zero),
// with phi_1 scaled so that c^T phi_1 > 0; the uniform pattern is M iota.
Eigen::VectorXd first_mode_pattern(Model& model, const Eigen::VectorXd& control);

// For a push along a direction in plan (3D): M Phi_c Phi_c^T M iota, iota the DOFs' rigid-body
// displacement for a unit ground displacement along it, Phi_c the mode with the largest effective
// mass along iota (at rest) together with every mode of the same frequency (1e-6 relative): a
// doubly symmetric building's pair of equal x and y modes then gives the load along the
// direction itself, not along whatever pair the eigensolver returned. Signed so that the
// control coordinate of Phi_c Phi_c^T M iota is positive.
Eigen::VectorXd dominant_mode_pattern(Model& model, const Eigen::VectorXd& iota,
                                      const Eigen::VectorXd& control);

}  // namespace isopound
