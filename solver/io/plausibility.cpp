// The table of plausible ranges and its check (interface: plausibility.h; documented in
// docs/plausibility.md, which lists the same rows). Hard ranges are wide: only values that no
// building can have (a 15 m moat gap, a friction coefficient of 8) are errors; the plausible
// ranges cover real base-isolated buildings, so toy models warn but still run.
#include "solver/io/plausibility.h"

#include <array>
#include <cmath>
#include <cstdio>
#include <limits>

#include "solver/core/constants.h"

namespace isopound {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr Dimension kLinearMass{-1, 1, 0};  // kg/m
constexpr Dimension kMoment{2, 1, -2};      // N m
constexpr Dimension kArea{2, 0, 0};         // m^2
constexpr Dimension kAreaMoment{4, 0, 0};   // m^4

// clang-format off
constexpr std::array<PlausibleRange, 72> kRanges{{
  // key, dimension, hard min, hard max, plausible low, high, unit, SI of unit, what it is
  {"gap",          dim::kLength, 0, 5, 0, 1, "cm", 1e-2, "a moat-wall or neighbour gap"},
  {"gap_left",     dim::kLength, 0, 5, 0, 1, "cm", 1e-2, "a moat-wall gap"},
  {"gap_right",    dim::kLength, 0, 5, 0, 1, "cm", 1e-2, "a moat-wall gap"},
  {"gap.east",     dim::kLength, 0, 5, 0, 1, "cm", 1e-2, "a moat-wall gap (3D, per side)"},
  {"gap.west",     dim::kLength, 0, 5, 0, 1, "cm", 1e-2, "a moat-wall gap (3D, per side)"},
  {"gap.north",    dim::kLength, 0, 5, 0, 1, "cm", 1e-2, "a moat-wall gap (3D, per side)"},
  {"gap.south",    dim::kLength, 0, 5, 0, 1, "cm", 1e-2, "a moat-wall gap (3D, per side)"},
  {"R",            dim::kLength, 0, 100, 0.5, 10, "m", 1, "a friction pendulum radius"},
  {"uy",           dim::kLength, 0, 1, 1e-4, 0.1, "mm", 1e-3, "a bearing yield displacement"},
  {"thickness",    dim::kLength, 0, 20, 0.05, 3, "m", 1, "a wall thickness"},
  {"height",       dim::kLength, 0, 200, 0.2, 20, "m", 1, "a storey or wall height"},
  {"extension",    dim::kLength, 0, 100, 0, 20, "m", 1, "a wall extension beyond the slab"},
  {"isolation_height", dim::kLength, 0, 50, 0.1, 5, "m", 1, "an isolated slab's height above its floor"},
  {"mass",         dim::kMass, 0, 1e9, 1e3, 1e8, "t", 1e3, "a floor or base-slab mass"},
  {"roof_mass",    dim::kMass, 0, 1e9, 1e3, 1e8, "t", 1e3, "a roof mass"},
  {"carried_mass", dim::kMass, 0, 1e9, 0, 1e8, "t", 1e3, "the mass one bearing carries"},
  {"mass_per_length", kLinearMass, 0, 1e7, 10, 1e5, "t/m", 1e3, "a wall mass per length"},
  {"stiffness",    dim::kStiffness, 0, 1e14, 1e5, 1e12, "kN/m", 1e3, "a storey or wall stiffness"},
  {"k",            dim::kStiffness, 0, 1e15, 1e5, 1e13, "kN/m", 1e3, "an impact stiffness"},
  {"k_h",          dim::kHertzStiffness, 0, 1e16, 1e6, 1e14, "kN/m^1.5", 1e3, "a Hertz impact stiffness"},
  {"k_tangential", dim::kStiffness, 0, 1e15, 1e4, 1e13, "kN/m", 1e3, "a tangential contact stiffness"},
  {"k_normal",     dim::kPressure, 0, 1e15, 1e5, 1e13, "kN/m^2", 1e3, "a contact stiffness per area"},
  {"E",            dim::kPressure, 0, 1e13, 1e8, 1e12, "GPa", 1e9, "an elastic modulus"},
  {"G",            dim::kPressure, 0, 1e13, 4e7, 5e11, "GPa", 1e9, "a shear modulus"},
  {"nu",           dim::kNone, 0, 0.5, 0.05, 0.45, "", 1, "a Poisson ratio"},
  {"mu_slow",      dim::kNone, 0, 1, 0.005, 0.3, "%", 1e-2, "a friction coefficient"},
  {"mu_fast",      dim::kNone, 0, 1, 0.005, 0.3, "%", 1e-2, "a friction coefficient"},
  {"mu_static",    dim::kNone, 0, 2, 0, 1, "", 1, "a contact friction coefficient"},
  {"mu_kinetic",   dim::kNone, 0, 2, 0, 1, "", 1, "a contact friction coefficient"},
  {"QW",           dim::kNone, 0, 1, 0.005, 0.3, "%", 1e-2, "a bearing strength ratio Q/W"},
  {"yield_drift_ratio", dim::kNone, 0, 0.2, 0.001, 0.03, "%", 1e-2, "a storey or column yield drift ratio"},
  {"capping_drift_ratio", dim::kNone, 0, 0.5, 0.005, 0.1, "%", 1e-2, "a storey capping drift ratio"},
  {"post_yield_ratio", dim::kNone, 0, 1, 0, 0.3, "%", 1e-2, "a post-yield stiffness ratio"},
  {"post_capping_ratio", dim::kNone, 0, 1, 0.005, 0.5, "%", 1e-2, "a post-capping slope ratio"},
  {"residual_strength_ratio", dim::kNone, 0, 1, 0, 0.6, "%", 1e-2, "a residual strength ratio"},
  {"yield_shear",  dim::kForce, 0, 1e11, 1e4, 1e9, "kN", 1e3, "a storey yield shear"},
  {"yield_moment", kMoment, 0, 1e10, 1e4, 1e8, "kN m", 1e3, "a column yield moment"},
  {"yield_shear_coefficient", dim::kNone, 0, 5, 0.02, 1, "%", 1e-2, "a storey yield shear / weight above"},
  {"elastic_limit_drift_ratio", dim::kNone, 0, 0.2, 0.002, 0.05, "%", 1e-2, "the drift ratio beyond which an elastic storey is flagged"},
  {"target_drift_ratio", dim::kNone, 0, 1, 0.002, 0.1, "%", 1e-2, "a pushover's target roof drift ratio"},
  {"ratio",        dim::kNone, 0, 1, 0, 0.3, "%", 1e-2, "a damping ratio"},
  {"ratios",       dim::kNone, 0, 1, 0, 0.3, "%", 1e-2, "a damping ratio"},
  {"isolation",    dim::kNone, 0, 1, 0, 0.5, "%", 1e-2, "an isolation damping ratio"},
  {"Tb",           dim::kTime, 0, 30, 0.5, 8, "s", 1, "an isolation period"},
  {"dt",           dim::kTime, 0, 100, 0, 0.05, "ms", 1e-3, "a time step (analysis: 0 = automatic)"},
  {"interval",     dim::kTime, 0, 60, 0, 1, "ms", 1e-3, "an output interval"},
  {"t_end",        dim::kTime, 0, 1e5, 0.01, 1000, "s", 1, "an analysis end time"},
  {"extra_time",   dim::kTime, 0, 1e4, 0, 300, "s", 1, "free vibration after the record"},
  {"scale",        dim::kNone, -100, 100, -20, 20, "", 1, "a record scale factor"},
  {"pga",          dim::kAcceleration, 0, 10 * kGravity, 0.005 * kGravity, 3 * kGravity, "g", kGravity, "a record's peak ground acceleration"},
  // "section.key" rows apply under that section only, before the key's own row (rubber is not
  // concrete: a 2 cm layer, a 10 MPa modulus).
  {"bumper.thickness", dim::kLength, 0, 2, 0, 0.3, "cm", 1e-2, "a rubber bumper's thickness (0: none)"},
  {"bumper.E",     dim::kPressure, 0, 1e11, 1e5, 1e9, "MPa", 1e6, "a rubber bumper's modulus"},
  {"bumper.k",     dim::kHertzStiffness, 0, 1e16, 1e5, 1e14, "kN/m^1.5", 1e3, "a Hertz-type bumper stiffness"},
  {"bumper.k",     dim::kStiffness, 0, 1e13, 1e4, 1e11, "kN/m", 1e3, "a linear bumper stiffness"},
  {"bumper.area",  kArea, 0, 1e4, 1e-4, 100, "m2", 1, "a bumper's contact area"},
  {"bumper.height", dim::kLength, 0, 20, 0.02, 2, "m", 1, "a 3D bumper's height against the slab edge"},
  {"max_strain",   dim::kNone, 0, 1, 0.2, 0.9, "%", 1e-2, "a bumper's compression limit"},
  // A 2D building's struck column line (columns:, docs/floor-to-column.md).
  {"M_y",          kMoment, 0, 1e10, 1e4, 1e8, "kN m", 1e3, "a column hinge yield moment"},
  {"V_n",          dim::kForce, 0, 1e11, 1e4, 1e9, "kN", 1e3, "a column shear capacity"},
  {"hardening_ratio", dim::kNone, 0, 1, 0.001, 0.3, "%", 1e-2, "a hinge hardening ratio"},
  {"ground_level", dim::kLength, -1000, 1000, -20, 20, "m", 1, "a neighbour's ground above the building's"},
  // Column sections (3D columns, 2D struck columns): b x h and its moments, easily in cm and cm^4.
  {"section",      dim::kLength, 0, 10, 0.1, 3, "cm", 1e-2, "a column's section side"},
  {"I",            kAreaMoment, 0, 100, 1e-5, 10, "m^4", 1, "a column's second moment of area"},
  {"I11",          kAreaMoment, 0, 100, 1e-5, 10, "m^4", 1, "a column's second moment of area"},
  {"I22",          kAreaMoment, 0, 100, 1e-5, 10, "m^4", 1, "a column's second moment of area"},
  {"J",            kAreaMoment, 0, 100, 1e-5, 10, "m^4", 1, "a column's torsion constant"},
  // A 3D building's plan and grid.
  {"bays_x",       dim::kLength, 0, 200, 1, 30, "m", 1, "a bay width of the column grid"},
  {"bays_y",       dim::kLength, 0, 200, 1, 30, "m", 1, "a bay width of the column grid"},
  {"rectangle",    dim::kLength, 0, 2000, 2, 300, "m", 1, "a plan's side"},
  // Contact detection (3D) and the built-in pulse.
  {"elevation_tolerance", dim::kLength, 0, 10, 1e-4, 1, "cm", 1e-2, "the elevation difference within which floors meet"},
  {"search_distance", dim::kLength, 0, 1000, 0.01, 50, "m", 1, "the rest separation within which contacts are sought"},
  {"amplitude",    dim::kVelocity, -1e6, 1e6, -3, 3, "m/s", 1, "a pulse's velocity amplitude"},
}};
// clang-format on

constexpr std::array<UncheckedKey, 31> kUnchecked{{
    {"tolerance", "a solver setting (relative error), bounded by the reader"},
    {"newton_tolerance", "a solver setting (relative residual), bounded by the reader"},
    {"steps_per_period", "a solver setting, bounded by the reader"},
    {"steps_per_contact", "a solver setting, bounded by the reader"},
    {"participation_threshold", "a solver setting (a mass ratio), bounded by the reader"},
    {"n", "Bouc-Wen or Hertz exponent (dimensionless, no other unit to mean)"},
    {"A", "Bouc-Wen shape parameter (dimensionless)"},
    {"beta", "Bouc-Wen shape parameter (dimensionless)"},
    {"gamma", "Bouc-Wen or pulse shape parameter (dimensionless)"},
    {"rate_parameter", "friction rate parameter, s/m: no common other unit"},
    {"deterioration",
     "cyclic deterioration lambda = E_t / (F_y d_y): a pure number, no other unit"},
    {"e", "coefficient of restitution, bounded (0, 1] by the reader"},
    {"damping", "a damping ratio of a wall, bounded [0, 1) by the reader"},
    {"polar_moment", "kg m^2: depends on the plan; computed when absent"},
    {"period", "pulse period: shape of the built-in pulse"},
    {"t_peak", "pulse time of the peak: shape of the built-in pulse"},
    {"duration", "pulse duration: shape of the built-in pulse"},
    {"min_impact_velocity", "a contact-detection setting"},
    {"position", "plan coordinates (m): the site's own geometry, checked by the site checks"},
    {"origin", "plan coordinates of grid line A1 (m): the site's own geometry"},
    {"from",
     "where a 3D bumper starts along its wall's or slab's face (m), checked against the face"},
    {"to", "where a 3D bumper ends along its wall's or slab's face (m), checked against the face"},
    {"polygon", "plan vertices (m): the site's own geometry, checked by the site checks"},
    {"polyline",
     "walls' faces in plan (m): the site's own geometry; each wall's clearance from the slab is "
     "measured and must be positive"},
    {"at", "a bearing's plan position (m): checked against the slab by the site checks"},
    {"eccentricity", "centre-of-mass offset (m): checked against the slab by the site checks"},
    {"restitution", "coefficient of restitution, bounded by the reader"},
    {"angle", "an angle: its unit is required (a bare number is an error)"},
    {"rotation", "an angle: its unit is required (a bare number is an error)"},
    {"orientation", "an angle: its unit is required (a bare number is an error)"},
    {"phase", "an angle: its unit is required (a bare number is an error)"},
}};

// Units a bare number may have been meant in, per dimension, for the hint.
struct Alternative {
  Dimension dimension;
  std::string_view unit;
  double si;
};
constexpr std::array<Alternative, 21> kAlternatives{{
    {dim::kLength, "cm", 1e-2},
    {dim::kLength, "mm", 1e-3},
    {dim::kMass, "t", 1e3},
    {dim::kStiffness, "kN/m", 1e3},
    {dim::kStiffness, "kN/mm", 1e6},
    {dim::kStiffness, "MN/m", 1e6},
    {dim::kPressure, "MPa", 1e6},
    {dim::kPressure, "GPa", 1e9},
    {dim::kTime, "ms", 1e-3},
    {dim::kNone, "%", 1e-2},
    {kLinearMass, "t/m", 1e3},
    {dim::kHertzStiffness, "kN/m^1.5", 1e3},
    {dim::kHertzStiffness, "MN/m^1.5", 1e6},
    {dim::kForce, "kN", 1e3},
    {dim::kForce, "MN", 1e6},
    {kMoment, "kN m", 1e3},
    {kMoment, "MN m", 1e6},
    {kAreaMoment, "cm^4", 1e-8},
    {kAreaMoment, "mm^4", 1e-12},
    {dim::kVelocity, "cm/s", 1e-2},
    {kArea, "cm^2", 1e-4},
}};

std::string number(double x) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%g", x);
  return buffer;
}

// "15 cm" for 0.15 m in the row's unit.
std::string in_unit(double si, const PlausibleRange& r) {
  // Appended, not '+': GCC 12 warns a false -Wrestrict on "x" + std::string at -O3.
  std::string out = number(si / r.unit_si);
  if (!r.unit.empty()) out.append(" ").append(r.unit);
  return out;
}

std::string range_text(double lo, double hi, const PlausibleRange& r) {
  if (hi == kInf) return ">= " + in_unit(lo, r);
  return in_unit(lo, r) + " to " + in_unit(hi, r);
}

}  // namespace

std::span<const PlausibleRange> plausible_ranges() {
  return kRanges;
}

std::string key_of(std::string_view key_path) {
  std::string generic;
  for (std::size_t i = 0; i < key_path.size(); ++i) {
    if (key_path[i] == '[') {
      while (i < key_path.size() && key_path[i] != ']') ++i;
      continue;
    }
    generic += key_path[i];
  }
  const std::size_t dot = generic.find_last_of('.');
  return dot == std::string::npos ? generic : generic.substr(dot + 1);
}

std::span<const UncheckedKey> unchecked_keys() {
  return kUnchecked;
}

bool is_unchecked_key(std::string_view key) {
  for (const UncheckedKey& u : kUnchecked)
    if (u.key == key) return true;
  return false;
}

const PlausibleRange* plausible_range_for(std::string_view key_path, const Dimension& d) {
  const std::string key = key_of(key_path);
  // The section's own row first ("bumper.E" for building.walls.bumper.E).
  const std::string generic = key_path.size() > key.size()
                                  ? key_of(key_path.substr(0, key_path.find_last_of('.')))
                                  : std::string();
  if (!generic.empty())
    for (const PlausibleRange& r : kRanges)
      if (r.key == generic + "." + key && r.dimension == d) return &r;
  // A gap or thickness per face of walls named by face ("gap.north-east", "thickness.east 2"): a
  // gap, a thickness.
  const std::string_view row = generic == "gap" || generic == "thickness"
                                   ? std::string_view(generic)
                                   : std::string_view(key);
  for (const PlausibleRange& r : kRanges)
    if (r.key == row && r.dimension == d) return &r;
  return nullptr;
}

PlausibilityVerdict check_plausible(std::string_view key_path, const Dimension& d, double si,
                                    std::string_view text, bool has_unit) {
  PlausibilityVerdict verdict;
  const PlausibleRange* r = plausible_range_for(key_path, d);
  if (r == nullptr || !std::isfinite(si)) return verdict;
  const bool hard = si < r->hard_min || si > r->hard_max;
  if (!hard && si >= r->low && si <= r->high) return verdict;
  verdict.level = hard ? Plausibility::kError : Plausibility::kWarning;
  std::string written(text);
  while (!written.empty() && written.back() == ' ') written.pop_back();
  while (!written.empty() && written.front() == ' ') written.erase(0, 1);
  std::string message = "'" + written + "'";
  if (!has_unit && r->unit_si != 1.0) message += " (a bare number is SI: " + in_unit(si, *r) + ")";
  message += hard ? " is impossible for " : " is implausible for ";
  message += std::string(r->what) + " (" +
             (hard ? "possible: " + range_text(r->hard_min, r->hard_max, *r)
                   : "plausible: " + range_text(r->low, r->high, *r)) +
             ")";
  if (!has_unit) {
    for (const Alternative& a : kAlternatives) {
      if (!(a.dimension == d)) continue;
      const double meant = si * a.si;
      if (meant >= r->low && meant <= r->high) {
        message += "; did you mean '" + number(si) + " " + std::string(a.unit) + "'?";
        break;
      }
    }
  }
  if (!hard) message += " (--strict makes this an error)";
  verdict.message = std::move(message);
  return verdict;
}

}  // namespace isopound
