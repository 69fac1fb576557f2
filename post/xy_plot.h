// Line charts laid out as a Figure: one or more panels of x-y series, with ticks, grid, axis
// titles (with units) and a legend. Data in any units; the mapping to pixels is linear.
#pragma once

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "post/figure.h"

namespace isopound::post {

// The shape drawn at every point of a series with markers.
enum class MarkerShape { kNone, kCircle, kSquare, kDiamond, kTriangle };

struct Series {
  std::string label;  // legend text ("" = not in the legend)
  std::vector<double> x, y;
  std::optional<Rgb> colour;  // default: series_colour(index in the panel); markers' fill too
  double width = 1.5;         // px; 0: no line (markers only)
  MarkerShape marker = MarkerShape::kNone;
  double marker_size = 12.0;  // px across
  Rgb marker_edge{0, 0, 0};   // the markers' outline
};

// A series in the default colour and width.
inline Series line_series(std::string label, std::vector<double> x, std::vector<double> y) {
  Series s;
  s.label = std::move(label);
  s.x = std::move(x);
  s.y = std::move(y);
  return s;
}

// One point drawn as a marker (no line), e.g. a marked point of a curve.
inline Series point_series(std::string label, double x, double y, MarkerShape shape, Rgb fill) {
  Series s;
  s.label = std::move(label);
  s.x = {x};
  s.y = {y};
  s.colour = fill;
  s.width = 0.0;
  s.marker = shape;
  return s;
}

// The outline of a marker of `shape`, `size` px across, centred on `at` (empty for kNone).
std::vector<Point2> marker_outline(MarkerShape shape, Point2 at, double size);

// Every value of v divided by divisor (a change of unit for a series).
std::vector<double> scaled(const std::vector<double>& v, double divisor);
// The largest |value| of v (0 for an empty series).
double peak_of(const std::vector<double>& v);

// A point marked on a panel with its own text beside it, e.g. a curve's true peak taken from
// elsewhere than the drawn samples: a diamond of `colour` (black outline) and the text in black.
struct Mark {
  double x = 0.0, y = 0.0;  // data units of the panel
  // Drawn beside the marker where it is clear of the legend, the other marks' texts and markers
  // and the frame: right of it, else left, else shifted up or down (PanelFrame::label_boxes).
  std::string text;
  Rgb colour{0, 0, 0};
  double size = 11.0;  // px across
};

struct Panel {
  std::string title;
  std::string x_title, y_title;  // with units, e.g. "time [s]"
  std::vector<Series> series;
  bool legend = true;
  bool symmetric_y = false;  // y range symmetric about 0 (time histories)
  bool y_from_zero = false;  // y range includes 0 (spectra)
  bool equal_axes = false;   // one data unit is as long in x as in y (plans, orbits)
  // Where the legend goes: top right, bottom right, or whichever of the two the data cross less.
  enum class LegendAt { kTopRight, kBottomRight, kBest };
  LegendAt legend_at = LegendAt::kTopRight;
  // The y range raised so that the data stay below a legend at the top right (time histories:
  // no curve under the legend's text), at most doubled.
  bool legend_above_data = false;
  // Logarithmic axes: decades with log_ticks; values <= 0 are not drawn (nor symmetric_y,
  // y_from_zero, equal_axes on that axis).
  bool log_x = false, log_y = false;
  std::vector<Mark> marks{};  // inside the data range; drawn above the series
};

// A rectangle on the figure, px: [x0, x1] x [y0, y1].
struct Box {
  double x0 = 0, y0 = 0, x1 = 0, y1 = 0;
  bool empty() const { return !(x1 > x0 && y1 > y0); }
  // The area both cover (0 when they do not overlap).
  double overlap(const Box& o) const {
    return std::max(0.0, std::min(x1, o.x1) - std::max(x0, o.x0)) *
           std::max(0.0, std::min(y1, o.y1) - std::max(y0, o.y0));
  }
};

// Where a panel's data lands on the figure (for tests and overlays).
struct PanelFrame {
  double left = 0, bottom = 0, width = 0, height = 0;  // plot area, px
  double x_lo = 0, x_hi = 1, y_lo = 0, y_hi = 1;       // data range shown (log10 on a log axis)
  bool log_x = false, log_y = false;
  // Where the legend and each Mark's text were placed (estimated extents of their text, 6.5 px
  // per character at 11 pt): legend_box empty without a legend; label_boxes in panel.marks'
  // order, empty boxes for marks without text or outside the range.
  Box legend_box;
  std::vector<Box> label_boxes;
  Point2 to_pixel(double x, double y) const {
    if (log_x) x = std::log10(x);
    if (log_y) y = std::log10(y);
    return {left + (x - x_lo) / (x_hi - x_lo) * width,
            bottom + (y - y_lo) / (y_hi - y_lo) * height};
  }
};

// Panels in a grid of `columns` columns, row by row from the top, under an optional title.
Figure xy_figure(const std::vector<Panel>& panels, int columns, int width, int height,
                 const std::string& title = "", std::vector<PanelFrame>* frames = nullptr);

// One more panel drawn into the cell [x0, x0 + w] x [y0, y0 + h] px of a figure (cell as
// xy_figure's: margins for ticks and titles inside it), e.g. an inset beside a larger panel or
// a layout of unequal cells; returns where its data lands.
PanelFrame add_panel(Figure& fig, const Panel& panel, double x0, double y0, double w, double h);

}  // namespace isopound::post
