// Polar envelope and contour layout (see polar_plot.h).
#include "post/polar_plot.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

namespace isopound::post {
namespace {

constexpr Rgb kBlack{0, 0, 0};
constexpr Rgb kGrid{210, 210, 210};
constexpr double kDeg = std::numbers::pi / 180.0;

// Circles at the radial ticks, spokes and labels every 30 deg, radial tick labels along 0 deg...
// placed on the 15 deg ray so they do not sit on a spoke.
void draw_polar_axes(const PolarFrame& f, const std::vector<double>& r_ticks,
                     const std::string& radial_title, Figure& fig) {
  for (double r : r_ticks) {
    if (r <= f.r_lo) continue;
    Polyline circle{{}, kGrid, 1.0};
    for (int d = 0; d <= 360; d += 3) circle.points.push_back(f.to_pixel(d, r));
    fig.lines.push_back(circle);
    const Point2 at = f.to_pixel(15.0, r);
    fig.texts.push_back(
        {{at.x + 3, at.y}, tick_label(r), 10, {90, 90, 90}, HAlign::kLeft, VAlign::kBottom});
  }
  Polyline outer{{}, {80, 80, 80}, 1.2};
  for (int d = 0; d <= 360; d += 2) outer.points.push_back(f.to_pixel(d, f.r_hi));
  fig.lines.push_back(outer);
  for (int d = 0; d < 360; d += 30) {
    fig.lines.push_back({{f.to_pixel(d, f.r_lo), f.to_pixel(d, f.r_hi)}, kGrid, 1.0});
    const double a = d * kDeg, off = f.radius_px + 18;
    fig.texts.push_back({{f.centre.x + off * std::cos(a), f.centre.y + off * std::sin(a)},
                         std::to_string(d) + "°",
                         12,
                         kBlack,
                         HAlign::kCentre,
                         VAlign::kCentre});
  }
  // The radial ticks' unit just outside the circle, past their labels on the 15 deg ray; the
  // whole radial title (in words, long) in the bottom-left corner, clear of the angle labels.
  const std::size_t open = radial_title.rfind('[');
  const bool unit =
      open != std::string::npos && !radial_title.empty() && radial_title.back() == ']';
  const Point2 at = f.to_pixel(8.0, f.r_hi);
  fig.texts.push_back({{at.x + 14, at.y - 4},
                       unit ? radial_title.substr(open) : radial_title,
                       12,
                       kBlack,
                       HAlign::kLeft,
                       VAlign::kBottom});
  if (unit)
    fig.texts.push_back(
        {{12, 10}, "radius: " + radial_title, 12, kBlack, HAlign::kLeft, VAlign::kBottom});
}

void draw_note(const std::string& note, Figure& fig) {
  if (!note.empty())
    fig.texts.push_back(
        {{fig.width - 12.0, 10}, note, 10, {110, 110, 110}, HAlign::kRight, VAlign::kBottom});
}

std::vector<Point2> curve_points(const PolarFrame& f, const std::vector<double>& angle,
                                 const std::vector<double>& value) {
  std::vector<Point2> pts;
  for (std::size_t i = 0; i < angle.size() && i < value.size(); ++i)
    if (std::isfinite(value[i])) pts.push_back(f.to_pixel(angle[i], value[i]));
  // Close the curve when the angles cover the circle (last step back to the first angle).
  if (angle.size() > 2 && !pts.empty()) {
    const double step = angle[1] - angle[0];
    if (angle.back() + step >= angle.front() + 360.0 - 1e-6 * std::abs(step))
      pts.push_back(pts.front());
  }
  return pts;
}

// Cell edges: half-way between values, half a step beyond the ends.
std::vector<double> edges_of(const std::vector<double>& v) {
  std::vector<double> e(v.size() + 1);
  if (v.size() == 1) return {v[0] - 0.5, v[0] + 0.5};
  for (std::size_t i = 1; i < v.size(); ++i) e[i] = 0.5 * (v[i - 1] + v[i]);
  e.front() = v.front() - (e[1] - v.front());
  e.back() = v.back() + (v.back() - e[v.size() - 1]);
  return e;
}

}  // namespace

Point2 PolarFrame::to_pixel(double angle_deg, double r) const {
  const double s = std::clamp((r - r_lo) / (r_hi - r_lo), 0.0, 1.0) * radius_px;
  return {centre.x + s * std::cos(angle_deg * kDeg), centre.y + s * std::sin(angle_deg * kDeg)};
}

Figure polar_envelope_figure(const PolarEnvelopeData& data, int width, int height,
                             PolarFrame* frame_out) {
  Figure fig;
  fig.width = width;
  fig.height = height;
  double vmax = 0.0;
  const auto grow = [&](const std::vector<double>& v) {
    for (double x : v)
      if (std::isfinite(x)) vmax = std::max(vmax, x);
  };
  for (const PolarCurve& c : data.curves) grow(c.value);
  if (data.mean) grow(data.mean->value);
  grow(data.band_hi);
  for (const PolarBand& b : data.bands) grow(b.hi);
  if (!(vmax > 0.0)) vmax = 1.0;
  std::vector<double> ticks = nice_ticks(0.0, vmax, 4);
  const double step = ticks.size() > 1 ? ticks[1] - ticks[0] : vmax;
  while (ticks.back() < vmax * (1 - 1e-12)) ticks.push_back(ticks.back() + step);

  PolarFrame f;
  const double legend_h = 18.0 * (data.curves.size() + (data.mean ? 1 : 0) + 1);
  const double top = 46, bottom = std::max(40.0, legend_h * 0 + 40);
  f.radius_px = std::min((width - 120) / 2.0, (height - top - bottom - 40) / 2.0);
  f.centre = {width / 2.0 - 60, bottom + 20 + f.radius_px};
  f.r_lo = 0.0;
  f.r_hi = ticks.back();
  if (f.centre.x - f.radius_px < 40) f.centre.x = f.radius_px + 40;

  // Bands: quads between lo and hi at neighbouring angles, subdivided in angle so the polygons
  // follow the circle (each piece is convex at these small steps); closed when the angles cover
  // the circle (last angle + step = first angle + 360).
  const auto shade = [&](std::vector<double> angle, std::vector<double> lo, std::vector<double> hi,
                         Rgb colour) {
    const std::size_t n = std::min({angle.size(), lo.size(), hi.size()});
    if (n > 2 && std::abs(angle[n - 1] + (angle[1] - angle[0]) - (angle[0] + 360.0)) <
                     1e-6 * std::abs(angle[1] - angle[0])) {
      angle.resize(n), lo.resize(n), hi.resize(n);
      angle.push_back(angle[0] + 360.0), lo.push_back(lo[0]), hi.push_back(hi[0]);
    }
    const auto lerp = [](double x, double y, double t) { return x + (y - x) * t; };
    for (std::size_t i = 0; i + 1 < std::min({angle.size(), lo.size(), hi.size()}); ++i) {
      if (!std::isfinite(lo[i] + lo[i + 1] + hi[i] + hi[i + 1])) continue;
      const double a0 = angle[i], a1 = angle[i + 1];
      for (int s = 0; s < 4; ++s) {
        const double t0 = s / 4.0, t1 = (s + 1) / 4.0;
        fig.polygons.push_back({{f.to_pixel(lerp(a0, a1, t0), lerp(lo[i], lo[i + 1], t0)),
                                 f.to_pixel(lerp(a0, a1, t1), lerp(lo[i], lo[i + 1], t1)),
                                 f.to_pixel(lerp(a0, a1, t1), lerp(hi[i], hi[i + 1], t1)),
                                 f.to_pixel(lerp(a0, a1, t0), lerp(hi[i], hi[i + 1], t0))},
                                colour});
      }
    }
  };
  for (const PolarBand& b : data.bands) shade(b.angle_deg, b.lo, b.hi, b.colour);
  shade(data.band_angle_deg, data.band_lo, data.band_hi, {222, 228, 240});
  draw_polar_axes(f, ticks, data.quantity, fig);
  draw_note(data.note, fig);
  int index = 0;
  std::vector<std::pair<std::string, Rgb>> legend;
  for (const PolarCurve& c : data.curves) {
    const Rgb colour = c.colour.value_or(series_colour(index++));
    fig.lines.push_back({curve_points(f, c.angle_deg, c.value), colour, c.width});
    legend.push_back({c.label, colour});
  }
  if (data.mean) {
    const Rgb colour = data.mean->colour.value_or(Rgb{0, 0, 0});
    fig.lines.push_back({curve_points(f, data.mean->angle_deg, data.mean->value), colour, 3.0});
    legend.push_back({data.mean->label.empty() ? "mean" : data.mean->label, colour});
  }
  if (!data.band_angle_deg.empty()) legend.push_back({"min–max", {200, 210, 230}});
  for (const PolarBand& b : data.bands)
    if (!b.label.empty()) legend.push_back({b.label, b.colour});
  double y = height - top - 10;
  const double lx = f.centre.x + f.radius_px + 40;
  for (const auto& [label, colour] : legend) {
    fig.lines.push_back({{{lx, y}, {lx + 24, y}}, colour, 3.0});
    fig.texts.push_back({{lx + 30, y}, label, 11, kBlack, HAlign::kLeft, VAlign::kCentre});
    y -= 18;
  }
  fig.texts.push_back({{width / 2.0, height - 10.0},
                       data.title,
                       15,
                       kBlack,
                       HAlign::kCentre,
                       VAlign::kTop,
                       0,
                       true});
  if (frame_out) *frame_out = f;
  return fig;
}

Figure polar_contour_figure(const PolarContourData& data, int width, int height,
                            PolarFrame* frame_out) {
  const std::size_t na = data.angle_deg.size(), nr = data.radius.size();
  if (na == 0 || nr == 0 || data.value.size() != na * nr)
    throw std::invalid_argument("polar contour: value must hold angles x radii numbers");
  Figure fig;
  fig.width = width;
  fig.height = height;
  double vlo = std::numeric_limits<double>::infinity(), vhi = -vlo;
  for (double v : data.value)
    if (std::isfinite(v)) vlo = std::min(vlo, v), vhi = std::max(vhi, v);
  if (!(vlo <= vhi)) vlo = 0, vhi = 1;
  if (vhi == vlo) vhi = vlo + 1;

  const std::vector<double> ae = edges_of(data.angle_deg), re = edges_of(data.radius);
  PolarFrame f;
  const double top = 46;
  f.radius_px = std::min((width - 230) / 2.0, (height - top - 70) / 2.0);
  f.centre = {40 + f.radius_px + 20, 30 + f.radius_px + 20};
  f.r_lo = std::max(0.0, re.front());
  if (data.radius.front() >= 0.0 && re.front() < 0.0) f.r_lo = 0.0;
  f.r_hi = re.back();
  for (std::size_t i = 0; i < nr; ++i)
    for (std::size_t j = 0; j < na; ++j) {
      const double v = data.value[i * na + j];
      const Rgb c = std::isfinite(v) ? colour_map((v - vlo) / (vhi - vlo)) : Rgb{190, 190, 190};
      const int sub = std::max(1, static_cast<int>(std::ceil((ae[j + 1] - ae[j]) / 3.0)));
      for (int s = 0; s < sub; ++s) {
        const double a0 = ae[j] + (ae[j + 1] - ae[j]) * s / sub;
        const double a1 = ae[j] + (ae[j + 1] - ae[j]) * (s + 1) / sub;
        fig.polygons.push_back({{f.to_pixel(a0, re[i]), f.to_pixel(a1, re[i]),
                                 f.to_pixel(a1, re[i + 1]), f.to_pixel(a0, re[i + 1])},
                                c});
      }
    }
  // Radial ticks at the data radii (the gaps of the study), thinned to about six.
  std::vector<double> r_ticks;
  const std::size_t every = std::max<std::size_t>(1, (nr + 5) / 6);
  for (std::size_t i = 0; i < nr; i += every) r_ticks.push_back(data.radius[i]);
  draw_polar_axes(f, r_ticks, data.radius_title, fig);
  draw_note(data.note, fig);
  for (Polyline& l : fig.lines)
    if (l.colour == kGrid) l.colour = {255, 255, 255};  // grid over colour: white
  for (Text& t : fig.texts)
    if (t.colour == Rgb{90, 90, 90}) t.colour = {255, 255, 255}, t.bold = true;

  // Colour bar.
  const double bx = width - 150, by = 60, bw = 24, bh = height - top - 120;
  for (int k = 0; k < 64; ++k) {
    const double y0 = by + bh * k / 64.0, y1 = by + bh * (k + 1) / 64.0;
    fig.polygons.push_back(
        {{{bx, y0}, {bx + bw, y0}, {bx + bw, y1}, {bx, y1}}, colour_map((k + 0.5) / 64.0)});
  }
  fig.lines.push_back(
      {{{bx, by}, {bx + bw, by}, {bx + bw, by + bh}, {bx, by + bh}, {bx, by}}, {60, 60, 60}, 1.0});
  for (double t : nice_ticks(vlo, vhi, 6)) {
    const double y = by + (t - vlo) / (vhi - vlo) * bh;
    fig.lines.push_back({{{bx + bw, y}, {bx + bw + 5, y}}, {60, 60, 60}, 1.0});
    fig.texts.push_back(
        {{bx + bw + 8, y}, tick_label(t), 11, kBlack, HAlign::kLeft, VAlign::kCentre});
  }
  fig.texts.push_back({{bx + bw + 70, by + bh / 2},
                       data.value_title,
                       12,
                       kBlack,
                       HAlign::kCentre,
                       VAlign::kCentre,
                       90.0});
  fig.texts.push_back({{width / 2.0, height - 10.0},
                       data.title,
                       15,
                       kBlack,
                       HAlign::kCentre,
                       VAlign::kTop,
                       0,
                       true});
  if (frame_out) *frame_out = f;
  return fig;
}

}  // namespace isopound::post
