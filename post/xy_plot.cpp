// Line-chart layout (see xy_plot.h).
#include "post/xy_plot.h"

#include <algorithm>
#include <cmath>
#include <limits>

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

namespace {

constexpr Rgb kBlack{0, 0, 0};
constexpr Rgb kGrid{225, 225, 225};
constexpr Rgb kFrame{60, 60, 60};

void range_of(const Panel& panel, double& x_lo, double& x_hi, double& y_lo, double& y_hi) {
  constexpr double inf = std::numeric_limits<double>::infinity();
  x_lo = y_lo = inf;
  x_hi = y_hi = -inf;
  for (const Series& s : panel.series)
    for (std::size_t i = 0; i < s.x.size() && i < s.y.size(); ++i) {
      if (!std::isfinite(s.x[i]) || !std::isfinite(s.y[i])) continue;
      x_lo = std::min(x_lo, s.x[i]);
      x_hi = std::max(x_hi, s.x[i]);
      y_lo = std::min(y_lo, s.y[i]);
      y_hi = std::max(y_hi, s.y[i]);
    }
  if (!(x_lo <= x_hi)) x_lo = 0, x_hi = 1;
  if (!(y_lo <= y_hi)) y_lo = 0, y_hi = 1;
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

void draw_panel(const Panel& panel, double x0, double y0, double w, double h, Figure& fig,
                PanelFrame& frame) {
  // Margins inside the panel cell for tick labels and titles.
  const double ml = 78, mr = 14, mb = 48, mt = panel.title.empty() ? 12 : 30;
  frame.left = x0 + ml;
  frame.bottom = y0 + mb;
  frame.width = std::max(10.0, w - ml - mr);
  frame.height = std::max(10.0, h - mb - mt);
  range_of(panel, frame.x_lo, frame.x_hi, frame.y_lo, frame.y_hi);
  if (panel.equal_axes) {
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

  for (double t : nice_ticks(frame.x_lo, frame.x_hi, 7)) {
    const double px = frame.to_pixel(t, 0).x;
    fig.lines.push_back({{{px, B}, {px, T}}, kGrid, 1.0});
    fig.lines.push_back({{{px, B}, {px, B - 5}}, kFrame, 1.0});
    fig.texts.push_back({{px, B - 8}, tick_label(t), 11, kBlack, HAlign::kCentre, VAlign::kTop});
  }
  for (double t : nice_ticks(frame.y_lo, frame.y_hi, 5)) {
    const double py = frame.to_pixel(0, t).y;
    fig.lines.push_back({{{L, py}, {R, py}}, kGrid, 1.0});
    fig.lines.push_back({{{L - 5, py}, {L, py}}, kFrame, 1.0});
    fig.texts.push_back({{L - 8, py}, tick_label(t), 11, kBlack, HAlign::kRight, VAlign::kCentre});
  }
  if (frame.y_lo < 0 && frame.y_hi > 0) {
    const double py = frame.to_pixel(0, 0).y;
    fig.lines.push_back({{{L, py}, {R, py}}, {150, 150, 150}, 1.0});
  }
  int index = 0;
  for (const Series& s : panel.series) {
    Polyline line;
    line.colour = s.colour.value_or(series_colour(index));
    line.width = s.width;
    for (std::size_t i = 0; i < s.x.size() && i < s.y.size(); ++i) {
      if (!std::isfinite(s.x[i]) || !std::isfinite(s.y[i])) continue;
      line.points.push_back(frame.to_pixel(s.x[i], s.y[i]));
    }
    fig.lines.push_back(std::move(line));
    ++index;
  }
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
  if (panel.legend) {
    // Wide enough for the longest label (about 6.5 px per character at 11 pt, UTF-8 counted
    // by code points), at most half the plot.
    std::size_t longest = 0;
    for (const Series& s : panel.series) {
      std::size_t n = 0;
      for (unsigned char ch : s.label) n += (ch & 0xC0) != 0x80;
      longest = std::max(longest, n);
    }
    const double width = std::min(std::max(150.0, 36.0 + 6.5 * longest), 0.5 * frame.width);
    double y = T - 14;
    index = 0;
    for (const Series& s : panel.series) {
      const Rgb c = s.colour.value_or(series_colour(index++));
      if (s.label.empty()) continue;
      fig.lines.push_back({{{R - width, y}, {R - width + 24, y}}, c, 2.5});
      fig.texts.push_back(
          {{R - width + 30, y}, s.label, 11, kBlack, HAlign::kLeft, VAlign::kCentre});
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

}  // namespace isopound::post
