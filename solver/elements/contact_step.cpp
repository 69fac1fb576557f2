// Step limits shared by the contact elements: time of impact, contact period, graded onset.
#include "solver/elements/contact_step.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace isopound {

TimeOfImpact time_of_impact(double distance, double approach_rate, double acceleration_bound) {
  TimeOfImpact r;
  const double v = approach_rate;
  r.arrival_speed =
      std::sqrt(std::max(v * v + 2.0 * acceleration_bound * std::max(distance, 0.0), 0.0));
  if (!(v + r.arrival_speed > 0)) return r;  // receding, nothing pulling them together
  r.time = distance > 0 ? 2.0 * distance / (v + r.arrival_speed) : 0.0;
  return r;
}

double contact_period_estimate(const ImpactLaw& law, const ImpactPhase& phase, double m_eff) {
  const double energy = 0.5 * m_eff * phase.impact_velocity * phase.impact_velocity;
  if (!(energy > 0)) return 1e300;
  double delta = 1e-3;
  for (int it = 0; it < 60; ++it) {
    const ImpactResponse e = law.respond(delta, 0.0, phase);
    if (!(e.force > 0)) return 1e300;
    // The law's own elastic energy (a power law's F delta / (n + 1); exact for a bumper's
    // stages, whose Newton path may pass the bottoming out).
    const double stored = law.stored_energy(delta, phase);
    const double next = delta - (stored - energy) / e.force;
    const double updated = next > 0 ? next : 0.5 * delta;
    if (std::abs(updated - delta) < 1e-10 * delta) {
      delta = updated;
      break;
    }
    delta = updated;
  }
  const double force = law.respond(delta, 0.0, phase).force;
  return force > 0 ? std::numbers::pi * std::sqrt(m_eff * delta / force) : 1e300;
}

double graded_contact_step(double contact_step, int steps_since_onset) {
  return contact_step * std::ldexp(1.0, std::min(steps_since_onset, 5) - 5);
}

}  // namespace isopound
