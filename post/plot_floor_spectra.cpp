// The floor-spectra figure (see plot_floor_spectra.h).
#include "post/plot_floor_spectra.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "solver/core/constants.h"

namespace isopound::post {
namespace {

const Rgb kGround{0, 0, 0};
// Equipment (0.05-1 s) and the isolation (2-3 s) lie below this; the CSV keeps every period.
constexpr double kMaxPeriodDrawn = 4.0;
// "Long periods" for the PSA axis rule: the isolation's range and beyond.
constexpr double kLongPeriod = 1.0;

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

// The level, its elevation and its peak floor acceleration (the spectra at T = 0, when computed).
std::string level_title(const PlaceSpectra& p, double pfa_g) {
  char z[80];
  if (std::isfinite(pfa_g))
    std::snprintf(z, sizeof z, " (z = %.3g m): PFA %.3g g", p.elevation, pfa_g);
  else
    std::snprintf(z, sizeof z, " (z = %.3g m)", p.elevation);
  return p.structure + "/" + p.level + z;
}

// The panel's axes by the rules of plot_floor_spectra.h; the peak PSA and the long-period one
// over the values a log period axis shows (T > 0). Then room above the curves for the legend at
// the top right: an undrawn, unlabelled point that puts the peak below the legend's entries.
void choose_axes(Panel& panel, bool log_period) {
  panel.log_x = log_period;
  double peak = 0.0, long_peak = 0.0, low = std::numeric_limits<double>::infinity();
  double t_lo = std::numeric_limits<double>::infinity();
  for (const Series& s : panel.series)
    for (std::size_t i = 0; i < s.x.size(); ++i) {
      if (log_period && !(s.x[i] > 0.0)) continue;
      peak = std::max(peak, s.y[i]);
      if (s.y[i] > 0.0) low = std::min(low, s.y[i]);
      if (s.x[i] >= kLongPeriod) long_peak = std::max(long_peak, s.y[i]);
      t_lo = std::min(t_lo, s.x[i]);
    }
  panel.log_y = long_peak > 0.0 && peak > kLogPsaRatio * long_peak;
  panel.x_title = log_period ? "period T [s], log scale" : "period T [s]";
  panel.y_title = panel.log_y ? "PSA [g], log scale" : "PSA [g]";
  panel.y_from_zero = !panel.log_y;
  panel.legend_at = Panel::LegendAt::kTopRight;
  if (!(peak > 0.0) || !std::isfinite(t_lo)) return;
  // The legend's entries take 16 px each and 24 px of margin of a plot about 280 px high.
  const auto entries = std::count_if(panel.series.begin(), panel.series.end(),
                                     [](const Series& s) { return !s.label.empty(); });
  const double share = std::clamp(1.0 - (24.0 + 16.0 * entries) / 280.0, 0.5, 0.9);
  const double top = panel.log_y ? low * std::pow(peak / low, 1.0 / share) : peak / share;
  Series room = line_series("", {t_lo}, {top});
  room.width = 0.0;
  panel.series.push_back(std::move(room));
}

}  // namespace

Figure floor_spectra_figure(const FloorSpectra& f, std::vector<PanelFrame>* frames) {
  const std::vector<double>& T = f.periods;
  double shortest = std::numeric_limits<double>::infinity(), longest = 0.0;
  for (double t : T)
    if (t > 0.0 && t <= kMaxPeriodDrawn) shortest = std::min(shortest, t), longest = t;
  const bool log_period = longest > kLogPeriodSpan * shortest;
  const bool has_zero = !T.empty() && T.front() == 0.0;

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
    // The largest T = 0 value of the level's places: its peak floor acceleration.
    double pfa = std::numeric_limits<double>::quiet_NaN();
    if (!f.three_d) {
      if (has_zero) pfa = places.front()->x.psa.front() / kGravity;
      panel.series.push_back(series("floor", T, places.front()->x.psa, series_colour(0), 2.0));
      panel.series.push_back(series("ground", T, f.ground.x.psa, kGround, 1.2));
    } else {
      const PlaceSpectra& cm = *places.front();
      std::vector<double> corners(T.size(), 0.0);
      for (std::size_t k = 1; k < places.size(); ++k)
        for (std::size_t i = 0; i < T.size(); ++i)
          corners[i] = std::max(corners[i], places[k]->rotd->psa100[i]);
      if (has_zero) pfa = std::max(cm.rotd->psa100.front(), corners.front()) / kGravity;
      // Drawn in this order: the corners' wide band under the centre's RotD100.
      panel.series.push_back(series("CM, x", T, cm.x.psa, series_colour(0), 1.2));
      panel.series.push_back(series("CM, y", T, cm.y->psa, series_colour(1), 1.2));
      if (places.size() > 1)
        panel.series.push_back(series("corners, largest RotD100", T, corners, kCornersColour, 5.0));
      panel.series.push_back(series("CM, RotD100", T, cm.rotd->psa100, kCentreRotDColour, 2.0));
      panel.series.push_back(series("ground, RotD100", T, f.ground.rotd->psa100, kGround, 1.2));
    }
    panel.title = level_title(*places.front(), pfa);
    choose_axes(panel, log_period);
    panels.push_back(std::move(panel));
  }
  // Up to 3 panels side by side; 4 as 2 x 2; more in rows of 3.
  const int columns =
      panels.size() == 4 ? 2 : static_cast<int>(std::min<std::size_t>(panels.size(), 3));
  const int rows = static_cast<int>((panels.size() + columns - 1) / columns);
  char title[128];
  if (f.steps > 0)
    std::snprintf(title, sizeof title, "Floor response spectra, ξ = %g %% (every analysis step)",
                  100.0 * f.damping);
  else
    std::snprintf(title, sizeof title, "Floor response spectra, ξ = %g %% (history every %.4g s)",
                  100.0 * f.damping, f.sampling.row_interval);
  std::string heading = title;
  if (f.three_d) heading += "; CM: centre of mass";
  return xy_figure(panels, columns, 500 * columns, 60 + 360 * rows, heading, frames);
}

}  // namespace isopound::post
