// Rubber bumper on a wall face (issue 27): Hunt-Crossley-type rubber with its damping factor
// solved for an exact e, bottoming out onto the wall's concrete law in series.
#include "solver/materials/bumper_law.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace isopound {

namespace {

struct Power {
  double value, slope;  // x^n and n x^(n-1)
};

Power power(double x, double n) {
  if (n == 1.0) return {x, 1.0};
  const double s = std::sqrt(x);  // n = 1.5, the only other form
  return {x * s, 1.5 * s};
}

std::string text(double v) {
  std::ostringstream os;
  os.precision(10);
  os << v;
  return os.str();
}

}  // namespace

// Separating variables in x'' = -x^n (1 + zeta x') (v = x'): v dv / (1 + zeta v) = -x^n dx, so
// the approach (v: 1 -> 0) and the restitution (v: 0 -> -e) take the same integral of x^n and
// phi(1) = phi(-e), phi(v) = v / zeta - ln(1 + zeta v) / zeta^2:
//   ln((1 + zeta) / (1 - e zeta)) = (1 + e) zeta,
// whatever n. Its root lies in (0, 1/e) (the left side minus the right is -(1 - e^2) zeta^2 / 2
// near 0 and +inf at 1/e); there 1 + zeta v > 0 for v > -e, so the clamp never acts in a free
// impact.
double hunt_crossley_factor(double e) {
  if (!(e > 0.0 && e <= 1.0))
    throw std::invalid_argument("bumper: coefficient of restitution e = " + text(e) +
                                " must be in (0, 1]");
  if (e == 1.0) return 0.0;
  const auto excess = [e](double zeta) {
    return std::log1p(zeta) - std::log1p(-e * zeta) - (1.0 + e) * zeta;
  };
  double lo = 0.0, hi = 1.0 / e;
  for (int it = 0; it < 200 && hi - lo > 1e-15 * hi; ++it) {
    const double mid = 0.5 * (lo + hi);
    (excess(mid) < 0 ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

double bumper_stiffness(const BumperConfig& b) {
  if (b.k > 0) return b.k;
  const double n = b.law == "hertz" ? 1.5 : 1.0;
  return b.modulus * b.area / std::pow(b.thickness, n);
}

BumperLaw::BumperLaw(const BumperConfig& b, std::unique_ptr<ImpactLaw> wall)
    : thickness_(b.thickness),
      bottom_(b.max_strain * b.thickness),
      k_(bumper_stiffness(b)),
      n_(b.law == "hertz" ? 1.5 : 1.0),
      e_(b.e),
      zeta_(hunt_crossley_factor(b.e)),
      min_impact_velocity_(b.min_impact_velocity),
      jump_(b.bottoming == BumperBottoming::kJump),
      wall_(std::move(wall)) {}

std::unique_ptr<ImpactLaw> BumperLaw::clone() const {
  std::unique_ptr<BumperLaw> copy(new BumperLaw(*this, nullptr));
  copy->wall_ = wall_->clone();
  return copy;
}

// Private copy helper: the constructor above needs a config; this one copies the numbers.
BumperLaw::BumperLaw(const BumperLaw& other, std::nullptr_t)
    : ImpactLaw(),
      thickness_(other.thickness_),
      bottom_(other.bottom_),
      k_(other.k_),
      n_(other.n_),
      e_(other.e_),
      zeta_(other.zeta_),
      min_impact_velocity_(other.min_impact_velocity_),
      jump_(other.jump_) {}

void BumperLaw::begin_contact(double impact_velocity, ImpactPhase& phase) const {
  phase.impact_velocity =
      impact_velocity > min_impact_velocity_ ? impact_velocity : min_impact_velocity_;
  phase.restitution = e_;
  phase.damping = zeta_ * k_ / phase.impact_velocity;  // N s/m^(n+1): F_r = K + damping x^n x'
  ImpactPhase w;
  wall_->begin_contact(impact_velocity, w);
  phase.wall_impact_velocity = w.impact_velocity;
  phase.wall_restitution = w.restitution;
  phase.wall_damping = w.damping;
  phase.bottomed = false;
}

ImpactPhase BumperLaw::wall_phase(const ImpactPhase& phase) const {
  ImpactPhase w;
  w.impact_velocity = phase.wall_impact_velocity;
  w.restitution = phase.wall_restitution;
  w.damping = phase.wall_damping;
  return w;
}

double BumperLaw::compression(double delta) const {
  return std::clamp(delta, 0.0, bottom_);
}

ImpactResponse BumperLaw::respond(double delta, double rate, const ImpactPhase& phase) const {
  ImpactResponse r;
  if (!(delta >= 0)) return r;
  const double x = std::min(delta, bottom_);
  const Power p = power(x, n_);
  const double g = 1.0 + phase.damping / k_ * rate;  // 1 + zeta rate / v_imp
  if (g > 0) {
    r.force = k_ * p.value * g;
    r.stiffness = delta <= bottom_ ? k_ * p.slope * g : 0.0;  // at s: the left limit
    r.damping = phase.damping * p.value;
  }
  if (jump_ && phase.bottomed) {
    // A frozen step may end a hair short of s: the wall's law at 0+ there.
    const ImpactResponse concrete =
        wall_->respond(std::max(delta - bottom_, 0.0), rate, wall_phase(phase));
    r.force += concrete.force;
    r.stiffness += concrete.stiffness;
    r.damping += concrete.damping;
  } else if (!jump_ && delta > bottom_) {
    const ImpactPhase w = wall_phase(phase);
    const ImpactResponse concrete = wall_->respond(delta - bottom_, rate, w);
    const ImpactResponse onset = wall_->respond(0.0, rate, w);
    r.force += concrete.force - onset.force;
    r.stiffness += concrete.stiffness;
    r.damping += concrete.damping - onset.damping;
  }
  if (r.force < 0) r = ImpactResponse{};  // a bumper does not pull
  return r;
}

double BumperLaw::rubber_damping_force(double delta, double rate, const ImpactPhase& phase) const {
  if (!(delta > 0)) return 0.0;
  const double kx = k_ * power(std::min(delta, bottom_), n_).value;
  return std::max(phase.damping / k_ * rate, -1.0) * kx;  // the clamp: F_r >= 0
}

double BumperLaw::stored_energy(double delta, const ImpactPhase& phase) const {
  if (!(delta > 0)) return 0.0;
  const double x = std::min(delta, bottom_);
  double stored = k_ * power(x, n_).value * x / (n_ + 1.0);
  if (delta > bottom_) {
    stored += k_ * power(bottom_, n_).value * (delta - bottom_);
    stored += wall_->stored_energy(delta - bottom_, wall_phase(phase));
  }
  return stored;
}

std::unique_ptr<ImpactLaw> make_bumper_law(const BumperConfig& b, std::unique_ptr<ImpactLaw> wall) {
  const auto reject = [](const std::string& what) {
    throw std::invalid_argument("bumper: " + what);
  };
  if (!(b.thickness > 0)) reject("thickness = " + text(b.thickness) + " must be > 0");
  if (b.law != "linear" && b.law != "hertz")
    reject("law '" + b.law + "' is not one of linear, hertz");
  if (!(b.max_strain > 0 && b.max_strain < 1))
    reject("max_strain = " + text(b.max_strain) + " must be in (0, 1)");
  if (!(b.k > 0) && !(b.modulus > 0 && b.area > 0)) reject("give k > 0, or E > 0 and area > 0");
  if (!(b.min_impact_velocity > 0)) reject("min_impact_velocity must be > 0");
  if (!wall) reject("no wall law behind the bumper");
  return std::make_unique<BumperLaw>(b, std::move(wall));
}

}  // namespace isopound
