// Study database -> polar figure data (see polar_study.h).
#include "post/polar_study.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numbers>
#include <set>
#include <sstream>

#include "post/study_words.h"
#include "solver/study/study_table.h"

namespace isopound::post {
namespace {

std::string join(const std::vector<std::string>& v) {
  std::string s;
  for (const std::string& x : v) {
    if (!s.empty()) s += ", ";
    s += x;
  }
  return s.empty() ? "(none)" : s;
}

std::string cell_text(const StudyTableCell& c) {
  if (!c.numeric) return c.text;
  std::ostringstream o;
  o << c.number;
  return c.text.empty() ? o.str() : c.text;
}

bool is_angle_name(std::string n) {
  std::transform(n.begin(), n.end(), n.begin(), ::tolower);
  return n == "angle" || n == "incidence" || n == "theta" ||
         (n.size() >= 5 && n.compare(n.size() - 5, 5, "angle") == 0);
}

// The study file's selector of an output column ("" when unknown).
std::string selector_of(const StudyTable& table, const std::string& column) {
  const auto it = std::find(table.outputs.begin(), table.outputs.end(), column);
  const std::size_t i = static_cast<std::size_t>(it - table.outputs.begin());
  return i < table.output_selectors.size() ? table.output_selectors[i] : "";
}

// The display unit of an output column from its selector's quantity; SI when it is unknown.
DisplayUnit unit_from_study(const StudyTable& table, const std::string& column) {
  const auto it = std::find(table.outputs.begin(), table.outputs.end(), column);
  if (it == table.outputs.end()) return {"SI", 1.0};
  return display_unit_of(table.output_quantities[it - table.outputs.begin()]);
}

// The study's table; a missing file or one that is not a study database is the user's mistake
// (PolarStudyError), a database that opens but cannot be read is not.
StudyTable read_table(const std::string& db_path) {
  try {
    return read_study_table(db_path);
  } catch (const StudyTableError& e) {
    if (e.reason() == StudyTableError::Reason::unreadable) throw;
    throw PolarStudyError(e.what());
  }
}

}  // namespace

DisplayUnit display_unit_of(const std::string& quantity) {
  const auto is = [&](std::initializer_list<const char*> names) {
    for (const char* n : names)
      if (quantity == n) return true;
    return false;
  };
  if (is({"displacement", "displacement_x", "displacement_y", "residual_displacement", "drift",
          "drift_x", "drift_y", "deformation", "deformation_x", "deformation_y", "penetration",
          "indentation", "pgd", "u", "v"}))
    return {"cm", 0.01};
  if (is({"velocity", "impact_velocity", "pgv"})) return {"m/s", 1.0};
  if (is({"absolute_acceleration", "absolute_acceleration_x", "absolute_acceleration_y", "pga"}))
    return {"g", 9.81};
  if (is({"force", "force_x", "force_y", "normal_force", "tangential_force"})) return {"kN", 1e3};
  if (is({"drift_ratio"})) return {"%", 0.01};
  if (is({"theta"})) return {"rad", 1.0};
  if (is({"area"})) return {"m2", 1.0};
  if (is({"first_impact_time", "time_in_stick", "time_in_slip"})) return {"s", 1.0};
  if (is({"impacts", "z", "relative_error", "max_relative_error"})) return {"-", 1.0};
  if (is({"dissipated_energy", "friction_dissipated_energy", "impact_dissipated_energy", "input",
          "kinetic", "elastic", "viscous", "hysteretic", "error"}))
    return {"kJ", 1e3};
  return {"SI", 1.0};
}

DisplayUnit axis_display_unit(const std::string& axis) {
  std::string n = axis;
  std::transform(n.begin(), n.end(), n.begin(), [](unsigned char c) { return std::tolower(c); });
  if (n.find("gap") != std::string::npos || n.find("thickness") != std::string::npos || n == "uy" ||
      n == "u_y")
    return {"cm", 0.01};
  if (n == "angle" || n == "incidence" || n == "theta" ||
      (n.size() >= 5 && n.compare(n.size() - 5, 5, "angle") == 0))
    return {"deg", std::numbers::pi / 180.0};
  if (n == "qw" || n.rfind("xi", 0) == 0) return {"%", 0.01};
  if (n == "tb" || n == "period" || n == "duration") return {"s", 1.0};
  return {"SI", 1.0};
}

EnsembleColumns ensemble_columns(const std::vector<std::string>& outputs,
                                 const std::string& quantity) {
  const auto find = [&](const std::string& stat) {
    for (const char* infix : {"_ens_", "_", ".", "_ensemble_"}) {
      const auto it = std::find(outputs.begin(), outputs.end(), quantity + infix + stat);
      if (it != outputs.end()) return static_cast<int>(it - outputs.begin());
    }
    return -1;
  };
  return {find("min"), find("mean"), find("max"), find("std")};
}

double unit_divisor(const std::string& unit) {
  static const std::map<std::string, double> kUnits{
      {"m", 1.0},  {"cm", 0.01}, {"mm", 1e-3}, {"m/s", 1.0}, {"g", 9.81}, {"m/s2", 1.0},
      {"N", 1.0},  {"kN", 1e3},  {"MN", 1e6},  {"%", 0.01},  {"-", 1.0},  {"J", 1.0},
      {"kJ", 1e3}, {"MJ", 1e6},  {"rad", 1.0}, {"m2", 1.0},  {"s", 1.0},  {"SI", 1.0}};
  const auto it = kUnits.find(unit);
  if (it == kUnits.end()) {
    std::string names;
    std::vector<std::string> all;
    for (const auto& entry : kUnits) all.push_back(entry.first);
    names = join(all);
    throw PolarStudyError("--unit '" + unit + "': not one of " + names);
  }
  return it->second;
}

PolarStudyResult read_polar_study(const std::string& db_path, const PolarStudyOptions& opt) {
  const StudyTable table = read_table(db_path);
  PolarStudyResult result;

  // The angle axis.
  int angle = -1;
  for (std::size_t i = 0; i < table.axes.size(); ++i)
    if (opt.angle_axis.empty() ? is_angle_name(table.axes[i]) : table.axes[i] == opt.angle_axis)
      angle = static_cast<int>(i);
  if (angle < 0)
    throw PolarStudyError(db_path + ": the study has no " +
                          (opt.angle_axis.empty()
                               ? std::string("incidence-angle axis (an axis named angle, "
                                             "incidence or *angle)")
                               : "axis '" + opt.angle_axis + "'") +
                          "; its axes are: " + join(table.axes));
  // Ensemble statistics beside the quantity (a study run with `ensemble: N`). A table holding
  // only the statistics draws the ensemble mean as the quantity.
  const EnsembleColumns ens = ensemble_columns(table.outputs, opt.quantity);
  const auto q = std::find(table.outputs.begin(), table.outputs.end(), opt.quantity);
  if (q == table.outputs.end() && ens.mean < 0)
    throw PolarStudyError(db_path + ": quantity '" + opt.quantity +
                          "' is not in the table; its quantities are: " + join(table.outputs));
  const std::size_t qi = q != table.outputs.end()
                             ? static_cast<std::size_t>(q - table.outputs.begin())
                             : static_cast<std::size_t>(ens.mean);
  if (q == table.outputs.end())
    result.notes.push_back("'" + opt.quantity +
                           "' itself is not in the table: its ensemble mean '" + table.outputs[qi] +
                           "' is drawn");
  const auto axis_index = [&](const std::string& name, const char* what) {
    const auto it = std::find(table.axes.begin(), table.axes.end(), name);
    if (it == table.axes.end())
      throw PolarStudyError(db_path + ": " + what + " axis '" + name +
                            "' is not in the study; its axes are: " + join(table.axes));
    return static_cast<int>(it - table.axes.begin());
  };
  int per = -1;
  if (opt.per != "case") {
    const bool has = std::find(table.axes.begin(), table.axes.end(), opt.per) != table.axes.end();
    if (has)
      per = axis_index(opt.per, "--per");
    else if (opt.per != "record")
      axis_index(opt.per, "--per");  // throws
  }
  const int radial = opt.contour_axis.empty() ? -1 : axis_index(opt.contour_axis, "--contour");
  std::vector<std::pair<int, std::string>> filters;
  for (const auto& [axis, label] : opt.where)
    filters.push_back({axis_index(axis, "--where"), label});

  const DisplayUnit unit = opt.unit.empty() ? unit_from_study(table, opt.quantity)
                                            : DisplayUnit{opt.unit, unit_divisor(opt.unit)};
  // Rows that pass the filters, finished.
  bool degrees = false;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  struct Row {
    double angle_deg, radius;
    std::string group;
    double value;
    double lo, mean, hi;  // ensemble min, mean, max (NaN without them)
  };
  const auto stat = [&](const StudyTableRow& r, int column) {
    return column >= 0 && static_cast<std::size_t>(column) < r.values.size()
               ? r.values[column] / unit.divisor
               : nan;
  };
  std::vector<Row> rows;
  for (const StudyTableRow& r : table.rows) {
    if (r.status != "done" || r.values.size() <= qi || !std::isfinite(r.values[qi])) continue;
    bool keep = true;
    for (const auto& [axis, label] : filters)
      if (cell_text(r.axes[axis]) != label) keep = false;
    if (!keep) continue;
    if (!r.axes[angle].numeric) throw PolarStudyError(db_path + ": angle axis holds labels");
    Row row{r.axes[angle].number,
            0.0,
            "",
            r.values[qi] / unit.divisor,
            stat(r, ens.min),
            stat(r, ens.mean),
            stat(r, ens.max)};
    if (std::abs(row.angle_deg) > 2 * std::numbers::pi + 1e-9) degrees = true;
    if (radial >= 0) row.radius = r.axes[radial].numeric ? r.axes[radial].number : 0.0;
    // Group: the --per axis, or every other axis (case) except angle and radial.
    for (std::size_t a = 0; a < r.axes.size(); ++a) {
      if (static_cast<int>(a) == angle || static_cast<int>(a) == radial) continue;
      if (per >= 0 && static_cast<int>(a) != per) continue;
      if (!row.group.empty()) row.group += ' ';
      row.group += cell_text(r.axes[a]);
    }
    rows.push_back(row);
  }
  if (rows.empty())
    throw PolarStudyError(db_path + ": no finished runs with '" + opt.quantity +
                          "' (after --where)");
  for (Row& r : rows)
    if (!degrees) r.angle_deg *= 180.0 / std::numbers::pi;
  std::set<double> angles_set, radii_set;
  std::vector<std::string> groups;
  for (const Row& r : rows) {
    angles_set.insert(r.angle_deg);
    radii_set.insert(r.radius);
    if (std::find(groups.begin(), groups.end(), r.group) == groups.end()) groups.push_back(r.group);
  }
  const std::vector<double> angles(angles_set.begin(), angles_set.end());
  const std::vector<double> radii(radii_set.begin(), radii_set.end());
  // Titles in words with units (study_words.h), the column's key beside them; the key alone when
  // the study file is gone.
  const std::string selector = selector_of(table, opt.quantity);
  const std::string qtitle = output_title(selector, opt.quantity, unit.unit);
  const std::string qwords = output_words(selector);
  const std::string what = qwords.empty() ? opt.quantity : capitalised(qwords);
  const auto idx = [](const std::vector<double>& v, double x) {
    return static_cast<std::size_t>(std::lower_bound(v.begin(), v.end(), x) - v.begin());
  };
  std::ostringstream csv;
  csv.precision(10);

  if (radial < 0) {
    // value[group][angle]: max over rows that share them (other axes not fixed by --where); the
    // ensemble band likewise spans the lowest min and the highest max of those rows.
    using Grid = std::vector<std::vector<double>>;
    Grid v(groups.size(), std::vector<double>(angles.size(), nan)), lo = v, mean_e = v, hi = v;
    std::vector<std::vector<int>> count(groups.size(), std::vector<int>(angles.size(), 0));
    const auto fold = [](double& into, double x, bool first, auto pick) {
      into = first || !std::isfinite(into) ? x : (std::isfinite(x) ? pick(into, x) : into);
    };
    const auto max_of = [](double x, double y) { return std::max(x, y); };
    const auto min_of = [](double x, double y) { return std::min(x, y); };
    for (const Row& r : rows) {
      const std::size_t g = std::find(groups.begin(), groups.end(), r.group) - groups.begin();
      const std::size_t a = idx(angles, r.angle_deg);
      const bool first = count[g][a]++ == 0;
      fold(v[g][a], r.value, first, max_of);
      fold(lo[g][a], r.lo, first, min_of);
      fold(mean_e[g][a], r.mean, first, max_of);
      fold(hi[g][a], r.hi, first, max_of);
    }
    for (auto& c : count)
      if (std::any_of(c.begin(), c.end(), [](int n) { return n > 1; })) {
        result.notes.push_back(
            "several runs per curve and angle (other axes vary): their maximum "
            "is drawn; fix them with --where AXIS=VALUE");
        break;
      }
    const bool band = ens.band();
    const bool ens_mean = ens.mean >= 0 && q != table.outputs.end();
    PolarEnvelopeData& e = result.envelope;
    e.title = what + " against incidence angle";
    e.quantity = qtitle;
    const auto name = [&](std::size_t g) { return groups[g].empty() ? opt.quantity : groups[g]; };
    csv << "angle_deg";
    if (band && groups.size() == 1) {
      // One curve: member 0 (the model as given) thin, the ensemble mean thick, min-max shaded.
      e.title += " (ensemble)";
      e.curves.push_back({"member 0", angles, v[0], Rgb{31, 119, 180}, 1.5});
      if (ens_mean) e.mean = PolarCurve{"ens. mean", angles, mean_e[0], Rgb{0, 0, 0}, 3.0};
      e.bands.push_back({"ens. min–max", angles, lo[0], hi[0], Rgb{198, 214, 238}});
      csv << "," << name(0) << ",min,mean,max";
    } else if (band) {
      // Several curves: each its ensemble mean (member 0 without one) over its own min-max band
      // in a light tint of its colour; the mean over the curves as before, without a band.
      e.title += ens_mean ? " (ensemble means, min–max)" : " (ensemble min–max)";
      for (std::size_t g = 0; g < groups.size(); ++g) {
        const Rgb c = series_colour(static_cast<int>(g));
        const Rgb tint{static_cast<unsigned char>(c.r + (255 - c.r) * 3 / 4),
                       static_cast<unsigned char>(c.g + (255 - c.g) * 3 / 4),
                       static_cast<unsigned char>(c.b + (255 - c.b) * 3 / 4)};
        e.curves.push_back({name(g), angles, ens_mean ? mean_e[g] : v[g], c, 1.8});
        e.bands.push_back({g == 0 ? "ens. min–max" : "", angles, lo[g], hi[g], tint});
        csv << "," << name(g) << "," << name(g) << "_min," << name(g) << "_mean," << name(g)
            << "_max";
      }
    } else {
      for (std::size_t g = 0; g < groups.size(); ++g) {
        e.curves.push_back({name(g), angles, v[g], {}, 1.5});
        csv << "," << name(g);
      }
    }
    if (groups.size() > 1) {
      PolarCurve mean{"mean", angles, {}, {}, 3.0};
      std::vector<double> band_lo, band_hi;
      for (std::size_t a = 0; a < angles.size(); ++a) {
        double sum = 0, l = std::numeric_limits<double>::infinity(), h = -l;
        int n = 0;
        for (const PolarCurve& c : e.curves)
          if (std::isfinite(c.value[a]))
            sum += c.value[a], ++n, l = std::min(l, c.value[a]), h = std::max(h, c.value[a]);
        mean.value.push_back(n ? sum / n : nan);
        band_lo.push_back(n ? l : nan);
        band_hi.push_back(n ? h : nan);
      }
      if (!band) {
        e.band_angle_deg = angles;
        e.band_lo = band_lo;
        e.band_hi = band_hi;
      }
      e.mean = mean;
      csv << (band ? ",mean" : ",mean,min,max");
    }
    csv << "\n";
    for (std::size_t a = 0; a < angles.size(); ++a) {
      csv << angles[a];
      for (std::size_t g = 0; g < groups.size(); ++g) {
        csv << "," << v[g][a];
        if (band) csv << "," << lo[g][a] << "," << mean_e[g][a] << "," << hi[g][a];
      }
      if (groups.size() > 1) {
        csv << "," << e.mean->value[a];
        if (!band) csv << "," << e.band_lo[a] << "," << e.band_hi[a];
      }
      csv << "\n";
    }
  } else {
    // Mean over the groups (records or cases) at each (radius, angle).
    const DisplayUnit runit = axis_display_unit(table.axes[radial]);
    std::vector<double> sum(angles.size() * radii.size(), 0.0);
    std::vector<int> n(sum.size(), 0);
    for (const Row& r : rows) {
      const std::size_t k = idx(radii, r.radius) * angles.size() + idx(angles, r.angle_deg);
      // With ensemble statistics the ensemble mean is the result (the single run is one member).
      sum[k] += ens.mean >= 0 && std::isfinite(r.mean) ? r.mean : r.value;
      ++n[k];
    }
    PolarContourData& c = result.contour;
    c.title = what + " against incidence angle and " + axis_words(table.axes[radial]);
    if (groups.size() > 1) c.title += " (mean of " + std::to_string(groups.size()) + ")";
    if (ens.mean >= 0) c.title += ", ensemble mean";
    c.radius_title = axis_words(table.axes[radial]) + " [" + runit.unit + "]";
    c.value_title = qtitle;
    c.angle_deg = angles;
    for (double r : radii) c.radius.push_back(r / runit.divisor);
    csv << "angle_deg," << table.axes[radial] << "_" << runit.unit << "," << opt.quantity << "_"
        << unit.unit << "\n";
    for (std::size_t i = 0; i < radii.size(); ++i)
      for (std::size_t a = 0; a < angles.size(); ++a) {
        const std::size_t k = i * angles.size() + a;
        c.value.push_back(n[k] ? sum[k] / n[k] : std::numeric_limits<double>::quiet_NaN());
        csv << angles[a] << "," << c.radius[i] << "," << c.value.back() << "\n";
      }
  }
  // The title says which rows were drawn: the --where filters, as given.
  std::string where;
  for (const auto& [axis, label] : opt.where)
    where += (where.empty() ? "" : ", ") + axis + " = " + label;
  if (!where.empty()) {
    result.envelope.title += " (where " + where + ")";
    result.contour.title += " (where " + where + ")";
  }
  if (!qwords.empty())  // the study's own names, small
    result.envelope.note = result.contour.note = opt.quantity + " = " + selector;
  result.csv = csv.str();
  return result;
}

}  // namespace isopound::post
