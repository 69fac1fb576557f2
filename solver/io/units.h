// Physical quantities with units at the input edge: "20 cm" -> 0.2 (SI), with dimension checks.
// Convention: a bare number is SI; "g" is standard gravity 9.81 m/s^2 (not gram); "%" is 0.01.
#pragma once

#include <stdexcept>
#include <string>
#include <string_view>

namespace isopound {

// Exponents of (length, mass, time); fractional exponents allowed (Hertz stiffness N/m^1.5).
struct Dimension {
  double length = 0.0;
  double mass = 0.0;
  double time = 0.0;
  bool operator==(const Dimension& other) const;
  std::string to_string() const;  // e.g. "m kg s^-2"
};

namespace dim {
inline constexpr Dimension kNone{0, 0, 0};
inline constexpr Dimension kLength{1, 0, 0};
inline constexpr Dimension kMass{0, 1, 0};
inline constexpr Dimension kTime{0, 0, 1};
inline constexpr Dimension kVelocity{1, 0, -1};
inline constexpr Dimension kAcceleration{1, 0, -2};
inline constexpr Dimension kForce{1, 1, -2};
inline constexpr Dimension kStiffness{0, 1, -2};          // N/m
inline constexpr Dimension kHertzStiffness{-0.5, 1, -2};  // N/m^1.5
inline constexpr Dimension kDamping{0, 1, -1};            // N s/m
inline constexpr Dimension kPressure{-1, 1, -2};          // Pa
inline constexpr Dimension kDensity{-3, 1, 0};
inline constexpr Dimension kFrequency{0, 0, -1};
}  // namespace dim

// Thrown for text that is not a quantity or has the wrong dimension. The message names
// the text and the expected dimension but not the file: callers add file:line:key.
class UnitError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct Quantity {
  double si = 0.0;      // value in SI units
  Dimension dimension;  // dimension of the unit written (kNone for a bare number)
  bool has_unit = false;
};

// Parses "<number> [unit]". Units: products/quotients of known symbols with powers,
// e.g. "kN/mm", "m/s^2", "m/s2", "N*s/m", "N/m^1.5", "t/m", "%", "deg".
Quantity parse_quantity(std::string_view text);

// Parses and checks the dimension. A bare number is taken as SI of `expected`.
double parse_quantity_as(std::string_view text, const Dimension& expected);

// An angle in rad from "30 deg", "30 \u00b0" or "0.5 rad". A bare number is refused: "30" could be
// 30 deg or 30 rad (1718.9 deg), and the message names both readings.
double parse_angle(std::string_view text);

// A number as people write it: 1e+308 as "1e+308", 0.003 as "0.003" (%g with 6 digits), never
// the 309 digits of std::to_string.
std::string readable_number(double value);

}  // namespace isopound
