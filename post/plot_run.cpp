// Run figures (see plot_run.h).
#include "post/plot_run.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "post/plot_run3d.h"
#include "post/xy_plot.h"
#include "solver/core/constants.h"

namespace isopound::post {
namespace {

std::string short_label(const std::string& label, const RunData& run) {
  // Drop the structure name when there is one structure.
  if (run.structures.size() == 1) {
    const auto slash = label.find('/');
    if (slash != std::string::npos) return label.substr(slash + 1);
  }
  return label;
}

// Ground displacement from the ground-acceleration column, integrated exactly as a piecewise-linear
// acceleration from rest (the solver's rule for the record): v' = a, u' = v between samples.
std::vector<double> ground_displacement(const std::vector<double>& t,
                                        const std::vector<double>& a) {
  std::vector<double> u(t.size(), 0.0);
  double v = 0.0;
  for (std::size_t i = 1; i < t.size(); ++i) {
    const double h = t[i] - t[i - 1];
    u[i] = u[i - 1] + h * v + h * h * (a[i - 1] / 3.0 + a[i] / 6.0);
    v += 0.5 * h * (a[i - 1] + a[i]);
  }
  return u;
}

}  // namespace

std::string peak_text(const ReportedPeak& peak, double divisor, const std::string& unit) {
  char buf[96];
  if (peak.time)
    std::snprintf(buf, sizeof buf, "%.4g %s at %.3f s", peak.value / divisor, unit.c_str(),
                  *peak.time);
  else
    std::snprintf(buf, sizeof buf, "%.4g %s", peak.value / divisor, unit.c_str());
  return buf;
}

void mark_reported_peaks(Panel& panel, const std::vector<std::optional<ReportedPeak>>& peaks,
                         double divisor, const std::string& unit) {
  int largest = -1;
  for (std::size_t k = 0; k < peaks.size() && k < panel.series.size(); ++k)
    if (peaks[k] && peaks[k]->time && (largest < 0 || peaks[k]->value > peaks[largest]->value))
      largest = static_cast<int>(k);
  for (std::size_t k = 0; k < peaks.size() && k < panel.series.size(); ++k) {
    if (!peaks[k]) continue;
    Series& s = panel.series[k];
    const std::string text = "peak " + peak_text(*peaks[k], divisor, unit);
    if (!s.label.empty())
      s.label += peaks[k]->time ? " — " + text : " — " + text + " (time not reported)";
    if (!peaks[k]->time) continue;
    panel.marks.push_back({*peaks[k]->time, peaks[k]->signed_value / divisor,
                           static_cast<int>(k) == largest ? text + " (summary.json)" : "",
                           s.colour.value_or(series_colour(static_cast<int>(k)))});
  }
}

std::vector<Panel> acceleration_panels(std::vector<PeakedSeries> all, int base,
                                       const std::array<std::string, 3>& titles, bool symmetric) {
  const auto panel = [&](const std::string& title) {
    return Panel{title, "time [s]", "absolute acceleration [g]", {}, true, symmetric, !symmetric};
  };
  Panel own = panel(titles[0]), rest = panel(base >= 0 ? titles[1] : titles[2]);
  std::vector<std::optional<ReportedPeak>> own_peaks, rest_peaks;
  for (std::size_t k = 0; k < all.size(); ++k) {
    Series& s = all[k].series;
    if (!s.colour) s.colour = series_colour(static_cast<int>(k));
    (static_cast<int>(k) == base ? own : rest).series.push_back(std::move(s));
    (static_cast<int>(k) == base ? own_peaks : rest_peaks).push_back(all[k].peak);
  }
  mark_reported_peaks(rest, rest_peaks, kGravity, "g");
  if (base < 0) return {rest};
  mark_reported_peaks(own, own_peaks, kGravity, "g");
  return {own, rest};
}

std::string sampled_every(const RunData& run) {
  char buf[96];
  std::snprintf(buf, sizeof buf, "curves: histories.csv every %g ms", 1e3 * history_interval(run));
  return buf;
}

double force_scale(double peak_newton, std::string& unit) {
  if (peak_newton >= 1e7) {
    unit = "MN";
    return 1e6;
  }
  unit = "kN";
  return 1e3;
}

std::vector<NamedFigure> run_figures(const RunData& run) {
  if (run.three_d) return run_figures3d(run);
  const std::vector<double>& t = run.time();
  std::vector<Panel> panels;
  const Structure& main = run.structures.front();

  // Ground displacement (from its acceleration) and the base's relative to the ground.
  Panel ground{"Ground and base", "time [s]", "displacement [cm]", {}, true, true};
  ground.legend_at = Panel::LegendAt::kBest;
  const int ag = run.find("", "ground_acceleration");
  // The isolated slab wherever it sits (isolated above a storey it is not the lowest level).
  const auto slab = std::find_if(main.levels.begin(), main.levels.end(),
                                 [&](const Level& l) { return l.label == main.name + "/base"; });
  const Level& base = slab != main.levels.end() ? *slab : main.levels.front();
  std::vector<std::optional<ReportedPeak>> ground_peaks;
  if (ag >= 0) {
    ground.series.push_back({"ground (a_g integrated twice)", t,
                             scaled(ground_displacement(t, run.column(ag)), 0.01),
                             Rgb{150, 150, 150}, 1.0});
    ground_peaks.push_back(reported_ground_peak(run, "pgd_m"));
  }
  ground.series.push_back(line_series(short_label(base.label, run) + " u (relative to the ground)",
                                      t, scaled(run.column(base.u), 0.01)));
  ground_peaks.push_back(reported_level_peak(run, base.label, "displacement"));
  mark_reported_peaks(ground, ground_peaks, 0.01, "cm");
  panels.push_back(ground);

  // Storey k of a structure: between its levels k-1 and k, or from the ground to its first level
  // when that stands above the ground (a neighbour); numbered from the bottom as summary.json.
  Panel drift{"Storey drift ratios", "time [s]", "drift ratio [%]", {}, true, true};
  std::vector<std::optional<ReportedPeak>> drift_peaks;
  for (const Structure& s : run.structures) {
    const bool on_ground = !s.levels.empty() && s.levels.front().elevation > 0.0;
    int story = 0;
    for (std::size_t k = on_ground ? 0 : 1; k < s.levels.size(); ++k) {
      const Level* lo = k > 0 ? &s.levels[k - 1] : nullptr;  // nullptr: the ground
      const Level& hi = s.levels[k];
      // The isolation layer under a slab above the ground is the isolator, no storey.
      if (lo && hi.label == s.name + "/base") continue;
      const double h = hi.elevation - (lo ? lo->elevation : 0.0);
      ++story;
      if (!(h > 0.0)) continue;
      std::vector<double> r(t.size());
      for (std::size_t i = 0; i < t.size(); ++i)
        r[i] = 100.0 * (run.column(hi.u)[i] - (lo ? run.column(lo->u)[i] : 0.0)) / h;
      const std::string lo_name =
          lo ? lo->label.substr(lo->label.find('/') + 1) : std::string("ground");
      const std::string name = "storey " + std::to_string(story) + " (" + lo_name + "–" +
                               hi.label.substr(hi.label.find('/') + 1) + ")";
      drift.series.push_back(
          line_series(run.structures.size() > 1 ? s.name + "/" + name : name, t, r));
      drift_peaks.push_back(reported_drift_ratio_peak(run, s.name, story));
    }
  }
  mark_reported_peaks(drift, drift_peaks, 0.01, "%");
  panels.push_back(drift);

  std::vector<PeakedSeries> accelerations;
  if (ag >= 0)
    accelerations.push_back(
        {{"ground", t, scaled(run.column(ag), kGravity), Rgb{120, 120, 120}, 1.2},
         reported_ground_peak(run, "pga_m_s2")});
  int base_index = -1;
  for (const Structure& s : run.structures)
    for (const Level& l : s.levels)
      if (l.a_abs >= 0) {
        if (slab != main.levels.end() && &l == &base)
          base_index = static_cast<int>(accelerations.size());
        accelerations.push_back(
            {line_series(short_label(l.label, run), t, scaled(run.column(l.a_abs), kGravity)),
             reported_level_peak(run, l.label, "absolute_acceleration")});
      }
  for (Panel& p : acceleration_panels(
           std::move(accelerations), base_index,
           {short_label(base.label, run) + ": absolute acceleration",
            "Absolute accelerations of the floors and the ground", "Absolute accelerations"},
           true))
    panels.push_back(std::move(p));

  if (!run.contacts.empty()) {
    double peak = 0.0;
    for (const ElementColumns& c : run.contacts) {
      peak = std::max(peak, peak_of(run.column(c.force)));
      if (const auto p = reported_element_peak(run, c.label, "force"))
        peak = std::max(peak, p->value);
    }
    std::string unit;
    const double div = force_scale(peak, unit);
    Panel impact{"Impact forces", "time [s]", "impact force [" + unit + "]", {}, true, false, true};
    std::vector<std::optional<ReportedPeak>> impact_peaks;
    for (const ElementColumns& c : run.contacts) {
      impact.series.push_back(
          line_series(short_label(c.label, run), t, scaled(run.column(c.force), div)));
      impact_peaks.push_back(reported_element_peak(run, c.label, "force"));
    }
    mark_reported_peaks(impact, impact_peaks, div, unit);
    panels.push_back(impact);
  }
  std::vector<NamedFigure> out;
  const int rows = static_cast<int>(panels.size());
  NamedFigure th{"time_histories.png", {}, {}};
  for (Panel& p : panels) p.legend_above_data = true;
  th.figure = xy_figure(panels, 1, 1000, kHistoryPanelHeight * rows + 40,
                        "Time histories: " + run.dir.filename().string() + " (" +
                            sampled_every(run) + "; ◆ peaks over every step, summary.json)",
                        &th.frames);
  out.push_back(std::move(th));

  std::vector<Panel> loops;
  for (const ElementColumns& e : run.isolators) {
    if (e.deformation < 0) continue;
    std::string unit;
    const double div = force_scale(peak_of(run.column(e.force)), unit);
    Panel p{short_label(e.label, run),
            "isolator deformation [cm]",
            "isolator force [" + unit + "]",
            {},
            false,
            true};
    p.series.push_back(
        line_series("", scaled(run.column(e.deformation), 0.01), scaled(run.column(e.force), div)));
    loops.push_back(p);
  }
  for (const ElementColumns& e : run.contacts) {
    std::string unit;
    const double div = force_scale(peak_of(run.column(e.force)), unit);
    Panel p{short_label(e.label, run),
            "penetration δ [mm]",
            "impact force [" + unit + "]",
            {},
            false,
            false,
            true};
    p.series.push_back(
        line_series("", scaled(run.column(e.penetration), 1e-3), scaled(run.column(e.force), div)));
    loops.push_back(p);
  }
  if (!loops.empty()) {
    const int columns = loops.size() > 1 ? 2 : 1;
    const int rows_l = static_cast<int>((loops.size() + columns - 1) / columns);
    out.push_back(
        {"hysteresis.png",
         xy_figure(loops, columns, 500 * columns, 360 * rows_l + 40,
                   "Hysteresis: " + run.dir.filename().string() + " (" + sampled_every(run) + ")"),
         {}});
  }
  return out;
}

}  // namespace isopound::post
