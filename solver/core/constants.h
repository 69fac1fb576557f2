// Physical constants used across isopound, defined once.
// g = 9.81 m/s^2 (THEORY.md "Units"): the "g" of record files, of units like "0.4 g" and of Q/W.
#pragma once

namespace isopound {

inline constexpr double kGravity = 9.81;  // m/s^2

}  // namespace isopound
