// Displacement-controlled static pushover (equations in the header).
#include "solver/core/pushover.h"

#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>

#include "solver/core/analysis.h"
#include "solver/core/modes.h"

namespace isopound {

namespace {

// Tangent K + sum of element tangents and residual K u + f_el - lambda P at u (v = 0).
void linearise(Model& model, const Eigen::VectorXd& u, double lambda, const Eigen::VectorXd& p,
               Eigen::MatrixXd& tangent, Eigen::VectorXd& residual) {
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(model.size());
  tangent = model.stiffness;
  residual = model.stiffness * u - lambda * p;
  for (auto& e : model.elements) {
    e->set_trial(u, zero);
    e->add_force(residual);
    e->add_tangent(tangent, 0.0);
  }
}

}  // namespace

Eigen::VectorXd first_mode_pattern(Model& model, const Eigen::VectorXd& control) {
  const Modes modes = compute_modes(stiffness_at_rest(model), model.mass, model.influence);
  Eigen::VectorXd phi = modes.shape.col(0);
  if (control.dot(phi) < 0) phi = -phi;
  return model.mass * phi;
}

Eigen::VectorXd dominant_mode_pattern(Model& model, const Eigen::VectorXd& iota,
                                      const Eigen::VectorXd& control) {
  const Modes modes = compute_modes(stiffness_at_rest(model), model.mass, iota);
  Eigen::Index dominant = 0;
  modes.effective_mass_ratio.maxCoeff(&dominant);
  const double omega = modes.omega[dominant];
  Eigen::VectorXd shape = Eigen::VectorXd::Zero(model.size());
  for (Eigen::Index j = 0; j < modes.omega.size(); ++j)
    if (std::abs(modes.omega[j] - omega) <= 1e-6 * omega)
      shape += modes.shape.col(j) * modes.participation[j];
  if (control.dot(shape) < 0) shape = -shape;
  return model.mass * shape;
}

std::vector<PushoverStep> run_pushover(Model& model, const PushoverOptions& o) {
  const int n = model.size();
  if (o.pattern.size() != n || o.control.size() != n || o.steps < 1)
    throw std::invalid_argument("pushover: pattern and control need one entry per DOF");
  std::vector<PushoverStep> curve;
  curve.push_back({0.0, 0.0, Eigen::VectorXd::Zero(n)});
  Eigen::VectorXd u = Eigen::VectorXd::Zero(n), residual(n);
  Eigen::MatrixXd tangent(n, n);
  double lambda = 0.0;
  const double p_norm = o.pattern.norm();
  for (int step = 1; step <= o.steps; ++step) {
    const double target = o.target * step / o.steps;
    bool converged = false;
    for (int it = 0; it < o.max_iterations && !converged; ++it) {
      linearise(model, u, lambda, o.pattern, tangent, residual);
      const Eigen::PartialPivLU<Eigen::MatrixXd> lu(tangent);
      const Eigen::VectorXd a = lu.solve(o.pattern);
      const Eigen::VectorXd b = lu.solve(-residual);
      const double ca = o.control.dot(a);
      if (!std::isfinite(ca) || ca == 0.0)
        throw std::runtime_error("pushover: singular tangent at step " + std::to_string(step));
      const double dlambda = (target - o.control.dot(u) - o.control.dot(b)) / ca;
      const Eigen::VectorXd du = b + dlambda * a;
      const bool residual_small =
          residual.norm() <= o.tolerance * std::max(std::abs(lambda), 1.0) * p_norm;
      u += du;
      lambda += dlambda;
      converged = residual_small && du.norm() <= 1e-12 * std::max(u.norm(), 1e-9) &&
                  std::abs(dlambda) <= 1e-12 * std::max(std::abs(lambda), 1.0);
    }
    if (!converged) {
      char where[160];
      std::snprintf(where, sizeof where, " (control coordinate %.4g m, load factor %.4g)",
                    target, lambda);
      // A diverged analysis (exit 3), as a time-history run's.
      throw AnalysisError(0.0, "",
                          "pushover: Newton did not converge at step " + std::to_string(step) +
                              " of " + std::to_string(o.steps) + where +
                              "; more steps (--steps) take smaller increments");
    }
    linearise(model, u, lambda, o.pattern, tangent, residual);
    for (auto& e : model.elements) e->commit();
    curve.push_back({o.control.dot(u), lambda, u});
  }
  return curve;
}

}  // namespace isopound
