// The capacity-curve figure (see plot_pushover.h).
#include "post/plot_pushover.h"

#include <cmath>
#include <cstdio>
#include <string>
#include <tuple>

namespace isopound::post {
namespace {

// "roof 3.46 cm, 9562.0 kN": as `isopound pushover` prints its points (an isolated building's
// "drift 2.84 cm, 9833.8 kN" and "bearings 73.48 cm": each panel's own coordinate).
std::string point_text(const std::string& what, double x, double base_shear) {
  char buf[96];
  if (std::isfinite(base_shear))
    std::snprintf(buf, sizeof buf, "%s %.2f cm, %.1f kN", what.c_str(), x * 100.0,
                  base_shear / 1e3);
  else
    std::snprintf(buf, sizeof buf, "%s %.2f cm", what.c_str(), x * 100.0);
  return buf;
}

std::string pattern_text(const std::string& pattern) {
  if (pattern == "first_mode") return "first-mode load pattern";
  if (pattern == "uniform") return "uniform load pattern";
  return pattern + " load pattern";
}

// The marked points: first yield, capping, the last row.
struct MarkedPoint {
  std::optional<PushoverPoint> point;
  const char* name;
  MarkerShape shape;
  Rgb fill;
  double size;
};

std::vector<MarkedPoint> marked_points(const PushoverData& d) {
  const std::size_t last = d.rows() - 1;
  return {{d.first_yield, "first yield", MarkerShape::kCircle, kFirstYieldColour, 13},
          {d.capping, "capping", MarkerShape::kDiamond, kCappingColour, 15},
          {PushoverPoint{static_cast<int>(last), d.roof_displacement()[last], 0.0,
                         d.base_shear()[last]},
           "end",
           MarkerShape::kSquare,
           {90, 90, 90},
           9}};
}

// Base shear [kN] against x [cm] (x per row, in m), the marked points on it and named in the
// legend with `what` and their x (with the base shear when `shear_in_legend`).
Panel shear_panel(const PushoverData& d, const std::string& title, const std::string& x_title,
                  const std::vector<double>& x, const std::string& curve, const std::string& what,
                  bool shear_in_legend, Rgb colour) {
  Panel p{title, x_title, "base shear [kN]", {}, true, false, true};
  p.legend_at = Panel::LegendAt::kBest;
  Series c = line_series(curve, scaled(x, 0.01), scaled(d.base_shear(), 1e3));
  c.width = 2.0;
  c.colour = colour;
  p.series.push_back(c);
  for (const MarkedPoint& m : marked_points(d)) {
    if (!m.point) continue;
    const double shear = shear_in_legend ? m.point->base_shear : std::nan("");
    Series s =
        point_series(std::string(m.name) + " (" + point_text(what, x[m.point->row], shear) + ")",
                     x[m.point->row] * 100.0, m.point->base_shear / 1e3, m.shape, m.fill);
    s.marker_size = m.size;
    p.series.push_back(s);
  }
  return p;
}

}  // namespace

Figure pushover_figure(const PushoverData& d, std::vector<PanelFrame>* frames) {
  const bool isolated = d.isolated();
  // The capacity curve's x: the roof displacement, or an isolated building's superstructure
  // drift (the bearings' deformation would put its first yield at the bearings' travel).
  const std::vector<double> x = isolated ? d.superstructure_drift() : d.roof_displacement();
  const std::vector<double> x_cm = scaled(x, 0.01);
  char drift_note[64];
  std::snprintf(drift_note, sizeof drift_note, "   (1 %% drift = %.3g cm)", d.height);
  const std::string x_title =
      (isolated ? "superstructure drift: roof relative to the base slab [cm]"
                : "roof displacement [cm]") +
      std::string(d.height > 0 ? drift_note : "");

  std::vector<Panel> panels;
  panels.push_back(
      shear_panel(d, isolated ? "Capacity curve of the superstructure" : "Capacity curve", x_title,
                  x, "capacity curve", isolated ? "drift" : "roof", true, series_colour(0)));
  if (!d.first_yield) panels.back().title += " (first yield not reached)";
  if (isolated)
    panels.push_back(shear_panel(
        d, "The bearings' share", "bearing displacement: roof less superstructure drift [cm]",
        d.bearing_displacement(), "bearings", "bearings", false, kBearingCurveColour));

  if (d.storeys > 0) {
    Panel drift{"Storey drift ratios",
                isolated ? "superstructure drift [cm]" : "roof displacement [cm]",
                "storey drift ratio [%]",
                {},
                true,
                false,
                true};
    drift.legend_at = Panel::LegendAt::kBest;
    std::vector<std::vector<double>> ratio_pct;
    for (int k = 1; k <= d.storeys; ++k) {
      ratio_pct.push_back(scaled(d.column("story" + std::to_string(k) + "_drift_ratio"), 0.01));
      drift.series.push_back(line_series("storey " + std::to_string(k), x_cm, ratio_pct.back()));
    }
    // The marked rows on every storey's curve (unlabelled: the capacity curve's legend names them).
    for (const auto& [p, shape, fill] :
         {std::tuple{d.first_yield, MarkerShape::kCircle, kFirstYieldColour},
          std::tuple{d.capping, MarkerShape::kDiamond, kCappingColour}}) {
      if (!p) continue;
      for (int k = 0; k < d.storeys; ++k) {
        Series s = point_series("", x_cm[p->row], ratio_pct[k][p->row], shape, fill);
        s.marker_size = 9;
        drift.series.push_back(s);
      }
    }
    panels.push_back(drift);
  }

  std::string title = "Pushover of " + d.building + ": " + pattern_text(d.pattern);
  if (d.dimension == 3) {
    char angle[48];
    std::snprintf(angle, sizeof angle, ", pushed at %g° from x",
                  std::round(d.angle_deg * 1e6) / 1e6);
    title += angle;
  }
  if (isolated) title += " (isolated: superstructure and bearings apart)";
  const int columns = static_cast<int>(panels.size());
  return xy_figure(panels, columns, 620 * columns, 520, title, frames);
}

}  // namespace isopound::post
