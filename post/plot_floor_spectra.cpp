// The floor-spectra figure (see plot_floor_spectra.h).
#include "post/plot_floor_spectra.h"

#include <algorithm>
#include <cstdio>
#include <map>

#include "post/xy_plot.h"
#include "solver/core/constants.h"

namespace isopound::post {
namespace {

const Rgb kGround{0, 0, 0};
// Equipment (0.05-1 s) and the isolation (2-3 s) lie below this; the CSV keeps every period.
constexpr double kMaxPeriodDrawn = 4.0;

Series series(std::string label, const std::vector<double>& period, const std::vector<double>& psa,
              std::optional<Rgb> colour, double width) {
  std::vector<double> t, a;
  for (std::size_t i = 0; i < period.size(); ++i)
    if (period[i] <= kMaxPeriodDrawn) {
      t.push_back(period[i]);
      a.push_back(psa[i] / kGravity);
    }
  Series s = line_series(std::move(label), t, a);
  s.colour = colour;
  s.width = width;
  return s;
}

std::string level_title(const PlaceSpectra& p) {
  char z[48];
  std::snprintf(z, sizeof z, " (z = %.3g m)", p.elevation);
  return p.structure + "/" + p.level + z;
}

}  // namespace

Figure floor_spectra_figure(const FloorSpectra& f) {
  const std::vector<double>& T = f.periods;
  std::vector<Panel> panels;
  // Levels in the order of the places (structure by structure, bottom to top); drawn top first.
  std::vector<std::vector<const PlaceSpectra*>> levels;
  for (const PlaceSpectra& p : f.places) {
    if (levels.empty() || levels.back().front()->structure != p.structure ||
        levels.back().front()->level != p.level)
      levels.push_back({});
    levels.back().push_back(&p);
  }
  for (auto first = levels.begin(); first != levels.end();) {
    const auto last = std::find_if(first, levels.end(), [&](const auto& l) {
      return l.front()->structure != first->front()->structure;
    });
    std::reverse(first, last);
    first = last;
  }
  for (const auto& places : levels) {
    Panel panel;
    panel.title = level_title(*places.front());
    panel.x_title = "period T [s]";
    panel.y_title = "PSA [g]";
    panel.y_from_zero = true;
    if (!f.three_d) {
      panel.series.push_back(series("floor", T, places.front()->x.psa, series_colour(0), 2.0));
      panel.series.push_back(series("ground", T, f.ground.x.psa, kGround, 1.2));
    } else {
      const PlaceSpectra& cm = *places.front();
      std::vector<double> corners(T.size(), 0.0);
      for (std::size_t k = 1; k < places.size(); ++k)
        for (std::size_t i = 0; i < T.size(); ++i)
          corners[i] = std::max(corners[i], places[k]->rotd->psa100[i]);
      panel.series.push_back(series("CM x", T, cm.x.psa, series_colour(0), 1.5));
      panel.series.push_back(series("CM y", T, cm.y->psa, series_colour(1), 1.5));
      panel.series.push_back(series("CM RotD100", T, cm.rotd->psa100, series_colour(2), 2.0));
      if (places.size() > 1)
        panel.series.push_back(series("corners RotD100 (max)", T, corners, series_colour(3), 2.0));
      panel.series.push_back(series("ground RotD100", T, f.ground.rotd->psa100, kGround, 1.2));
    }
    panels.push_back(std::move(panel));
  }
  // Up to 3 panels side by side; 4 as 2 x 2; more in rows of 3.
  const int columns =
      panels.size() == 4 ? 2 : static_cast<int>(std::min<std::size_t>(panels.size(), 3));
  const int rows = static_cast<int>((panels.size() + columns - 1) / columns);
  char title[96];
  if (f.steps > 0)
    std::snprintf(title, sizeof title, "Floor response spectra, ξ = %g %% (every analysis step)",
                  100.0 * f.damping);
  else
    std::snprintf(title, sizeof title, "Floor response spectra, ξ = %g %% (history every %.4g s)",
                  100.0 * f.damping, f.sampling.row_interval);
  return xy_figure(panels, columns, 420 * columns, 60 + 340 * rows, title);
}

}  // namespace isopound::post
