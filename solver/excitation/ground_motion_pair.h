// Two horizontal components at an incidence angle (THEORY eq. 5.12-5.13): theta is measured
// counter-clockwise from the model's X axis to the L component; a_x = a_L cos theta - a_T sin
// theta, a_y = a_L sin theta + a_T cos theta.
#pragma once

#include "solver/excitation/ground_motion.h"

namespace isopound {

// The pair as one GroundMotion with acceleration (x) and acceleration_y. Components of different
// sampling are both resampled at the smaller dt by linear interpolation (the records' own
// convention, linear between samples, so nothing is lost when one dt is a multiple of the other);
// a shorter component is zero after its end (the motion lasts as long as the longer one).
GroundMotion combine_pair(const GroundMotion& longitudinal, const GroundMotion& transverse,
                          double angle);

}  // namespace isopound
