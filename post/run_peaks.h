// The peaks summary.json reports for the quantities the run figures draw, and the interval of the
// histories' samples. summary.json's peaks are over every analysis step; histories.csv holds
// samples every output interval, so a drawn curve can peak lower than the run did (impacts last
// milliseconds). Beside run_data.h, the only place that knows summary.json's keys for peaks.
#pragma once

#include <optional>
#include <string>

#include "post/run_data.h"

namespace isopound::post {

// A peak of |quantity| as summary.json reports it, in SI.
struct ReportedPeak {
  double value = 0.0;          // max |x|
  double signed_value = 0.0;   // the extreme with its sign (value or -value; value when unsigned)
  std::optional<double> time;  // s; empty when summary.json does not report when
  std::string key;             // where it was read, e.g. "structures[0].levels[1].displacement"
};

// The sampling interval of histories.csv: the median time step of its rows (s; 0 for < 2 rows).
double history_interval(const RunData& run);

// 2D: a level's peak "displacement" or "absolute_acceleration" (by the level's full label).
// 3D: at the level's centre of mass (label "<building>/<level>"), `component` "x", "y" or
// "resultant".
std::optional<ReportedPeak> reported_level_peak(const RunData& run, const std::string& level,
                                                const std::string& quantity,
                                                const std::string& component = "resultant");

// 2D: the peak drift ratio of story `story` (1-based, counted from the ground or the base slab)
// of a structure. 3D: the largest corner-column drift ratio of storey `story` (the worst corner).
std::optional<ReportedPeak> reported_drift_ratio_peak(const RunData& run,
                                                      const std::string& structure, int story);

// 2D elements: "peak_<output>" of the element labelled `label` (e.g. "force").
// 3D contacts (label "a|b"): "normal_force" or "tangential_force".
std::optional<ReportedPeak> reported_element_peak(const RunData& run, const std::string& label,
                                                  const std::string& output);

// A ground-motion peak "pga_m_s2" or "pgd_m" (of the record, x in 3D; its time is not reported).
std::optional<ReportedPeak> reported_ground_peak(const RunData& run, const std::string& key);

}  // namespace isopound::post
