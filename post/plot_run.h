// The figures of one run: time histories (ground and base, story drift ratios, absolute floor
// accelerations, impact forces) and hysteresis loops (isolator force vs deformation, impact force
// vs penetration), axes in engineering units (cm, g, kN or MN, %). Curves are the histories.csv
// samples (the title says every how long); each time history's true peak, over every analysis
// step, is marked from summary.json (run_peaks.h) with its value and time.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "post/figure.h"
#include "post/run_data.h"
#include "post/run_peaks.h"
#include "post/xy_plot.h"

namespace isopound::post {

struct NamedFigure {
  std::string file;  // e.g. "time_histories.png"
  Figure figure;
  std::vector<PanelFrame> frames{};  // where each panel's data lands (xy_figure's), for tests
};

// px per panel of time_histories.png: room for the curves below a legend of four or five lines
// (Panel::legend_above_data).
inline constexpr int kHistoryPanelHeight = 270;

// time_histories.png and hysteresis.png (the latter only when the run has isolators or contacts);
// a 3D run's figures are run_figures3d's (plot_run3d.h).
std::vector<NamedFigure> run_figures(const RunData& run);

// "124.7 g at 7.099 s" for a peak in SI shown as value / divisor in `unit` (no time: the value).
std::string peak_text(const ReportedPeak& peak, double divisor, const std::string& unit);

// Marks the reported peak of each series of a time-history panel (peaks[k] of series k, in SI;
// nothing for a series without one): a diamond in the series' colour at (time, signed value /
// divisor) and "peak ... (summary.json)" in its legend label; the panel's largest also gets that
// text beside its marker. A peak without a time gets no marker, its value in the legend only.
void mark_reported_peaks(Panel& panel, const std::vector<std::optional<ReportedPeak>>& peaks,
                         double divisor, const std::string& unit);

// A curve of a time-history panel with the peak summary.json reports for it (nullopt: none).
struct PeakedSeries {
  Series series;
  std::optional<ReportedPeak> peak;
};

// The absolute-acceleration panels of a time-history figure, in g (`all` in SI divided by
// kGravity already; the peaks in SI): with an isolated base (all[base], tens of g where it
// strikes a wall) that one in a panel of its own titled titles[0], so that the floors and the
// ground (a few g and less) set the axis of theirs, titles[1]; base < 0: one panel, titles[2].
// Each curve without a colour takes that of its place in `all`, the same in either panel.
std::vector<Panel> acceleration_panels(std::vector<PeakedSeries> all, int base,
                                       const std::array<std::string, 3>& titles, bool symmetric);

// " (curves: histories.csv every 5 ms)" for the title of a figure of sampled curves.
std::string sampled_every(const RunData& run);

// Force unit for a peak |F| in N: kN below 10 MN, else MN. Returns the divisor and sets unit.
double force_scale(double peak_newton, std::string& unit);

}  // namespace isopound::post
