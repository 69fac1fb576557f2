// A study's peak against one numeric swept axis (read through solver/study/study_table.h), one
// curve per level of a grouping axis; every other axis fixed by --where (an axis that varies and
// is left open: at the study's first selected run's value, with a note), never averaged over.
// Ensembles as in polar_study.h: line = ensemble mean (Q_ens_mean), band = ensemble min–max.
#pragma once

#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "solver/study/study_table.h"

namespace isopound::post {

// Bad input (unknown axis or output, labels on the x axis, nothing left after the filters): the
// message names the option and the value; the CLI exits 2.
class SweepPlotError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct SweepPlotOptions {
  std::string x_axis;      // --x: a numeric axis column
  std::string output;      // --y: an output (peak) column
  std::string group_axis;  // --group: one curve per level; "" = one curve
  std::vector<std::pair<std::string, std::string>> where;  // --where AXIS=VALUE
  std::string unit;    // --unit of the output; "" = from the study file's selector, else SI
  std::string x_unit;  // --x-unit; "" = from the axis name (gap, uy: cm; angle: deg), else SI
};

// One curve: the finished runs of one group level, in ascending x. Display units.
struct SweepCurve {
  std::string label;  // the group level ("" without --group)
  std::vector<double> x;
  std::vector<double> y;  // the drawn line: the output, or its ensemble mean with a band
  // With an ensemble band (else empty): member 0 (the output column itself, NaN when the table
  // holds only the statistics) and the members' min, mean, max per x.
  std::vector<double> member0, lo, mean, hi;
};

struct SweepPlotData {
  std::string output, x_axis, group_axis;
  std::string output_selector;  // the study file's selector of `output` ("" when unknown)
  std::string unit, x_unit;     // display units, e.g. "cm"
  std::vector<std::pair<std::string, std::string>> where;
  bool band = false;  // ensemble min–max bands (the study has ensembles)
  std::vector<SweepCurve> curves;
  std::vector<std::string> notes;  // skipped runs, empty groups
};

// The curves of `table` (read from `db_path`, named in messages). Throws SweepPlotError.
SweepPlotData sweep_plot_data(const StudyTable& table, const std::string& db_path,
                              const SweepPlotOptions& options);
// Reads the database, then as above; a missing file or a foreign one is a SweepPlotError.
SweepPlotData read_sweep_plot(const std::string& db_path, const SweepPlotOptions& options);

// The plotted numbers, one row per point (long form), display units in the column names:
// [group,] x, output [, member0, ens_min, ens_mean, ens_max].
std::string sweep_plot_csv(const SweepPlotData& data);

// What is drawn, for the figure, in words with units (study_words.h): the title (quantity against
// the axis, grouping), the subtitle (the study column and its selector, the --where filters and
// what line and band are) and the two axis titles.
std::string sweep_plot_title(const SweepPlotData& data);
std::string sweep_plot_subtitle(const SweepPlotData& data);
std::string sweep_plot_x_title(const SweepPlotData& data);
std::string sweep_plot_y_title(const SweepPlotData& data);

}  // namespace isopound::post
