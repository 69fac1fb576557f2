// Step limits every contact geometry shares (the 2D Contact1D, the 3D PolygonContact): the time
// of impact before a contact, the contact period, and the step graded up from an onset.
#pragma once

#include "solver/materials/impact_law.h"

namespace isopound {

// Conservative advancement (time of impact): a gap d > 0 closing at the rate v (> 0 closing)
// with |d''| <= A cannot close before t = 2d / (v + sqrt(v^2 + 2 A d)), the earliest root of
// -d + v t + A t^2 / 2. arrival_speed = sqrt(v^2 + 2 A d) bounds the approach rate on arrival.
struct TimeOfImpact {
  double time = 1e300;         // s; 1e300 if receding with no acceleration towards contact
  double arrival_speed = 0.0;  // m/s
};
TimeOfImpact time_of_impact(double distance, double approach_rate, double acceleration_bound);

// Duration of a contact of the law begun with `phase` (s), from the peak penetration of its
// elastic part (Newton on F_e delta / (n + 1) = m_eff v_imp^2 / 2, v_imp the phase's impact
// velocity) and the secant stiffness there: pi sqrt(m_eff delta_max / F_e(delta_max)). 1e300 if
// the law stores no energy.
double contact_period_estimate(const ImpactLaw& law, const ImpactPhase& phase, double m_eff);

// The step in the first steps of a contact: contact_step / 32, doubling each accepted step up to
// contact_step from the sixth on (the force of the Hertz-type laws grows as delta^(n-1), the
// Jankowski damping as delta^(1/4), with an infinite slope at the onset).
double graded_contact_step(double contact_step, int steps_since_onset);

}  // namespace isopound
