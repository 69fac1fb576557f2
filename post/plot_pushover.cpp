// The capacity-curve figure (see plot_pushover.h).
#include "post/plot_pushover.h"

#include <cmath>
#include <cstdio>
#include <string>
#include <tuple>

namespace isopound::post {
namespace {

// "roof 3.46 cm, 9562.0 kN": as `isopound pushover` prints its points.
std::string point_text(double roof_displacement, double base_shear) {
  char buf[80];
  std::snprintf(buf, sizeof buf, "roof %.2f cm, %.1f kN", roof_displacement * 100.0,
                base_shear / 1e3);
  return buf;
}

std::string pattern_text(const std::string& pattern) {
  if (pattern == "first_mode") return "first-mode load pattern";
  if (pattern == "uniform") return "uniform load pattern";
  return pattern + " load pattern";
}

}  // namespace

Figure pushover_figure(const PushoverData& d, std::vector<PanelFrame>* frames) {
  const std::vector<double> roof_cm = scaled(d.roof_displacement(), 0.01);
  char drift_note[64];
  std::snprintf(drift_note, sizeof drift_note, "   (1 %% roof drift = %.3g cm)", d.height);
  const std::string x_title =
      "roof displacement [cm]" + std::string(d.height > 0 ? drift_note : "");

  Panel curve{"Capacity curve", x_title, "base shear [kN]", {}, true, false, true};
  curve.legend_at = Panel::LegendAt::kBest;
  Series c = line_series("capacity curve", roof_cm, scaled(d.base_shear(), 1e3));
  c.width = 2.0;
  curve.series.push_back(c);
  const auto mark = [&](const std::optional<PushoverPoint>& p, const std::string& name,
                        MarkerShape shape, Rgb fill, double size) {
    if (!p) return;
    Series s = point_series(name + " (" + point_text(p->roof_displacement, p->base_shear) + ")",
                            p->roof_displacement * 100.0, p->base_shear / 1e3, shape, fill);
    s.marker_size = size;
    curve.series.push_back(s);
  };
  mark(d.first_yield, "first yield", MarkerShape::kCircle, kFirstYieldColour, 13);
  mark(d.capping, "capping", MarkerShape::kDiamond, kCappingColour, 15);
  const std::size_t last = d.rows() - 1;
  mark(
      PushoverPoint{static_cast<int>(last), d.roof_displacement()[last], 0.0, d.base_shear()[last]},
      "end", MarkerShape::kSquare, {90, 90, 90}, 9);
  if (!d.first_yield) curve.title += " (first yield not reached)";

  std::vector<Panel> panels{curve};
  if (d.storeys > 0) {
    Panel drift{"Storey drift ratios",
                "roof displacement [cm]",
                "storey drift ratio [%]",
                {},
                true,
                false,
                true};
    drift.legend_at = Panel::LegendAt::kBest;
    std::vector<std::vector<double>> ratio_pct;
    for (int k = 1; k <= d.storeys; ++k) {
      ratio_pct.push_back(scaled(d.column("story" + std::to_string(k) + "_drift_ratio"), 0.01));
      drift.series.push_back(line_series("storey " + std::to_string(k), roof_cm, ratio_pct.back()));
    }
    // The marked rows on every storey's curve (unlabelled: the capacity curve's legend names them).
    for (const auto& [p, shape, fill] :
         {std::tuple{d.first_yield, MarkerShape::kCircle, kFirstYieldColour},
          std::tuple{d.capping, MarkerShape::kDiamond, kCappingColour}}) {
      if (!p) continue;
      for (int k = 0; k < d.storeys; ++k) {
        Series s = point_series("", roof_cm[p->row], ratio_pct[k][p->row], shape, fill);
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
  const int columns = static_cast<int>(panels.size());
  return xy_figure(panels, columns, 620 * columns, 520, title, frames);
}

}  // namespace isopound::post
