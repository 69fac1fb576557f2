// Witness function of a contact over one step: the cubic Hermite interpolant of a signed
// penetration (delta > 0 closed, <= 0 open) from its values and rates at both step ends.
#pragma once

namespace isopound {

// The witness at the two ends of a step of length h (s): values d0, d1 (m), rates r0, r1 (m/s).
// Any contact geometry (a 1D gap, a 3D signed distance) that can say these four numbers gets
// its onsets and separations located the same way.
struct WitnessStep {
  double d0 = 0.0, r0 = 0.0, d1 = 0.0, r1 = 0.0;
  double h = 0.0;
};

// The interpolant p(theta), theta in [0, 1] the fraction of the step, and its rate dp/dt (m/s).
double witness_value(const WitnessStep& w, double theta);
double witness_rate(const WitnessStep& w, double theta);

// Values of the witness within `tolerance` (m) of zero count as zero: a crossing must go past
// it, so that round-off at a step that was cut to end at an event does not flip the status back.
inline constexpr double kWitnessTolerance = 1e-12;

// The first fraction theta in [0, 1) of the step at which the status `closed` stops holding
// along the interpolant, or 1 if it holds throughout. An open status changes where p rises
// through 0 (onset), a closed one where p falls through 0 (separation), including crossings at
// an interior extremum that the end values do not show (a maximum above 0 in an open step, a
// minimum below 0 in a closed one). A step that starts on the wrong side of 0 (e.g. cut at an
// event, not yet switched) reports 0 if it moves further that way, and nothing for the part
// where it returns. Pseudocode: split [0, 1] at the roots of p' (monotone pieces); scan the
// pieces in order with q = p (open) or -p (closed); the first piece whose end has q > tolerance
// after a start with q <= tolerance holds the crossing, found by safeguarded Newton.
double first_status_change(const WitnessStep& w, bool closed, double tolerance = kWitnessTolerance);

}  // namespace isopound
