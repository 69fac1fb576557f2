// Parsing of "<number> [unit]" into SI with a dimension check (interface and conventions: units.h).
// Factors multiply left to right; '/' divides by the one factor after it ("N*s/m" = N s m^-1).
#include "solver/io/units.h"

#include "solver/core/constants.h"

#include <array>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <numbers>

namespace isopound {
namespace {

constexpr double kTolerance = 1e-9;
constexpr double kMaxExponent = 100.0;  // keeps dimensions and scales finite

Dimension operator+(const Dimension& a, const Dimension& b) {
  return {a.length + b.length, a.mass + b.mass, a.time + b.time};
}
Dimension operator*(const Dimension& a, double k) {
  return {a.length * k, a.mass * k, a.time * k};
}

struct Symbol {
  std::string_view name;
  double scale;  // SI value of one unit
  Dimension dimension;
};

// The known symbols. "g" is standard gravity, not gram: masses are written in kg or t.
constexpr std::array<Symbol, 23> kSymbols{{
    {"m", 1.0, dim::kLength},
    {"cm", 1e-2, dim::kLength},
    {"mm", 1e-3, dim::kLength},
    {"km", 1e3, dim::kLength},
    {"kg", 1.0, dim::kMass},
    {"t", 1e3, dim::kMass},
    {"s", 1.0, dim::kTime},
    {"ms", 1e-3, dim::kTime},
    {"min", 60.0, dim::kTime},
    {"N", 1.0, dim::kForce},
    {"kN", 1e3, dim::kForce},
    {"MN", 1e6, dim::kForce},
    {"GN", 1e9, dim::kForce},
    {"Pa", 1.0, dim::kPressure},
    {"kPa", 1e3, dim::kPressure},
    {"MPa", 1e6, dim::kPressure},
    {"GPa", 1e9, dim::kPressure},
    {"Hz", 1.0, dim::kFrequency},
    {"g", kGravity, dim::kAcceleration},
    {"%", 1e-2, dim::kNone},
    {"deg", std::numbers::pi / 180.0, dim::kNone},
    {"\xC2\xB0", std::numbers::pi / 180.0, dim::kNone},  // the degree sign
    {"rad", 1.0, dim::kNone},
}};
constexpr const char* kKnownSymbols =
    "m cm mm km, kg t, s ms min, N kN MN GN, Pa kPa MPa GPa, Hz, g (gravity), %, deg, rad";

struct NamedDimension {
  Dimension dimension;
  std::string_view description;
};

constexpr std::array<NamedDimension, 13> kNamedDimensions{{
    {dim::kNone, "dimensionless"},
    {dim::kLength, "a length (m)"},
    {dim::kMass, "a mass (kg)"},
    {dim::kTime, "a time (s)"},
    {dim::kVelocity, "a velocity (m/s)"},
    {dim::kAcceleration, "an acceleration (m/s^2)"},
    {dim::kForce, "a force (N)"},
    {dim::kStiffness, "a stiffness (N/m)"},
    {dim::kHertzStiffness, "a Hertz stiffness (N/m^1.5)"},
    {dim::kDamping, "a damping coefficient (N s/m)"},
    {dim::kPressure, "a pressure (Pa)"},
    {dim::kDensity, "a density (kg/m^3)"},
    {dim::kFrequency, "a frequency (Hz)"},
}};

// "a length (m)" for the common dimensions, else "of dimension m^2 kg".
std::string describe(const Dimension& d) {
  for (const auto& named : kNamedDimensions)
    if (named.dimension == d) return std::string(named.description);
  return "of dimension " + d.to_string();
}

bool is_space(char c) {
  return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f' || c == '\v';
}
bool is_ascii_letter(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z');
}
bool is_digit(char c) {
  return c >= '0' && c <= '9';
}

// "'text'". Built by appending: "'" + std::string(...) trips GCC 12's false -Wrestrict at -O3.
std::string quoted(std::string_view s) {
  std::string out(1, '\'');
  out.append(s);
  out.push_back('\'');
  return out;
}

std::string_view trim(std::string_view s) {
  while (!s.empty() && is_space(s.front())) s.remove_prefix(1);
  while (!s.empty() && is_space(s.back())) s.remove_suffix(1);
  return s;
}

// Length of a multiplication or division operator at the start of s, 0 if none:
// '*', '/', and the middle dots '·' (C2 B7) and '⋅' (E2 8B 85).
std::size_t operator_length(std::string_view s) {
  if (s.starts_with("*") || s.starts_with("/")) return 1;
  if (s.starts_with("\xC2\xB7")) return 2;
  if (s.starts_with("\xE2\x8B\x85")) return 3;
  return 0;
}

// A superscript digit at the start of s ("²" is C2 B2, "⁴" is E2 81 B4), -1 if none.
int superscript_digit(std::string_view s, std::size_t& length) {
  if (s.size() >= 2 && s[0] == '\xC2') {
    length = 2;
    if (s[1] == '\xB9') return 1;
    if (s[1] == '\xB2') return 2;
    if (s[1] == '\xB3') return 3;
  }
  if (s.size() >= 3 && s[0] == '\xE2' && s[1] == '\x81') {
    length = 3;
    const auto c = static_cast<unsigned char>(s[2]);
    if (c == 0xB0) return 0;
    if (c >= 0xB4 && c <= 0xB9) return c - 0xB0;
  }
  return -1;
}
constexpr std::string_view kSuperscriptMinus = "\xE2\x81\xBB";

// Parses a decimal number at the start of s ("1e-3", ".5", "+2"; from_chars itself rejects '+').
// Returns the number of characters used, 0 when there is no number. Overflow gives HUGE_VAL.
std::size_t parse_number(std::string_view s, double& value) {
  std::size_t skip = 0;
  if (s.starts_with("+")) {
    skip = 1;
    if (s.size() > 1 && (s[1] == '+' || s[1] == '-')) return 0;
  }
  const auto [ptr, ec] =
      std::from_chars(s.data() + skip, s.data() + s.size(), value, std::chars_format::general);
  if (ec == std::errc::result_out_of_range) {
    value = HUGE_VAL;
  } else if (ec != std::errc()) {
    return 0;
  }
  return static_cast<std::size_t>(ptr - s.data());
}

// "  20 cm " -> number 20 and unit text "cm" (empty for a bare number).
struct SplitQuantity {
  double number = 0.0;
  std::string_view unit;
};
SplitQuantity split_quantity(std::string_view text) {
  const std::string_view trimmed = trim(text);
  if (trimmed.empty()) throw UnitError("empty text where a quantity was expected");
  SplitQuantity out;
  const std::size_t used = parse_number(trimmed, out.number);
  if (used == 0)
    throw UnitError(quoted(trimmed) +
                    " is not a quantity: expected a number, optionally with a unit (e.g. '20 cm')");
  if (!std::isfinite(out.number)) throw UnitError(quoted(trimmed) + " is not a finite number");
  out.unit = trim(trimmed.substr(used));
  return out;
}

[[noreturn]] void fail_unit(std::string_view unit, const std::string& why) {
  throw UnitError("unit " + quoted(unit) + ": " + why);
}

// Exponent after a symbol: "^2", "^-1", "^1.5", "^(1.5)", digits appended ("s2"), superscripts
// ("s²", "s⁻¹"); 1 when there is none. Advances `rest` past it.
double parse_exponent(std::string_view unit, std::string_view& rest) {
  if (rest.starts_with("^")) {
    rest.remove_prefix(1);
    const bool parenthesised = rest.starts_with("(");
    if (parenthesised) rest.remove_prefix(1);
    double e = 0.0;
    const std::size_t used = parse_number(rest, e);
    if (used == 0 || !std::isfinite(e)) fail_unit(unit, "'^' must be followed by a number");
    rest.remove_prefix(used);
    if (parenthesised) {
      if (!rest.starts_with(")")) fail_unit(unit, "missing ')' after the exponent");
      rest.remove_prefix(1);
    }
    return e;
  }
  if (!rest.empty() && is_digit(rest[0])) {
    std::size_t n = 0;
    while (n < rest.size() && (is_digit(rest[n]) || rest[n] == '.')) ++n;
    double e = 0.0;
    const auto [ptr, ec] =
        std::from_chars(rest.data(), rest.data() + n, e, std::chars_format::fixed);
    if (ec != std::errc() || ptr != rest.data() + n)
      fail_unit(unit, "bad exponent '" + std::string(rest.substr(0, n)) + "'");
    rest.remove_prefix(n);
    return e;
  }
  std::string_view probe = rest;
  const bool negative = probe.starts_with(kSuperscriptMinus);
  if (negative) probe.remove_prefix(kSuperscriptMinus.size());
  std::size_t length = 0;
  int digit = superscript_digit(probe, length);
  if (digit < 0) {
    if (negative) fail_unit(unit, "superscript minus without a digit");
    return 1.0;
  }
  double e = 0.0;
  while (digit >= 0) {
    e = 10.0 * e + digit;
    probe.remove_prefix(length);
    digit = superscript_digit(probe, length);
  }
  rest = probe;
  return negative ? -e : e;
}

struct UnitValue {
  double scale = 1.0;  // SI value of one unit
  Dimension dimension;
};

UnitValue parse_unit(std::string_view unit) {
  UnitValue result;
  std::string_view rest = unit;
  bool divide = false;        // the next factor is a divisor
  bool expect_factor = true;  // at the start or after an operator
  while (true) {
    while (!rest.empty() && is_space(rest.front())) rest.remove_prefix(1);
    if (rest.empty()) break;
    if (const std::size_t op = operator_length(rest); op > 0) {
      if (expect_factor) fail_unit(unit, "an operator needs a unit on each side");
      divide = rest[0] == '/';
      expect_factor = true;
      rest.remove_prefix(op);
      continue;
    }
    // A symbol: a run of ASCII letters, '%', or the degree sign.
    std::size_t n = 0;
    if (rest.starts_with("%")) {
      n = 1;
    } else if (rest.starts_with("\xC2\xB0")) {
      n = 2;
    } else {
      while (n < rest.size() && is_ascii_letter(rest[n])) ++n;
    }
    if (n == 0) fail_unit(unit, "unexpected character " + quoted(rest.substr(0, 1)));
    const std::string_view name = rest.substr(0, n);
    const Symbol* symbol = nullptr;
    for (const auto& s : kSymbols)
      if (s.name == name) symbol = &s;
    if (symbol == nullptr) {
      const std::string where = name == unit ? "" : " in " + quoted(unit);
      throw UnitError("unknown unit " + quoted(name) + where + " (known: " + kKnownSymbols +
                      "; combine with * / ^)");
    }
    rest.remove_prefix(n);
    const double exponent = parse_exponent(unit, rest) * (divide ? -1.0 : 1.0);
    if (std::abs(exponent) > kMaxExponent) fail_unit(unit, "exponent out of range");
    result.scale *= std::pow(symbol->scale, exponent);
    result.dimension = result.dimension + symbol->dimension * exponent;
    divide = false;
    expect_factor = false;
    // "m2s" or "kg(": a factor must be followed by a space, an operator, or the end.
    if (!rest.empty() && !is_space(rest.front()) && operator_length(rest) == 0)
      fail_unit(unit, "unexpected " + quoted(rest) + " after " +
                          quoted(unit.substr(0, unit.size() - rest.size())));
  }
  if (expect_factor) fail_unit(unit, "ends with an operator");
  return result;
}

}  // namespace

bool Dimension::operator==(const Dimension& other) const {
  return std::abs(length - other.length) < kTolerance && std::abs(mass - other.mass) < kTolerance &&
         std::abs(time - other.time) < kTolerance;
}

std::string Dimension::to_string() const {
  std::string out;
  const auto add = [&out](const char* symbol, double e) {
    if (std::abs(e) < kTolerance) return;
    if (!out.empty()) out += ' ';
    out += symbol;
    if (std::abs(e - 1.0) >= kTolerance) {
      char buffer[32];
      std::snprintf(buffer, sizeof buffer, "^%.6g", e);
      out += buffer;
    }
  };
  add("m", length);
  add("kg", mass);
  add("s", time);
  return out.empty() ? "1" : out;
}

Quantity parse_quantity(std::string_view text) {
  const SplitQuantity split = split_quantity(text);
  Quantity q;
  q.si = split.number;
  if (split.unit.empty()) return q;
  const UnitValue unit = parse_unit(split.unit);
  q.si = split.number * unit.scale;
  q.dimension = unit.dimension;
  q.has_unit = true;
  if (!std::isfinite(q.si)) throw UnitError(quoted(trim(text)) + " is out of range in SI units");
  return q;
}

double parse_quantity_as(std::string_view text, const Dimension& expected) {
  const Quantity q = parse_quantity(text);
  if (q.has_unit && !(q.dimension == expected))
    throw UnitError("unit " + quoted(split_quantity(text).unit) + " is " + describe(q.dimension) +
                    ", expected " + describe(expected));
  return q.si;
}

double parse_angle(std::string_view text) {
  const Quantity q = parse_quantity(text);
  const std::string_view unit = split_quantity(text).unit;
  if (!q.has_unit) {
    const std::string number = readable_number(q.si);
    throw UnitError(quoted(trim(text)) + " is an angle without a unit: '" + number + " deg' is " +
                    readable_number(q.si * std::numbers::pi / 180.0) + " rad, '" + number +
                    " rad' is " + readable_number(q.si * 180.0 / std::numbers::pi) +
                    " deg; did you mean '" + number + " deg'? Write the unit");
  }
  if (unit != "deg" && unit != "rad" && unit != "\xC2\xB0")
    throw UnitError("unit " + quoted(unit) +
                    " is not an angle unit: write deg or rad (e.g. '30 deg')");
  return q.si;
}

std::string readable_number(double value) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%g", value);
  return buffer;
}

}  // namespace isopound
