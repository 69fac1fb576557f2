// Line-chart layout (see xy_plot.h).
#include "post/xy_plot.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>

namespace isopound::post {

std::vector<double> scaled(const std::vector<double>& v, double divisor) {
  std::vector<double> out(v.size());
  for (std::size_t i = 0; i < v.size(); ++i) out[i] = v[i] / divisor;
  return out;
}

double peak_of(const std::vector<double>& v) {
  double m = 0.0;
  for (double x : v) m = std::max(m, std::abs(x));
  return m;
}

std::vector<Point2> marker_outline(MarkerShape shape, Point2 at, double size) {
  const double h = 0.5 * size;
  switch (shape) {
    case MarkerShape::kNone:
      return {};
    case MarkerShape::kSquare:
      return {
          {at.x - h, at.y - h}, {at.x + h, at.y - h}, {at.x + h, at.y + h}, {at.x - h, at.y + h}};
    case MarkerShape::kDiamond:
      return {{at.x, at.y - h}, {at.x + h, at.y}, {at.x, at.y + h}, {at.x - h, at.y}};
    case MarkerShape::kTriangle:  // pointing up, centred on its centroid
      return {{at.x - h, at.y - h / std::sqrt(3.0)},
              {at.x + h, at.y - h / std::sqrt(3.0)},
              {at.x, at.y + 2 * h / std::sqrt(3.0)}};
    case MarkerShape::kCircle:
      break;
  }
  std::vector<Point2> circle;
  constexpr int kSides = 20;
  for (int k = 0; k < kSides; ++k) {
    const double a = 2.0 * std::numbers::pi * k / kSides;
    circle.push_back({at.x + h * std::cos(a), at.y + h * std::sin(a)});
  }
  return circle;
}

namespace {

constexpr Rgb kBlack{0, 0, 0};
constexpr Rgb kGrid{225, 225, 225};
constexpr Rgb kFrame{60, 60, 60};

// A value on an axis as laid out: log10 on a log axis (NaN for values <= 0: not drawn).
double axis_value(double v, bool log) {
  if (!log) return v;
  return v > 0.0 ? std::log10(v) : std::numeric_limits<double>::quiet_NaN();
}

void range_of(const Panel& panel, double& x_lo, double& x_hi, double& y_lo, double& y_hi) {
  constexpr double inf = std::numeric_limits<double>::infinity();
  x_lo = y_lo = inf;
  x_hi = y_hi = -inf;
  const auto take = [&](double x, double y) {
    x = axis_value(x, panel.log_x), y = axis_value(y, panel.log_y);
    if (!std::isfinite(x) || !std::isfinite(y)) return;
    x_lo = std::min(x_lo, x);
    x_hi = std::max(x_hi, x);
    y_lo = std::min(y_lo, y);
    y_hi = std::max(y_hi, y);
  };
  for (const Series& s : panel.series)
    for (std::size_t i = 0; i < s.x.size() && i < s.y.size(); ++i) take(s.x[i], s.y[i]);
  for (const Mark& m : panel.marks) take(m.x, m.y);
  if (!(x_lo <= x_hi)) x_lo = 0, x_hi = 1;
  if (!(y_lo <= y_hi)) y_lo = 0, y_hi = 1;
  if (panel.log_y) {
    if (y_hi == y_lo) y_lo -= 0.5, y_hi += 0.5;
    const double pad = 0.05 * (y_hi - y_lo);  // as below, in decades
    y_lo -= pad;
    y_hi += pad;
    if (x_hi == x_lo) x_lo -= 0.5, x_hi += 0.5;
    return;
  }
  if (panel.symmetric_y) {
    const double m = std::max(std::abs(y_lo), std::abs(y_hi));
    y_lo = -m;
    y_hi = m;
  }
  if (panel.y_from_zero) {
    y_lo = std::min(y_lo, 0.0);
    y_hi = std::max(y_hi, 0.0);
  }
  if (x_hi == x_lo) x_lo -= 0.5, x_hi += 0.5;
  if (y_hi == y_lo) {
    const double d = y_lo == 0.0 ? 1.0 : 0.1 * std::abs(y_lo);
    y_lo -= d;
    y_hi += d;
  }
  // 5 % headroom in y so that peaks do not touch the frame.
  const double pad = 0.05 * (y_hi - y_lo);
  if (!(panel.y_from_zero && y_lo == 0.0)) y_lo -= pad;
  y_hi += pad;
}

// A panel's data as drawn: fig.lines[line_begin, line_end) and fig.markers[marker_begin, end).
struct DrawnData {
  std::size_t line_begin = 0, line_end = 0, marker_begin = 0;
};

// How much of the data falls in the box [x0, x1] x [y0, y1] px: line samples every 2 px and
// marker centres (weighted: a marker hidden by the legend is worse than a stretch of line).
int data_in_box(const Figure& fig, const DrawnData& data, double x0, double y0, double x1,
                double y1) {
  const auto inside = [&](Point2 p) { return p.x >= x0 && p.x <= x1 && p.y >= y0 && p.y <= y1; };
  int n = 0;
  for (std::size_t k = data.line_begin; k < data.line_end; ++k) {
    const std::vector<Point2>& pts = fig.lines[k].points;
    for (std::size_t i = 0; i + 1 < pts.size(); ++i) {
      const double len = std::hypot(pts[i + 1].x - pts[i].x, pts[i + 1].y - pts[i].y);
      const int m = std::max(1, static_cast<int>(std::ceil(len / 2.0)));
      for (int j = 0; j < m; ++j) {
        const double f = static_cast<double>(j) / m;
        n += inside(
            {pts[i].x + f * (pts[i + 1].x - pts[i].x), pts[i].y + f * (pts[i + 1].y - pts[i].y)});
      }
    }
    if (pts.size() == 1) n += inside(pts[0]);
  }
  for (std::size_t k = data.marker_begin; k < fig.markers.size(); ++k) {
    Point2 c;
    for (const Point2& p : fig.markers[k].points) c.x += p.x, c.y += p.y;
    const double count = static_cast<double>(fig.markers[k].points.size());
    n += 20 * inside({c.x / count, c.y / count});
  }
  return n;
}

// Text extents as estimated for layout: about 6.5 px per character at 11 pt (UTF-8 counted by
// code points), 14 px high.
constexpr double kCharWidth = 6.5, kLineHeight = 14.0;
std::size_t code_points(const std::string& s) {
  std::size_t n = 0;
  for (unsigned char ch : s) n += (ch & 0xC0) != 0x80;
  return n;
}

// A legend's width (px: wide enough for the longest label, inside the plot), its longest label
// (characters) and its number of entries (0 without a legend).
struct LegendSize {
  double width = 0.0;
  std::size_t longest = 0;
  int entries = 0;
};
LegendSize legend_size(const Panel& panel, const PanelFrame& frame) {
  LegendSize size;
  for (const Series& s : panel.series) {
    size.longest = std::max(size.longest, code_points(s.label));
    size.entries += panel.legend && !s.label.empty();
  }
  size.width = std::min(std::max(150.0, 36.0 + kCharWidth * size.longest), frame.width - 4.0);
  return size;
}

// Panel::legend_above_data: the top of the y range raised (the range at most doubled) until the
// data (points and marks) under a top-right legend's span of x lie below its box.
void raise_above_legend(const Panel& panel, PanelFrame& frame) {
  const LegendSize legend = legend_size(panel, frame);
  if (legend.entries == 0) return;
  const double per_px_x = (frame.x_hi - frame.x_lo) / frame.width,
               per_px_y = (frame.y_hi - frame.y_lo) / frame.height;
  const double x_from = frame.x_hi - (legend.width + 4.0) * per_px_x;
  double top = -std::numeric_limits<double>::infinity();
  for (const Series& s : panel.series)
    for (std::size_t i = 0; i < s.x.size() && i < s.y.size(); ++i)
      if (s.x[i] >= x_from && std::isfinite(s.y[i])) top = std::max(top, s.y[i]);
  for (const Mark& m : panel.marks)
    if (m.x + 0.5 * m.size * per_px_x >= x_from) top = std::max(top, m.y + 0.5 * m.size * per_px_y);
  // The legend's box reaches 16 px per entry + 10 px below the top; 4 px more to the data.
  const double band = std::min(0.5, (16.0 * legend.entries + 14.0) / frame.height);
  if (top - frame.y_lo > (1.0 - band) * (frame.y_hi - frame.y_lo))
    frame.y_hi = frame.y_lo + (top - frame.y_lo) / (1.0 - band);
}

// Each Mark's diamond, and its text where it is clear: candidate places beside the marker (right,
// left, then also centred, on its level, then 1, 2, ... lines below and above) scored by how much
// of the text box lies on the legend, on texts already placed, on the marks' diamonds or outside
// the plot area; the first clear one, else the least covered.
void place_marks(const Panel& panel, PanelFrame& frame, Figure& fig) {
  const Box plot{frame.left, frame.bottom, frame.left + frame.width, frame.bottom + frame.height};
  std::vector<std::optional<Point2>> at;
  std::vector<Box> diamonds;
  for (const Mark& m : panel.marks) {
    const bool drawn =
        std::isfinite(axis_value(m.x, panel.log_x)) && std::isfinite(axis_value(m.y, panel.log_y));
    at.push_back(drawn ? std::optional(frame.to_pixel(m.x, m.y)) : std::nullopt);
    const double h = 0.5 * m.size;
    diamonds.push_back(
        drawn ? Box{at.back()->x - h, at.back()->y - h, at.back()->x + h, at.back()->y + h}
              : Box{});
    if (drawn)
      fig.markers.push_back(
          {marker_outline(MarkerShape::kDiamond, *at.back(), m.size), m.colour, kBlack, 1.0});
  }
  frame.label_boxes.assign(panel.marks.size(), Box{});
  for (std::size_t k = 0; k < panel.marks.size(); ++k) {
    const Mark& m = panel.marks[k];
    if (!at[k] || m.text.empty()) continue;
    const Point2 p = *at[k];
    const double w = kCharWidth * static_cast<double>(code_points(m.text));
    const auto covered = [&](const Box& b) {
      double c = b.overlap(frame.legend_box);
      c += (b.x1 - b.x0) * (b.y1 - b.y0) - b.overlap(plot);
      for (std::size_t j = 0; j < panel.marks.size(); ++j)
        c += frame.label_boxes[j].overlap(b) + diamonds[j].overlap(b);
      return c;
    };
    // A candidate moved down or up into the plot area where it sticks out (a peak near the top).
    const auto inside = [&](Box b) {
      const double dy = std::max(0.0, plot.y0 - b.y0) - std::max(0.0, b.y1 - plot.y1);
      return Box{b.x0, b.y0 + dy, b.x1, b.y1 + dy};
    };
    Box best;
    double best_cover = std::numeric_limits<double>::infinity();
    const int steps = 2 * static_cast<int>(frame.height / 16.0);  // every line of the plot
    for (int step = 0; step <= steps && best_cover > 0.0; ++step) {
      // 0, -1, +1, -2, +2, ... lines (16 px) below or above the marker: right of it, left of it,
      // or centred under or over it.
      const double yc = p.y + 16.0 * ((step + 1) / 2) * (step % 2 ? -1.0 : 1.0);
      const double y0 = yc - 0.5 * kLineHeight, y1 = yc + 0.5 * kLineHeight;
      for (const Box b : {inside({p.x + m.size, y0, p.x + m.size + w, y1}),
                          inside({p.x - m.size - w, y0, p.x - m.size, y1}),
                          inside({p.x - 0.5 * w, y0, p.x + 0.5 * w, y1})}) {
        const double c = covered(b);
        if (c < best_cover) best = b, best_cover = c;
        if (c <= 0.0) break;
      }
    }
    frame.label_boxes[k] = best;
    // A text away from its marker gets a thin leader to it.
    const Point2 near{std::clamp(p.x, best.x0 - 2, best.x1 + 2),
                      std::clamp(p.y, best.y0 - 1, best.y1 + 1)};
    if (std::hypot(near.x - p.x, near.y - p.y) > 15.0)
      fig.lines.push_back({{p, near}, Rgb{110, 110, 110}, 0.8});
    fig.texts.push_back(
        {{best.x0, 0.5 * (best.y0 + best.y1)}, m.text, 11, kBlack, HAlign::kLeft, VAlign::kCentre});
  }
}

void draw_panel(const Panel& panel, double x0, double y0, double w, double h, Figure& fig,
                PanelFrame& frame) {
  // Margins inside the panel cell for tick labels and titles.
  const double ml = 78, mr = 14, mb = 48, mt = panel.title.empty() ? 12 : 30;
  frame.left = x0 + ml;
  frame.bottom = y0 + mb;
  frame.width = std::max(10.0, w - ml - mr);
  frame.height = std::max(10.0, h - mb - mt);
  range_of(panel, frame.x_lo, frame.x_hi, frame.y_lo, frame.y_hi);
  frame.log_x = panel.log_x;
  frame.log_y = panel.log_y;
  if (panel.equal_axes && !panel.log_x && !panel.log_y) {
    // Widen the range that has fewer pixels per unit, about its centre.
    const double per_x = (frame.x_hi - frame.x_lo) / frame.width;
    const double per_y = (frame.y_hi - frame.y_lo) / frame.height;
    if (per_x > per_y) {
      const double c = 0.5 * (frame.y_lo + frame.y_hi), half = 0.5 * per_x * frame.height;
      frame.y_lo = c - half, frame.y_hi = c + half;
    } else {
      const double c = 0.5 * (frame.x_lo + frame.x_hi), half = 0.5 * per_y * frame.width;
      frame.x_lo = c - half, frame.x_hi = c + half;
    }
  }
  const double L = frame.left, B = frame.bottom, R = L + frame.width, T = B + frame.height;
  if (panel.legend && panel.legend_above_data && !panel.log_x && !panel.log_y)
    raise_above_legend(panel, frame);

  const auto ticks = [](double lo, double hi, bool log, int target) {
    return log ? log_ticks(std::pow(10.0, lo), std::pow(10.0, hi)) : nice_ticks(lo, hi, target);
  };
  for (double t : ticks(frame.x_lo, frame.x_hi, panel.log_x, 7)) {
    const double px = frame.to_pixel(t, 1).x;
    fig.lines.push_back({{{px, B}, {px, T}}, kGrid, 1.0});
    fig.lines.push_back({{{px, B}, {px, B - 5}}, kFrame, 1.0});
    fig.texts.push_back({{px, B - 8}, tick_label(t), 11, kBlack, HAlign::kCentre, VAlign::kTop});
  }
  for (double t : ticks(frame.y_lo, frame.y_hi, panel.log_y, 5)) {
    const double py = frame.to_pixel(1, t).y;
    fig.lines.push_back({{{L, py}, {R, py}}, kGrid, 1.0});
    fig.lines.push_back({{{L - 5, py}, {L, py}}, kFrame, 1.0});
    fig.texts.push_back({{L - 8, py}, tick_label(t), 11, kBlack, HAlign::kRight, VAlign::kCentre});
  }
  if (!panel.log_y && frame.y_lo < 0 && frame.y_hi > 0) {
    const double py = frame.to_pixel(1, 0).y;
    fig.lines.push_back({{{L, py}, {R, py}}, {150, 150, 150}, 1.0});
  }
  DrawnData drawn{fig.lines.size(), 0, fig.markers.size()};
  int index = 0;
  for (const Series& s : panel.series) {
    Polyline line;
    line.colour = s.colour.value_or(series_colour(index));
    line.width = s.width;
    for (std::size_t i = 0; i < s.x.size() && i < s.y.size(); ++i) {
      if (!std::isfinite(axis_value(s.x[i], panel.log_x)) ||
          !std::isfinite(axis_value(s.y[i], panel.log_y)))
        continue;
      line.points.push_back(frame.to_pixel(s.x[i], s.y[i]));
    }
    if (s.marker != MarkerShape::kNone)
      for (const Point2& p : line.points)
        fig.markers.push_back(
            {marker_outline(s.marker, p, s.marker_size), line.colour, s.marker_edge, 1.0});
    if (s.width > 0.0) fig.lines.push_back(std::move(line));
    ++index;
  }
  drawn.line_end = fig.lines.size();

  // The legend's place first (the marks' texts keep clear of it).
  const auto [legend_w, longest, entries] = legend_size(panel, frame);
  const double top_y = T - 14, bottom_y = B + 14 + 16.0 * std::max(0, entries - 1);
  double legend_y = top_y;
  if (panel.legend_at == Panel::LegendAt::kBottomRight) legend_y = bottom_y;
  if (panel.legend_at == Panel::LegendAt::kBest && entries > 0 &&
      data_in_box(fig, drawn, R - legend_w - 4, top_y - 16.0 * (entries - 1) - 8, R, top_y + 8) >
          data_in_box(fig, drawn, R - legend_w - 4, B + 6, R, bottom_y + 8))
    legend_y = bottom_y;
  if (entries > 0)
    frame.legend_box = {R - legend_w - 4, legend_y - 16.0 * (entries - 1) - 8,
                        std::max(R, R - legend_w + 30 + kCharWidth * longest), legend_y + 8};

  place_marks(panel, frame, fig);

  fig.lines.push_back({{{L, B}, {R, B}, {R, T}, {L, T}, {L, B}}, kFrame, 1.0});
  fig.texts.push_back(
      {{(L + R) / 2, y0 + 4}, panel.x_title, 12, kBlack, HAlign::kCentre, VAlign::kBottom});
  fig.texts.push_back(
      {{x0 + 14, (B + T) / 2}, panel.y_title, 12, kBlack, HAlign::kCentre, VAlign::kCentre, 90.0});
  if (!panel.title.empty())
    fig.texts.push_back({{(L + R) / 2, T + 6},
                         panel.title,
                         13,
                         kBlack,
                         HAlign::kCentre,
                         VAlign::kBottom,
                         0.0,
                         true});
  if (entries > 0) {
    double y = legend_y;
    index = 0;
    for (const Series& s : panel.series) {
      const Rgb c = s.colour.value_or(series_colour(index++));
      if (s.label.empty()) continue;
      if (s.width > 0.0) fig.lines.push_back({{{R - legend_w, y}, {R - legend_w + 24, y}}, c, 2.5});
      if (s.marker != MarkerShape::kNone)
        fig.markers.push_back(
            {marker_outline(s.marker, {R - legend_w + 12, y}, std::min(s.marker_size, 11.0)), c,
             s.marker_edge, 1.0});
      fig.texts.push_back(
          {{R - legend_w + 30, y}, s.label, 11, kBlack, HAlign::kLeft, VAlign::kCentre});
      y -= 16;
    }
  }
}

}  // namespace

Figure xy_figure(const std::vector<Panel>& panels, int columns, int width, int height,
                 const std::string& title, std::vector<PanelFrame>* frames) {
  Figure fig;
  fig.width = width;
  fig.height = height;
  columns = std::max(1, columns);
  const int rows = static_cast<int>((panels.size() + columns - 1) / columns);
  const double top = title.empty() ? 0.0 : 34.0;
  const double cell_w = static_cast<double>(width) / columns;
  const double cell_h = (height - top) / std::max(1, rows);
  if (!title.empty())
    fig.texts.push_back(
        {{width / 2.0, height - 8.0}, title, 15, kBlack, HAlign::kCentre, VAlign::kTop, 0.0, true});
  if (frames) frames->assign(panels.size(), {});
  for (std::size_t i = 0; i < panels.size(); ++i) {
    const int r = static_cast<int>(i) / columns, c = static_cast<int>(i) % columns;
    PanelFrame frame;
    draw_panel(panels[i], c * cell_w, height - top - (r + 1) * cell_h, cell_w, cell_h, fig, frame);
    if (frames) (*frames)[i] = frame;
  }
  return fig;
}

PanelFrame add_panel(Figure& fig, const Panel& panel, double x0, double y0, double w, double h) {
  PanelFrame frame;
  draw_panel(panel, x0, y0, w, h, fig, frame);
  return frame;
}

}  // namespace isopound::post
