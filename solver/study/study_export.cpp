// CSV export of a study database (see study_export.h). Ratio rows and statistics are derived here
// from the stored runs, so they never disagree with them.
#include "solver/study/study_export.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <unordered_map>

#include "solver/study/study_csv.h"
#include "solver/study/study_statistics.h"

namespace isopound {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr char kSeparator = '\x1f';  // joins cells into a key; never in a label

std::string text_of(const Cell& cell) {
  return cell.numeric ? format_number(cell.number) : cell.text;
}

// Axis cells as text, values, and whether the run finished: what ratios and statistics use.
struct TableRow {
  std::vector<std::string> axes;
  std::vector<double> values;
};

std::string key_without(const std::vector<std::string>& cells, const std::vector<bool>& skip) {
  std::string key;
  for (std::size_t i = 0; i < cells.size(); ++i) {
    if (skip[i]) continue;
    key += cells[i];
    key += kSeparator;
  }
  return key;
}

std::vector<TableRow> ratio_rows(const StoreLayout& layout, const std::vector<TableRow>& runs) {
  std::vector<TableRow> out;
  for (const RatioSpec& ratio : layout.ratios) {
    const auto at = std::find(layout.axes.begin(), layout.axes.end(), ratio.axis);
    if (at == layout.axes.end()) continue;
    const std::size_t axis = static_cast<std::size_t>(at - layout.axes.begin());
    std::vector<bool> skip(layout.axes.size(), false);
    skip[axis] = true;
    std::unordered_map<std::string, const TableRow*> denominators;
    for (const TableRow& row : runs)
      if (row.axes[axis] == ratio.denominator)
        denominators.emplace(key_without(row.axes, skip), &row);
    for (const TableRow& row : runs) {
      if (row.axes[axis] != ratio.numerator) continue;
      const auto found = denominators.find(key_without(row.axes, skip));
      TableRow r;
      r.axes = row.axes;
      r.axes[axis] = ratio.name;
      for (std::size_t k = 0; k < row.values.size(); ++k) {
        const double den = found == denominators.end() ? kNaN : found->second->values[k];
        r.values.push_back(den == 0.0 ? kNaN : row.values[k] / den);
      }
      out.push_back(std::move(r));
    }
  }
  return out;
}

std::string statistics_table(const StoreLayout& layout, const std::vector<TableRow>& rows) {
  std::vector<std::string> header = layout.axes;
  for (const char* column : {"over", "output", "n", "mean", "std", "mean_minus_std",
                             "mean_plus_std", "min", "max", "median"})
    header.push_back(column);
  std::string csv = csv_line(header);
  for (const StatisticsSpec& spec : layout.statistics) {
    std::vector<bool> over(layout.axes.size(), false);
    std::string over_text;
    for (const std::string& name : spec.over) {
      const auto at = std::find(layout.axes.begin(), layout.axes.end(), name);
      if (at != layout.axes.end()) over[static_cast<std::size_t>(at - layout.axes.begin())] = true;
      over_text += (over_text.empty() ? "" : "+") + name;
    }
    // Groups in order of first appearance (rows are in case order: deterministic).
    std::vector<std::vector<const TableRow*>> groups;
    std::unordered_map<std::string, std::size_t> group_of;
    for (const TableRow& row : rows) {
      const auto [it, added] = group_of.emplace(key_without(row.axes, over), groups.size());
      if (added) groups.emplace_back();
      groups[it->second].push_back(&row);
    }
    for (const std::vector<const TableRow*>& group : groups) {
      std::vector<std::string> cells = group.front()->axes;
      for (std::size_t i = 0; i < cells.size(); ++i)
        if (over[i]) cells[i].clear();
      for (std::size_t k = 0; k < layout.outputs.size(); ++k) {
        std::vector<double> values;
        for (const TableRow* row : group) values.push_back(row->values[k]);
        const SummaryStatistics s = summarize(values, spec.sample_std);
        std::vector<std::string> line = cells;
        line.push_back(over_text);
        line.push_back(layout.outputs[k]);
        line.push_back(std::to_string(s.n));
        for (const double v :
             {s.mean, s.std, s.mean - s.std, s.mean + s.std, s.min, s.max, s.median})
          line.push_back(format_number(v));
        csv += csv_line(line);
      }
    }
  }
  return csv;
}

}  // namespace

ExportTables export_tables(const StudyStore& store, const ExportOptions& options) {
  const StoreLayout& layout = store.layout();
  const std::vector<RunRow> runs = store.read_runs();
  ExportTables tables;

  std::vector<std::string> header{"case_id"};
  header.insert(header.end(), layout.axes.begin(), layout.axes.end());
  header.push_back("status");
  header.push_back("steps");
  header.insert(header.end(), layout.outputs.begin(), layout.outputs.end());
  if (options.timing) header.push_back("wall_seconds");
  header.push_back("error");
  tables.runs = csv_line(header);

  std::vector<TableRow> rows;
  rows.reserve(runs.size());
  for (const RunRow& run : runs) {
    TableRow row;
    for (const Cell& cell : run.axes) row.axes.push_back(text_of(cell));
    row.values = run.values;
    if (run.status != "done") std::fill(row.values.begin(), row.values.end(), kNaN);
    std::vector<std::string> line{std::to_string(run.case_id)};
    line.insert(line.end(), row.axes.begin(), row.axes.end());
    line.push_back(run.status);
    line.push_back(run.steps < 0 ? "" : std::to_string(run.steps));
    for (const double v : row.values) line.push_back(format_number(v));
    if (options.timing)
      line.push_back(run.status == "pending" ? "" : format_number(run.wall_seconds));
    line.push_back(run.error);
    tables.runs += csv_line(line);
    rows.push_back(std::move(row));
  }

  const std::vector<TableRow> ratios = ratio_rows(layout, rows);
  if (!layout.ratios.empty()) {
    std::vector<std::string> ratio_header = layout.axes;
    ratio_header.insert(ratio_header.end(), layout.outputs.begin(), layout.outputs.end());
    tables.ratios = csv_line(ratio_header);
    for (const TableRow& r : ratios) {
      std::vector<std::string> line = r.axes;
      for (const double v : r.values) line.push_back(format_number(v));
      tables.ratios += csv_line(line);
    }
  }
  if (!layout.statistics.empty()) {
    rows.insert(rows.end(), ratios.begin(), ratios.end());
    tables.statistics = statistics_table(layout, rows);
  }
  // Every column with its unit: outputs in SI, numeric axes hold SI values, ratios are "-".
  const auto unit_of = [](const std::vector<std::string>& units, std::size_t i) {
    return i < units.size() ? units[i] : std::string("SI");
  };
  tables.units = csv_line({"table", "column", "unit"});
  const auto add = [&](const char* table, const std::string& column, const std::string& unit) {
    tables.units += csv_line({table, column, unit});
  };
  add("runs", "case_id", "-");
  for (std::size_t i = 0; i < layout.axes.size(); ++i)
    add("runs", layout.axes[i], unit_of(layout.axis_units, i));
  add("runs", "status", "label");
  add("runs", "steps", "-");
  for (std::size_t i = 0; i < layout.outputs.size(); ++i)
    add("runs", layout.outputs[i], unit_of(layout.output_units, i));
  if (options.timing) add("runs", "wall_seconds", "s");
  add("runs", "error", "text");
  if (!tables.ratios.empty())
    for (std::size_t i = 0; i < layout.outputs.size(); ++i)
      add("ratios", layout.outputs[i], "- (ratio of two runs' values)");
  if (!tables.statistics.empty()) {
    add("statistics", "n", "-");
    for (const char* column :
         {"mean", "std", "mean_minus_std", "mean_plus_std", "min", "max", "median"})
      add("statistics", column, "the unit of the row's output (runs table), '-' for ratios");
  }
  return tables;
}

std::vector<std::string> write_export(const StudyStore& store, const std::string& dir,
                                      const ExportOptions& options) {
  namespace fs = std::filesystem;
  const ExportTables tables = export_tables(store, options);
  fs::create_directories(dir);
  std::vector<std::string> written;
  for (const auto& [name, text] :
       {std::pair{"runs.csv", &tables.runs}, std::pair{"ratios.csv", &tables.ratios},
        std::pair{"statistics.csv", &tables.statistics}, std::pair{"units.csv", &tables.units}}) {
    if (text->empty()) continue;
    const std::string path = (fs::path(dir) / name).string();
    std::ofstream out(path, std::ios::binary);
    out << *text;
    if (!out) throw std::runtime_error(path + ": cannot write");
    written.push_back(path);
  }
  return written;
}

}  // namespace isopound
