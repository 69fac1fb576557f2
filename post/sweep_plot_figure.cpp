// Sweep-plot figure (see sweep_plot_figure.h): xy_figure's panel, then the bands as trapezoids
// (one per interval, convex: vertical sides, lo <= hi) under every line.
#include "post/sweep_plot_figure.h"

#include <cmath>

#include "post/study_words.h"

namespace isopound::post {

Rgb band_tint(Rgb c) {
  const auto mix = [](unsigned char v) {
    return static_cast<unsigned char>(v + (255 - v) * 3 / 4);
  };
  return {mix(c.r), mix(c.g), mix(c.b)};
}

Figure sweep_plot_figure(const SweepPlotData& d, int width, int height, PanelFrame* frame) {
  Panel panel;
  panel.title = sweep_plot_subtitle(d);
  panel.x_title = sweep_plot_x_title(d);
  panel.y_title = sweep_plot_y_title(d);
  panel.legend_at = Panel::LegendAt::kBest;
  const bool one = d.curves.size() == 1;
  // Band extents first, unlabelled and undrawn (width 0): they only widen the y range.
  struct Band {
    std::vector<double> x, lo, hi;
    Rgb colour;
  };
  std::vector<Band> bands;
  for (std::size_t k = 0; k < d.curves.size() && d.band; ++k) {
    const SweepCurve& c = d.curves[k];
    const Rgb colour = one ? Rgb{198, 214, 238} : band_tint(series_colour(static_cast<int>(k)));
    bands.push_back({c.x, c.lo, c.hi, colour});
    for (const auto* v : {&c.lo, &c.hi}) {
      Series s = line_series("", c.x, *v);
      s.colour = colour;
      s.width = 0.0;
      panel.series.push_back(std::move(s));
    }
  }
  if (d.band) {
    Series key = line_series("ens. min–max (shaded)", {}, {});
    key.colour = one ? Rgb{160, 185, 225} : band_tint(series_colour(0));
    panel.series.push_back(std::move(key));
  }
  for (std::size_t k = 0; k < d.curves.size(); ++k) {
    const SweepCurve& c = d.curves[k];
    const Rgb colour = series_colour(static_cast<int>(k));
    const bool markers = c.x.size() <= 25;  // a few points: show where the runs are
    if (one && d.band) {
      // Polar's convention for one curve: member 0 (the model as given) thin, the mean thick.
      bool member0 = false;
      for (double v : c.member0) member0 = member0 || std::isfinite(v);
      if (member0) {
        Series m = line_series("member 0 (as given)", c.x, c.member0);
        m.colour = colour;
        m.width = 1.2;
        panel.series.push_back(std::move(m));
      }
      Series s = line_series("ens. mean", c.x, c.y);
      s.colour = Rgb{0, 0, 0};
      s.width = 2.5;
      panel.series.push_back(std::move(s));
      continue;
    }
    const std::string words = output_words(d.output_selector);
    Series s =
        line_series(c.label.empty() ? (words.empty() ? d.output : words) : c.label, c.x, c.y);
    s.colour = colour;
    s.width = 2.0;
    if (markers) {
      s.marker = MarkerShape::kCircle;
      s.marker_size = 7.0;
      s.marker_edge = colour;
    }
    panel.series.push_back(std::move(s));
  }
  std::vector<PanelFrame> frames;
  Figure fig = xy_figure({panel}, 1, width, height, sweep_plot_title(d), &frames);
  const PanelFrame& f = frames.front();
  for (const Band& b : bands)
    for (std::size_t i = 0; i + 1 < b.x.size(); ++i) {
      if (!std::isfinite(b.lo[i]) || !std::isfinite(b.hi[i]) || !std::isfinite(b.lo[i + 1]) ||
          !std::isfinite(b.hi[i + 1]))
        continue;
      fig.polygons.push_back({{f.to_pixel(b.x[i], b.lo[i]), f.to_pixel(b.x[i + 1], b.lo[i + 1]),
                               f.to_pixel(b.x[i + 1], b.hi[i + 1]), f.to_pixel(b.x[i], b.hi[i])},
                              b.colour});
    }
  if (frame) *frame = f;
  return fig;
}

}  // namespace isopound::post
