// Tests of parse_quantity / parse_quantity_as: SI values of the unit forms used in model files,
// dimension checks, and rejection of unknown units, garbage and non-finite numbers.
#include "solver/io/units.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

namespace isopound {
namespace {

// Relative comparison: the values span 1e-3 .. 1e9.
void expect_si(const char* text, const Dimension& d, double expected) {
  SCOPED_TRACE(text);
  const double value = parse_quantity_as(text, d);
  EXPECT_NEAR(value, expected, 1e-12 * std::abs(expected)) << text;
}

std::string error_of(const char* text, const Dimension& d) {
  try {
    parse_quantity_as(text, d);
  } catch (const UnitError& e) {
    return e.what();
  }
  ADD_FAILURE() << "no UnitError for '" << text << "'";
  return {};
}

TEST(UnitsParse, ValuesFromTheModelFiles) {
  expect_si("2500 kN/mm", dim::kStiffness, 2.5e9);
  expect_si("20 cm", dim::kLength, 0.2);
  expect_si("340 t", dim::kMass, 3.4e5);
  expect_si("5 %", dim::kNone, 0.05);
  expect_si("0.4 g", dim::kAcceleration, 0.4 * 9.81);
  expect_si("600 MN/m", dim::kStiffness, 6e8);
  expect_si("1e-3 m", dim::kLength, 1e-3);
  expect_si("1 cm", dim::kLength, 0.01);
  expect_si("3.2 m", dim::kLength, 3.2);
  expect_si("2 s", dim::kTime, 2.0);
  expect_si("5 ms", dim::kTime, 5e-3);
  expect_si("2 min", dim::kTime, 120.0);
  expect_si("1.5 km", dim::kLength, 1500.0);
  expect_si("12 mm", dim::kLength, 0.012);
  expect_si("7 kg", dim::kMass, 7.0);
  expect_si("3 GN", dim::kForce, 3e9);
}

TEST(UnitsParse, NumberFormsAndSpaces) {
  expect_si("  42  ", dim::kLength, 42.0);
  expect_si(" 20 cm ", dim::kLength, 0.2);
  expect_si("20cm", dim::kLength, 0.2);
  expect_si("+1.5", dim::kNone, 1.5);
  expect_si("-2.5 m", dim::kLength, -2.5);
  expect_si(".5 m", dim::kLength, 0.5);
  expect_si("5. m", dim::kLength, 5.0);
  expect_si("1E3 N", dim::kForce, 1e3);
  expect_si("2.5e+2 kN", dim::kForce, 2.5e5);
  expect_si("0", dim::kMass, 0.0);
}

TEST(UnitsParse, ProductsQuotientsAndPowers) {
  expect_si("9.81 m/s^2", dim::kAcceleration, 9.81);
  expect_si("9.81 m/s2", dim::kAcceleration, 9.81);
  expect_si("9.81 m/s\xC2\xB2", dim::kAcceleration, 9.81);  // m/s²
  expect_si("981 cm/s2", dim::kAcceleration, 9.81);
  expect_si("100 N*s/m", dim::kDamping, 100.0);
  expect_si("100 kN\xC2\xB7s/m", dim::kDamping, 1e5);  // kN·s/m
  expect_si("100 kN s/m", dim::kDamping, 1e5);
  expect_si("2 N/m^1.5", dim::kHertzStiffness, 2.0);
  expect_si("2 kN/mm^1.5", dim::kHertzStiffness, 2e3 / std::pow(1e-3, 1.5));
  expect_si("2 kN/mm^(1.5)", dim::kHertzStiffness, 2e3 / std::pow(1e-3, 1.5));
  expect_si("3 t/m", Dimension{-1, 1, 0}, 3e3);
  expect_si("2400 kg/m^3", dim::kDensity, 2400.0);
  expect_si("2400 kg/m3", dim::kDensity, 2400.0);
  expect_si("2400 kg m^-3", dim::kDensity, 2400.0);
  expect_si("2400 kg\xC2\xB7m\xE2\x81\xBB\xC2\xB3", dim::kDensity, 2400.0);  // kg·m⁻³
  expect_si("30 GPa", dim::kPressure, 3e10);
  expect_si("250 MPa", dim::kPressure, 2.5e8);
  expect_si("3 kPa", dim::kPressure, 3e3);
  expect_si("1 Pa", dim::kPressure, 1.0);
  expect_si("1 N/m^2", dim::kPressure, 1.0);
  expect_si("2 Hz", dim::kFrequency, 2.0);
  expect_si("2 s^-1", dim::kFrequency, 2.0);
  expect_si("4 m/s/s", dim::kAcceleration, 4.0);
  expect_si("1 kN*m/m", dim::kForce, 1e3);
}

TEST(UnitsParse, DimensionlessUnits) {
  expect_si("5 %", dim::kNone, 0.05);
  expect_si("5%", dim::kNone, 0.05);
  expect_si("0.05", dim::kNone, 0.05);
  expect_si("180 deg", dim::kNone, std::numbers::pi);
  expect_si("90 \xC2\xB0", dim::kNone, std::numbers::pi / 2);  // 90 °
  expect_si("1.5 rad", dim::kNone, 1.5);
  expect_si("2 s/s", dim::kNone, 2.0);
}

TEST(UnitsParse, QuantityCarriesDimension) {
  const Quantity q = parse_quantity("2500 kN/mm");
  EXPECT_TRUE(q.has_unit);
  EXPECT_EQ(q.dimension, dim::kStiffness);
  EXPECT_DOUBLE_EQ(q.si, 2.5e9);

  const Quantity bare = parse_quantity("12.5");
  EXPECT_FALSE(bare.has_unit);
  EXPECT_EQ(bare.dimension, dim::kNone);
  EXPECT_DOUBLE_EQ(bare.si, 12.5);

  const Quantity g = parse_quantity("1 g");  // gravity, not gram
  EXPECT_EQ(g.dimension, dim::kAcceleration);
  EXPECT_DOUBLE_EQ(g.si, 9.81);
}

TEST(UnitsDimension, ComparesWithToleranceAndPrints) {
  EXPECT_EQ(dim::kHertzStiffness, (Dimension{-0.5 + 1e-12, 1, -2}));
  EXPECT_FALSE(dim::kHertzStiffness == (Dimension{-0.5 + 1e-6, 1, -2}));
  EXPECT_FALSE(dim::kForce == dim::kStiffness);
  EXPECT_EQ(dim::kForce.to_string(), "m kg s^-2");
  EXPECT_EQ(dim::kHertzStiffness.to_string(), "m^-0.5 kg s^-2");
  EXPECT_EQ(dim::kNone.to_string(), "1");
  EXPECT_EQ(parse_quantity("1 m/s^1.5").dimension.to_string(), "m s^-1.5");
}

TEST(UnitsErrors, WrongDimension) {
  const std::string e = error_of("20 kg", dim::kLength);
  EXPECT_NE(e.find("unit 'kg' is a mass (kg), expected a length (m)"), std::string::npos) << e;
  EXPECT_NE(error_of("600 MN", dim::kStiffness).find("is a force (N), expected a stiffness (N/m)"),
            std::string::npos);
  EXPECT_NE(error_of("5 %", dim::kLength).find("is dimensionless, expected a length (m)"),
            std::string::npos);
  EXPECT_NE(error_of("2 m", dim::kNone).find("expected dimensionless"), std::string::npos);
  EXPECT_NE(error_of("1 kN/mm", dim::kHertzStiffness).find("expected a Hertz stiffness (N/m^1.5)"),
            std::string::npos);
  EXPECT_NE(error_of("1 N*s/m", dim::kStiffness).find("is a damping coefficient (N s/m)"),
            std::string::npos);
  EXPECT_NE(
      error_of("1 m^2", dim::kLength).find("'m^2' is of dimension m^2, expected a length (m)"),
      std::string::npos);
  EXPECT_NE(error_of("1 Hz", dim::kTime).find("a frequency (Hz), expected a time (s)"),
            std::string::npos);
  EXPECT_NE(error_of("0.4 g", dim::kMass).find("an acceleration (m/s^2), expected a mass (kg)"),
            std::string::npos);
}

TEST(UnitsErrors, UnknownUnitIsNamed) {
  const std::string e = error_of("20 furlong", dim::kLength);
  EXPECT_NE(e.find("unknown unit 'furlong'"), std::string::npos) << e;
  EXPECT_NE(error_of("3 kN/inch", dim::kStiffness).find("unknown unit 'inch' in 'kN/inch'"),
            std::string::npos);
  EXPECT_NE(error_of("3 gram", dim::kMass).find("unknown unit 'gram'"), std::string::npos);
  EXPECT_THROW(parse_quantity("3 KN"), UnitError);  // symbols are case-sensitive
}

TEST(UnitsErrors, GarbageAndMalformedUnits) {
  for (const char* text : {"",        "   ",       "abc",   "m",      "kN 20", "--1",  "+-1",
                           "1.2.3 m", "20 cm cm/", "1 /s",  "1 m//s", "1 m*",  "1 m^", "1 m^x",
                           "1 m^(2",  "1 m2s",     "1 kN(", "1 m 2",  "1 m#",  "1 ^2"}) {
    SCOPED_TRACE(text);
    EXPECT_THROW(parse_quantity(text), UnitError) << "'" << text << "'";
  }
  EXPECT_NE(error_of("abc", dim::kMass).find("'abc' is not a quantity"), std::string::npos);
}

TEST(UnitsErrors, NonFiniteNumbersAreRejected) {
  for (const char* text : {"nan", "NaN m", "inf", "-inf", "infinity s", "1e400", "1e308 GPa",
                           "1 m^1e300", "1 km^300"}) {
    SCOPED_TRACE(text);
    EXPECT_THROW(parse_quantity(text), UnitError) << "'" << text << "'";
  }
}

}  // namespace
}  // namespace isopound
