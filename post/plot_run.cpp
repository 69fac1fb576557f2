// Run figures (see plot_run.h).
#include "post/plot_run.h"

#include <algorithm>
#include <cmath>

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

}  // namespace

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

  Panel ground{"Ground and base", "time [s]", "", {}, true, true};
  const int ag = run.find("", "ground_acceleration");
  // Base (lowest level of the main building) displacement relative to the ground.
  const Level& base = main.levels.front();
  ground.y_title = "displacement [cm]";
  ground.series.push_back(
      line_series(short_label(base.label, run) + " u", t, scaled(run.column(base.u), 0.01)));
  panels.push_back(ground);

  Panel drift{"Story drift ratios", "time [s]", "drift ratio [%]", {}, true, true};
  for (const Structure& s : run.structures)
    for (std::size_t k = 1; k < s.levels.size(); ++k) {
      const Level& lo = s.levels[k - 1];
      const Level& hi = s.levels[k];
      const double h = hi.elevation - lo.elevation;
      if (!(h > 0.0)) continue;
      std::vector<double> r(t.size());
      for (std::size_t i = 0; i < t.size(); ++i)
        r[i] = 100.0 * (run.column(hi.u)[i] - run.column(lo.u)[i]) / h;
      drift.series.push_back(line_series(short_label(hi.label, run), t, r));
    }
  // The first story of an isolated building rests on the base slab; of a neighbour, on the ground.
  for (const Structure& s : run.structures)
    if (!s.levels.empty() && s.levels.front().elevation > 0.0) {
      const Level& l = s.levels.front();
      drift.series.push_back(
          line_series(short_label(l.label, run), t, scaled(run.column(l.u), l.elevation / 100.0)));
    }
  panels.push_back(drift);

  Panel acc{"Absolute accelerations", "time [s]", "absolute acceleration [g]", {}, true, true};
  if (ag >= 0)
    acc.series.push_back({"ground", t, scaled(run.column(ag), kGravity), Rgb{150, 150, 150}, 1.0});
  for (const Structure& s : run.structures)
    for (const Level& l : s.levels)
      if (l.a_abs >= 0)
        acc.series.push_back(
            line_series(short_label(l.label, run), t, scaled(run.column(l.a_abs), kGravity)));
  panels.push_back(acc);

  if (!run.contacts.empty()) {
    double peak = 0.0;
    for (const ElementColumns& c : run.contacts)
      peak = std::max(peak, peak_of(run.column(c.force)));
    std::string unit;
    const double div = force_scale(peak, unit);
    Panel impact{"Impact forces", "time [s]", "impact force [" + unit + "]", {}, true, false, true};
    for (const ElementColumns& c : run.contacts)
      impact.series.push_back(
          line_series(short_label(c.label, run), t, scaled(run.column(c.force), div)));
    panels.push_back(impact);
  }
  std::vector<NamedFigure> out;
  const int rows = static_cast<int>(panels.size());
  out.push_back(
      {"time_histories.png", xy_figure(panels, 1, 1000, 230 * rows + 40,
                                       "Time histories: " + run.dir.filename().string())});

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
    out.push_back({"hysteresis.png", xy_figure(loops, columns, 500 * columns, 360 * rows_l + 40,
                                               "Hysteresis: " + run.dir.filename().string())});
  }
  return out;
}

}  // namespace isopound::post
