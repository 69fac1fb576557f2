// Study table -> sweep-plot curves and their CSV (see sweep_plot.h).
#include "post/sweep_plot.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <map>
#include <numbers>
#include <set>

#include "post/polar_study.h"
#include "post/study_words.h"
#include "solver/io/units.h"

namespace isopound::post {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

std::string join(const std::vector<std::string>& v, std::size_t limit = 12) {
  std::string s;
  for (std::size_t i = 0; i < v.size() && i < limit; ++i) s += (i ? ", " : "") + v[i];
  if (v.size() > limit) s += ", … (" + std::to_string(v.size()) + " in all)";
  return s.empty() ? "(none)" : s;
}

// Shortest text that reads back as the same double (the study's own tables write numbers so).
std::string number_text(double x) {
  if (std::isnan(x)) return "";
  char buf[32];
  const auto end = std::to_chars(buf, buf + sizeof buf, x).ptr;
  return std::string(buf, end);
}

// An axis value in its display unit, to the 12 significant digits the study writes axes with
// (0.104 m is 10.4 cm, not 10.399999999999999).
double axis_display(double si, double divisor) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.12g", si / divisor);
  return std::strtod(buf, nullptr);
}

std::string cell_text(const StudyTableCell& c) {
  return c.numeric && c.text.empty() ? number_text(c.number) : c.text;
}

// --unit / --x-unit: polar's unit names, and deg for angle axes (stored in rad).
DisplayUnit named_unit(const std::string& unit, const char* option) {
  if (unit == "deg") return {"deg", std::numbers::pi / 180.0};
  try {
    return {unit, unit_divisor(unit)};
  } catch (const PolarStudyError&) {
    throw SweepPlotError(std::string(option) + " '" + unit +
                         "': not a unit this command knows; use m, cm, mm, m/s, g, m/s2, N, kN, "
                         "MN, %, -, J, kJ, MJ, rad, deg, m2, s or SI");
  }
}

// A --where value against a cell: labels by text; numbers by value within 1e-9 (relative), the
// value written in SI ("0.2") or with a unit ("20 cm"), or by the cell's own text.
bool matches(const StudyTableCell& c, const std::string& value) {
  if (!c.numeric || !c.text.empty()) return c.text == value || cell_text(c) == value;
  double v = 0.0;
  try {
    v = parse_quantity(value).si;
  } catch (const UnitError&) {
    return false;
  }
  return std::abs(v - c.number) <= 1e-9 * std::max({std::abs(v), std::abs(c.number), 1e-300});
}

// Distinct texts of axis `a` over `rows`, in first-appearance order.
std::vector<std::string> levels_of(const std::vector<const StudyTableRow*>& rows, int a) {
  std::vector<std::string> out;
  for (const StudyTableRow* r : rows) {
    const std::string t = cell_text(r->axes[a]);
    if (std::find(out.begin(), out.end(), t) == out.end()) out.push_back(t);
  }
  return out;
}

std::string where_text(const std::pair<std::string, std::string>& w) {
  return w.first + "=" + w.second;
}

// A CSV column's unit suffix: "_cm", "_pct" for %, none for "-".
std::string unit_suffix(const std::string& unit) {
  if (unit.empty() || unit == "-") return "";
  std::string s = "_";
  for (char c : unit)
    s += c == '%' ? std::string("pct") : c == '/' ? std::string("_") : std::string(1, c);
  return s;
}

}  // namespace

SweepPlotData sweep_plot_data(const StudyTable& table, const std::string& db_path,
                              const SweepPlotOptions& opt) {
  const auto axis_index = [&](const std::string& name, const std::string& option) {
    const auto it = std::find(table.axes.begin(), table.axes.end(), name);
    if (it == table.axes.end())
      throw SweepPlotError(db_path + ": " + option + " '" + name +
                           "': not an axis of the study; its axes are: " + join(table.axes, 100));
    return static_cast<int>(it - table.axes.begin());
  };
  const int x = axis_index(opt.x_axis, "--x");
  const int g = opt.group_axis.empty() ? -1 : axis_index(opt.group_axis, "--group");
  if (g == x)
    throw SweepPlotError("--group '" + opt.group_axis + "': it is the --x axis; group by another");
  std::vector<std::pair<int, std::string>> filters;
  for (const auto& w : opt.where) {
    const int a = axis_index(w.first, "--where '" + where_text(w) + "':");
    if (a == x || a == g)
      throw SweepPlotError("--where '" + where_text(w) + "': " + w.first + " is the " +
                           (a == x ? "--x" : "--group") + " axis; it cannot also be fixed");
    filters.push_back({a, w.second});
  }

  // The output column, or its ensemble mean when the table holds only the statistics.
  SweepPlotData data;
  data.output = opt.output;
  data.x_axis = opt.x_axis;
  data.group_axis = opt.group_axis;
  data.where = opt.where;
  const EnsembleColumns ens = ensemble_columns(table.outputs, opt.output);
  const auto q = std::find(table.outputs.begin(), table.outputs.end(), opt.output);
  if (q == table.outputs.end() && ens.mean < 0)
    throw SweepPlotError(
        db_path + ": --y '" + opt.output +
        "': not an output of the study; its outputs are: " + join(table.outputs, 100));
  const int value_column =
      q != table.outputs.end() ? static_cast<int>(q - table.outputs.begin()) : ens.mean;
  if (q == table.outputs.end())
    data.notes.push_back("'" + opt.output + "' itself is not in the table: its ensemble mean '" +
                         table.outputs[ens.mean] + "' is drawn");
  data.band = ens.band();
  if (q != table.outputs.end() &&
      static_cast<std::size_t>(q - table.outputs.begin()) < table.output_selectors.size())
    data.output_selector = table.output_selectors[q - table.outputs.begin()];
  const DisplayUnit unit =
      !opt.unit.empty() ? named_unit(opt.unit, "--unit")
                        : (q != table.outputs.end() && static_cast<std::size_t>(value_column) <
                                                           table.output_quantities.size()
                               ? display_unit_of(table.output_quantities[value_column])
                               : DisplayUnit{"SI", 1.0});
  const DisplayUnit xunit =
      opt.x_unit.empty() ? axis_display_unit(opt.x_axis) : named_unit(opt.x_unit, "--x-unit");
  data.unit = unit.unit;
  data.x_unit = xunit.unit;

  // Every --where value must name a level of its axis.
  for (std::size_t i = 0; i < filters.size(); ++i) {
    const auto [a, value] = filters[i];
    if (std::none_of(table.rows.begin(), table.rows.end(),
                     [&](const StudyTableRow& r) { return matches(r.axes[a], value); })) {
      std::vector<const StudyTableRow*> all;
      for (const StudyTableRow& r : table.rows) all.push_back(&r);
      throw SweepPlotError("--where '" + where_text(opt.where[i]) + "': no run has " +
                           table.axes[a] + " = " + value +
                           "; its values are: " + join(levels_of(all, a)));
    }
  }
  // The finished runs that pass the filters.
  std::vector<const StudyTableRow*> rows;
  int unfinished = 0;
  for (const StudyTableRow& r : table.rows) {
    if (!std::all_of(filters.begin(), filters.end(),
                     [&](const auto& f) { return matches(r.axes[f.first], f.second); }))
      continue;
    if (r.status != "done") {
      ++unfinished;
      continue;
    }
    rows.push_back(&r);
  }
  if (unfinished > 0)
    data.notes.push_back(std::to_string(unfinished) +
                         " selected runs are not finished (pending or failed): left out");
  if (rows.empty())
    throw SweepPlotError(db_path + ": no finished runs" +
                         (opt.where.empty() ? std::string() : " with the --where filters") +
                         " to plot");
  for (const StudyTableRow* r : rows)
    if (!r->axes[x].numeric) {
      std::vector<std::string> numeric;
      for (std::size_t a = 0; a < table.axes.size(); ++a)
        if (r->axes[a].numeric) numeric.push_back(table.axes[a]);
      throw SweepPlotError("--x '" + opt.x_axis + "': the axis holds labels (" +
                           join(levels_of(rows, x), 6) +
                           "), not numbers; numeric axes: " + join(numeric));
    }

  // Never average: within one curve, one x must be one run. Axes that take several values at the
  // same (group, x) vary and must be fixed (a zip partner of x or of the group does not vary).
  std::map<std::pair<std::string, double>, std::vector<const StudyTableRow*>> cells;
  for (const StudyTableRow* r : rows)
    cells[{g >= 0 ? cell_text(r->axes[g]) : "", r->axes[x].number}].push_back(r);
  // A default never refuses: such axes are fixed at the study's first selected run (a zip
  // partner keeps its own value there), said in one note and in the subtitle.
  std::vector<std::string> varying, fixed;
  std::vector<int> fixed_axes;
  for (std::size_t a = 0; a < table.axes.size(); ++a) {
    if (static_cast<int>(a) == x || static_cast<int>(a) == g) continue;
    const bool varies = std::any_of(cells.begin(), cells.end(), [&](const auto& cell) {
      return levels_of(cell.second, static_cast<int>(a)).size() > 1;
    });
    if (!varies) continue;
    const std::vector<std::string> levels = levels_of(rows, static_cast<int>(a));
    varying.push_back(table.axes[a] + " (" + std::to_string(levels.size()) +
                      " values: " + join(levels, 6) + ")");
    const StudyTableCell& first = rows.front()->axes[a];
    const DisplayUnit au = axis_display_unit(table.axes[a]);
    const std::string shown =
        first.numeric && first.text.empty() && au.unit != "SI"
            ? number_text(axis_display(first.number, au.divisor)) + " " + au.unit
            : cell_text(first);
    fixed.push_back(table.axes[a] + " = " + shown);
    data.where.push_back({table.axes[a], shown});
    fixed_axes.push_back(static_cast<int>(a));
  }
  if (!varying.empty()) {
    const StudyTableRow* first = rows.front();
    std::erase_if(rows, [&](const StudyTableRow* r) {
      return std::any_of(fixed_axes.begin(), fixed_axes.end(),
                         [&](int a) { return cell_text(r->axes[a]) != cell_text(first->axes[a]); });
    });
    data.notes.push_back("axes that are neither --x nor --group vary: " + join(varying, 100) +
                         "; drawn at " + join(fixed, 100) +
                         " (the first run's; runs are never averaged): --where AXIS=VALUE "
                         "chooses another value, --group AXIS one curve per value");
  }

  // The curves, in the order the study enumerates the groups.
  const auto value = [&](const StudyTableRow* r, int column) {
    return column >= 0 && static_cast<std::size_t>(column) < r->values.size()
               ? r->values[column] / unit.divisor
               : kNaN;
  };
  const std::vector<std::string> groups =
      g >= 0 ? levels_of(rows, g) : std::vector<std::string>{""};
  const DisplayUnit gunit = g >= 0 ? axis_display_unit(opt.group_axis) : DisplayUnit{};
  for (const std::string& level : groups) {
    std::vector<const StudyTableRow*> in;
    for (const StudyTableRow* r : rows)
      if (g < 0 || cell_text(r->axes[g]) == level) in.push_back(r);
    std::stable_sort(in.begin(), in.end(), [&](const StudyTableRow* a, const StudyTableRow* b) {
      return a->axes[x].number < b->axes[x].number;
    });
    SweepCurve c;
    c.label = level;
    if (g >= 0 && in.front()->axes[g].numeric && in.front()->axes[g].text.empty())
      c.label = opt.group_axis + " = " + number_text(in.front()->axes[g].number / gunit.divisor) +
                (gunit.unit == "SI" ? "" : " " + gunit.unit);
    for (const StudyTableRow* r : in) {
      const double y = data.band && ens.mean >= 0 ? value(r, ens.mean) : value(r, value_column);
      if (!std::isfinite(y)) continue;  // an empty cell: e.g. a wall peak of a run without walls
      c.x.push_back(axis_display(r->axes[x].number, xunit.divisor));
      c.y.push_back(y);
      if (!data.band) continue;
      c.member0.push_back(q != table.outputs.end() ? value(r, value_column) : kNaN);
      c.lo.push_back(value(r, ens.min));
      c.mean.push_back(value(r, ens.mean));
      c.hi.push_back(value(r, ens.max));
    }
    if (c.x.empty()) {
      data.notes.push_back((level.empty() ? opt.output : level) +
                           ": no finished run has a value of '" + opt.output + "': no curve");
      continue;
    }
    data.curves.push_back(std::move(c));
  }
  if (data.curves.empty())
    throw SweepPlotError(db_path + ": --y '" + opt.output +
                         "': no selected run has a value (all cells empty)");
  return data;
}

SweepPlotData read_sweep_plot(const std::string& db_path, const SweepPlotOptions& options) {
  StudyTable table;
  try {
    table = read_study_table(db_path);
  } catch (const StudyTableError& e) {
    // A missing or foreign file is the user's mistake; a study that cannot be read is not.
    if (e.reason() == StudyTableError::Reason::unreadable) throw;
    throw SweepPlotError(e.what());
  }
  return sweep_plot_data(table, db_path, options);
}

std::string sweep_plot_csv(const SweepPlotData& d) {
  const std::string u = unit_suffix(d.unit);
  std::string csv;
  if (!d.group_axis.empty()) csv += d.group_axis + ",";
  csv += d.x_axis + unit_suffix(d.x_unit) + ",";
  if (d.band)
    csv += d.output + "_member0" + u + "," + d.output + "_ens_min" + u + "," + d.output +
           "_ens_mean" + u + "," + d.output + "_ens_max" + u;
  else
    csv += d.output + u;
  csv += "\n";
  for (const SweepCurve& c : d.curves)
    for (std::size_t i = 0; i < c.x.size(); ++i) {
      if (!d.group_axis.empty()) csv += c.label + ",";
      csv += number_text(c.x[i]) + ",";
      if (d.band)
        csv += number_text(c.member0[i]) + "," + number_text(c.lo[i]) + "," +
               number_text(c.mean[i]) + "," + number_text(c.hi[i]);
      else
        csv += number_text(c.y[i]);
      csv += "\n";
    }
  return csv;
}

std::string sweep_plot_x_title(const SweepPlotData& d) {
  return axis_words(d.x_axis) + " [" + d.x_unit + "]";
}

std::string sweep_plot_y_title(const SweepPlotData& d) {
  return output_title(d.output_selector, d.output, d.unit);
}

std::string sweep_plot_title(const SweepPlotData& d) {
  std::string t = capitalised(sweep_plot_y_title(d)) + " against " + sweep_plot_x_title(d);
  if (!d.group_axis.empty()) t += ", one curve per " + axis_words(d.group_axis);
  return t;
}

std::string sweep_plot_subtitle(const SweepPlotData& d) {
  // The study's own names first, small: the column and its selector.
  std::string s = d.output_selector.empty() ? "" : d.output + " = " + d.output_selector;
  bool where = false;
  for (const auto& w : d.where) {
    s += (s.empty() ? ""
          : where   ? ", "
                    : "; ") +
         std::string(where ? "" : "where ") + w.first + " = " + w.second;
    where = true;
  }
  if (d.band) {
    if (!s.empty()) s += "; ";
    bool member0 = false;
    for (const SweepCurve& c : d.curves)
      for (double v : c.member0) member0 = member0 || std::isfinite(v);
    s += d.curves.size() > 1 ? "lines: ensemble means"
         : member0           ? "thick: ensemble mean, thin: member 0"
                             : "line: ensemble mean";
    s += ", shaded: ensemble min–max";
  }
  return s;
}

}  // namespace isopound::post
