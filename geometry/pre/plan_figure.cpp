// The plan figure: layout (equal scale in x and y, legend at the right, scale bar below), then
// shapes in drawing order (walls, slabs, bearings, columns, markers), dimension lines and text.
#include "geometry/pre/plan_figure.h"
#include "geometry/plan_shape.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <numbers>
#include <span>

namespace isopound::pre {
namespace {

using post::Point2;
using post::Rgb;

constexpr double kLegendWidth = 330;        // px
constexpr double kMargin = 50;              // px
constexpr double kTitleHeight = 50;         // px
constexpr double kBottom = 90;              // px: scale bar
constexpr double kStruckMinPx = 16;         // px: a struck column's mark at least this diagonal
constexpr double kLegendWidthStruck = 420;  // px: room for the struck slabs' lines

Rgb tint(Rgb c, double f) {
  const auto mix = [f](unsigned char v) {
    return static_cast<unsigned char>(std::lround(v + f * (255 - v)));
  };
  return {mix(c.r), mix(c.g), mix(c.b)};
}

std::vector<Point2> circle(Point2 c, double r, int n = 16) {
  std::vector<Point2> out;
  for (int k = 0; k < n; ++k) {
    const double a = 2 * std::numbers::pi * k / n;
    out.push_back({c.x + r * std::cos(a), c.y + r * std::sin(a)});
  }
  return out;
}

std::vector<Point2> square(Point2 c, double r) {
  return {{c.x - r, c.y - r}, {c.x + r, c.y - r}, {c.x + r, c.y + r}, {c.x - r, c.y + r}};
}

std::string length_text(double m) {
  char buf[64];
  if (std::abs(m) < 1.0)
    std::snprintf(buf, sizeof buf, "%.1f cm", 100 * m);
  else
    std::snprintf(buf, sizeof buf, "%.2f m", m);
  return buf;
}

// 1, 2 or 5 times a power of ten, at most `max`.
double nice_length(double max) {
  const double p = std::pow(10.0, std::floor(std::log10(max)));
  for (double f : {5.0, 2.0, 1.0})
    if (f * p <= max) return f * p;
  return p;
}

void arrow(post::Figure& f, Point2 from, Point2 to, Rgb colour, double width) {
  f.lines.push_back({{from, to}, colour, width});
  const double a = std::atan2(to.y - from.y, to.x - from.x), h = 14;
  for (double s : {-1.0, 1.0})
    f.lines.push_back({{to, {to.x - h * std::cos(a + s * 0.4), to.y - h * std::sin(a + s * 0.4)}},
                       colour,
                       width});
}

// "3.2 m": an elevation as the configs write them.
std::string metres(double z) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g m", z);
  return buf;
}

// The struck columns at one plan position: every storey of `struck` struck there.
struct StruckPlace {
  int struck = -1, striker = -1;
  std::vector<Vec2> section_W;
  int storey_lo = 0, storey_hi = 0;
};

Vec2 centroid_of(const std::vector<Vec2>& points) {
  Vec2 c;
  for (Vec2 p : points) c = c + (1.0 / static_cast<double>(points.size())) * p;
  return c;
}

std::vector<StruckPlace> struck_places(const std::vector<StruckColumnSite>& sites) {
  std::vector<StruckPlace> places;
  for (const StruckColumnSite& s : sites) {
    const Vec2 c = centroid_of(s.section_W);
    const auto it = std::find_if(places.begin(), places.end(), [&](const StruckPlace& q) {
      const Vec2 d = centroid_of(q.section_W);
      return q.struck == s.struck && std::hypot(d.x - c.x, d.y - c.y) < 1e-6;
    });
    if (it == places.end()) {
      places.push_back({s.struck, s.striker, s.section_W, s.storey, s.storey});
    } else {
      it->storey_lo = std::min(it->storey_lo, s.storey);
      it->storey_hi = std::max(it->storey_hi, s.storey);
    }
  }
  return places;
}

}  // namespace

Rgb slab_fill(int structure) {
  return tint(post::series_colour(structure), 0.72);
}

post::Figure plan_figure(const Site& site, const std::vector<StructureProperties>& properties,
                         const std::vector<Clearance>& clearances,
                         const std::vector<StruckColumnSite>& struck, const PlanOptions& options,
                         PlanView* view_out) {
  post::Figure f;
  f.width = options.width;
  f.height = options.height;

  // Extent of everything drawn, and the scale that fits it into the plot area.
  Vec2 lo{1e300, 1e300}, hi{-1e300, -1e300};
  const auto grow = [&](Vec2 p) {
    lo = {std::min(lo.x, p.x), std::min(lo.y, p.y)};
    hi = {std::max(hi.x, p.x), std::max(hi.y, p.y)};
  };
  for (const PlanSlab& s : site.slabs)
    for (Vec2 p : s.plan_W) grow(p);
  for (const PlanWall& w : site.walls)
    for (Vec2 p : w.plan_W) grow(p);
  for (const PlanColumn& c : site.ground_columns)
    for (Vec2 p : c.outline_W()) grow(p);
  if (lo.x > hi.x) lo = hi = {0, 0};
  const double pad = 0.08 * std::max({hi.x - lo.x, hi.y - lo.y, 1.0});
  lo = lo - Vec2{pad, pad};
  hi = hi + Vec2{pad, pad};
  const double legend_width = struck.empty() ? kLegendWidth : kLegendWidthStruck;
  const double plot_w = f.width - legend_width - 2 * kMargin;
  const double plot_h = f.height - kTitleHeight - kBottom;
  PlanView view;
  view.scale = std::min(plot_w / (hi.x - lo.x), plot_h / (hi.y - lo.y));
  view.origin_W = 0.5 * (lo + hi);
  view.origin_px = {kMargin + plot_w / 2, kBottom + plot_h / 2};
  if (view_out) *view_out = view;
  const auto px = [&](Vec2 p) { return view.to_px(p); };
  const auto px_all = [&](const std::vector<Vec2>& v) {
    std::vector<Point2> out;
    for (Vec2 p : v) out.push_back(px(p));
    return out;
  };
  const auto closed = [&](const std::vector<Vec2>& v) {
    std::vector<Point2> out = px_all(v);
    out.push_back(out.front());
    return out;
  };

  // Walls, slabs (lowest level first), bearings, columns.
  for (const PlanWall& w : site.walls) f.polygons.push_back({px_all(w.plan_W), kWallColour});
  std::vector<const PlanSlab*> slabs;
  for (const PlanSlab& s : site.slabs) slabs.push_back(&s);
  std::stable_sort(slabs.begin(), slabs.end(), [](const PlanSlab* a, const PlanSlab* b) {
    return a->elevation < b->elevation;
  });
  for (const PlanSlab* s : slabs)
    f.polygons.push_back({px_all(s->plan_W), slab_fill(s->structure)});
  for (const PlanSlab* s : slabs) {
    const Rgb edge = post::series_colour(s->structure);
    f.lines.push_back({closed(s->plan_W), edge, s->level_index == 0 ? 2.5 : 1.0});
  }
  for (const PlanSlab& s : site.slabs)
    for (const PlanBearing& b : s.bearings)
      f.polygons.push_back({circle(px(b.p_W), std::max(6.0, 0.35 * view.scale)), kBearingColour});
  const auto draw_column = [&](const PlanColumn& c) {
    // At least 5 px across so that it shows; its orientation from the axis-1 tick.
    const double grow_by = std::max(1.0, 5.0 / (view.scale * std::min(c.b, c.h)));
    PlanColumn big = c;
    big.b *= grow_by;
    big.h *= grow_by;
    f.polygons.push_back({px_all(big.outline_W()), kColumnColour});
    // Axis 1 as a white stroke through it (the orientation of a square section).
    const Vec2 a1{std::cos(c.orientation), std::sin(c.orientation)};
    f.lines.push_back(
        {{px(c.p_W - 0.45 * big.b * a1), px(c.p_W + 0.45 * big.b * a1)}, {255, 255, 255}, 1.5});
  };
  for (const PlanSlab& s : site.slabs)
    for (const PlanColumn& c : s.columns) draw_column(c);
  for (const PlanColumn& c : site.ground_columns) draw_column(c);

  // Struck columns: each marked in kStruckColour over its column (a marker: above the axis
  // stroke), at least kStruckMinPx across (a mark round it would run into the facing line across
  // the gap). One label per facing line (the columns of one struck structure, striker and storeys):
  // beyond its last column along the line, on the side away from the striking structure.
  struct Line {
    const StruckPlace* place;  // the last along the line so far
    Vec2 away, along;
    double reach, half_px;
  };
  std::vector<Line> lines;
  const std::vector<StruckPlace> places = struck_places(struck);
  for (const StruckPlace& q : places) {
    const Vec2 c = centroid_of(q.section_W);
    double diagonal = 0.0;
    for (Vec2 p : q.section_W) diagonal = std::max(diagonal, 2 * std::hypot(p.x - c.x, p.y - c.y));
    const double grow_by = std::max(1.0, kStruckMinPx / (view.scale * diagonal));
    std::vector<Point2> outline;
    for (Vec2 p : q.section_W) outline.push_back(px(c + grow_by * (p - c)));
    f.markers.push_back({outline, kStruckColour, {0, 0, 0}, 1.0});
    Vec2 striker_at, away{1, 0};
    int n = 0;
    for (const PlanSlab& sl : site.slabs)
      if (sl.structure == q.striker)
        for (Vec2 p : sl.plan_W) striker_at = striker_at + p, ++n;
    if (n > 0) {
      striker_at = (1.0 / n) * striker_at;
      const double dx = c.x - striker_at.x, dy = c.y - striker_at.y;
      away = std::abs(dx) >= std::abs(dy) ? Vec2{dx > 0 ? 1.0 : -1.0, 0}
                                          : Vec2{0, dy > 0 ? 1.0 : -1.0};
    }
    const Vec2 along = away.x != 0 ? Vec2{0, 1} : Vec2{1, 0};  // north or east
    const double reach = along.x * c.x + along.y * c.y;
    const auto same = [&](const Line& l) {
      return l.place->struck == q.struck && l.place->striker == q.striker &&
             l.place->storey_lo == q.storey_lo && l.place->storey_hi == q.storey_hi &&
             l.away.x == away.x && l.away.y == away.y;
    };
    const auto it = std::find_if(lines.begin(), lines.end(), same);
    const double half_px = 0.25 * grow_by * diagonal * view.scale * std::sqrt(2.0);
    if (it == lines.end())
      lines.push_back({&q, away, along, reach, half_px});
    else if (reach > it->reach)
      *it = {&q, away, along, reach, half_px};
  }
  for (const Line& l : lines) {
    const StruckPlace& q = *l.place;
    const std::string text =
        (q.storey_lo == q.storey_hi
             ? "storey " + std::to_string(q.storey_lo)
             : "storeys " + std::to_string(q.storey_lo) + "–" + std::to_string(q.storey_hi)) +
        " struck";
    const Point2 at = px(centroid_of(q.section_W));
    const double off = l.half_px + 3;
    // Beyond the last column along the line, from its centre away from the striker (the facing
    // line's label starts as far the other way: the two stay apart across the gap).
    const Point2 where{at.x + l.along.x * off + 2 * l.away.x,
                       at.y + l.along.y * off + 2 * l.away.y};
    f.texts.push_back({where, text, 11, kStruckColour,
                       l.away.x > 0   ? post::HAlign::kLeft
                       : l.away.x < 0 ? post::HAlign::kRight
                                      : post::HAlign::kLeft,
                       l.away.y > 0   ? post::VAlign::kBottom
                       : l.away.y < 0 ? post::VAlign::kTop
                                      : post::VAlign::kBottom});
  }

  // Centres of mass and stiffness (per structure: the whole mass; the bearings' or storey 1's
  // centre of stiffness).
  for (std::size_t i = 0; i < properties.size(); ++i) {
    const StructureProperties& p = properties[i];
    if (p.storeys.empty()) continue;
    double m = 0;
    Vec2 cm;
    for (const DiaphragmProperties& d : p.diaphragms) {
      m += d.mass;
      cm = cm + d.mass * d.p_WM;
    }
    cm = (1.0 / m) * cm;
    // The isolation layer's centre of stiffness (wherever it sits), else storey 1's.
    const StoreyProperties* stiff = &p.storeys.front();
    for (const StoreyProperties& st : p.storeys)
      if (st.storey == 0) stiff = &st;
    const Point2 s = px(stiff->p_WS), c = px(cm);
    std::vector<Point2> frame = square(s, 10);
    frame.push_back(frame.front());
    f.lines.push_back({frame, kStiffnessColour, 3});
    f.polygons.push_back({circle(c, 6), kMassColour});
    f.texts.push_back({{s.x + 10, s.y - 10},
                       "CS",
                       12,
                       kStiffnessColour,
                       post::HAlign::kLeft,
                       post::VAlign::kTop});
    f.texts.push_back(
        {{c.x + 10, c.y + 10}, "CM", 12, kMassColour, post::HAlign::kLeft, post::VAlign::kBottom});
  }
  // Structure names inside their lowest slab, a sixth of its height below the top (clear of
  // the gap dimensions at its edges and of the centres at its middle).
  std::map<int, Vec2> name_at;
  for (const PlanSlab& s : site.slabs) {
    if (name_at.count(s.structure)) continue;  // slabs are listed bottom-up per structure
    double top = -1e300, bottom = 1e300;
    for (Vec2 p : s.plan_W) top = std::max(top, p.y), bottom = std::min(bottom, p.y);
    const AreaProperties a = plan_area_properties(s.plan_W);
    name_at[s.structure] = {a.p_WC.x, top - (top - bottom) / 6};
  }
  for (const auto& [i, p] : name_at) {
    std::string name;
    for (const PlanSlab& s : site.slabs)
      if (s.structure == i) name = s.name;
    f.texts.push_back({px(p), name, 16, post::series_colour(i), post::HAlign::kCentre,
                       post::VAlign::kCentre, 0.0, true});
  }

  // Gaps: one dimension per pair of bodies and side (the lowest level), ticks at both faces.
  std::map<std::string, const Clearance*> gaps;
  for (const Clearance& c : clearances) {
    if (!(c.measured > 0) || c.measured > options.max_dimensioned_gap) continue;
    const std::string a = c.a.substr(0, c.a.find('/')), b = c.b.substr(0, c.b.find('/'));
    const std::string key = a + "|" + b + "|" + c.side;
    if (!gaps.count(key) || c.elevation < gaps[key]->elevation) gaps[key] = &c;
  }
  const Rgb dim{0, 0, 0};
  for (const auto& [key, c] : gaps) {
    const Point2 a = px(c->p_WA), b = px(c->p_WB);
    double dx = b.x - a.x, dy = b.y - a.y;
    const double len = std::hypot(dx, dy);
    dx = len > 0 ? dx / len : 1;
    dy = len > 0 ? dy / len : 0;
    // Extend the dimension line 12 px beyond both faces, so that a small gap still shows.
    f.lines.push_back({{{a.x - 12 * dx, a.y - 12 * dy}, {b.x + 12 * dx, b.y + 12 * dy}}, dim, 1.5});
    for (Point2 e : {a, b})
      f.lines.push_back({{{e.x - 6 * dy, e.y + 6 * dx}, {e.x + 6 * dy, e.y - 6 * dx}}, dim, 1.5});
    // The value on A's side of the gap (inside the slab: readable, clear of walls), written
    // along the slab's edge: vertical for a gap to the east or west, so that the values of two
    // gaps across a narrow slab do not meet; slanted along a slanted edge (a chamfer's wall).
    std::string label = length_text(c->measured);
    if (c->declared >= 0) label += " (declared " + length_text(c->declared) + ")";
    if (std::min(std::abs(dx), std::abs(dy)) > 0.2) {
      double along = std::atan2(dy, dx) * 180.0 / std::numbers::pi + 90.0;  // the edge, degrees
      while (along > 90.0) along -= 180.0;                                  // read left to right
      while (along <= -90.0) along += 180.0;
      const Point2 at{a.x - 22 * dx, a.y - 22 * dy};
      f.texts.push_back({at, label, 12, dim, post::HAlign::kCentre, post::VAlign::kCentre, along});
    } else if (std::abs(dx) >= std::abs(dy)) {
      const Point2 at{a.x - 14 * dx, a.y};
      f.texts.push_back({at, label, 12, dim, post::HAlign::kCentre,
                         dx > 0 ? post::VAlign::kBottom : post::VAlign::kTop, 90.0});
    } else {
      const Point2 at{a.x + 8, a.y - 14 * dy};
      f.texts.push_back({at, label, 12, dim, post::HAlign::kLeft,
                         dy > 0 ? post::VAlign::kTop : post::VAlign::kBottom});
    }
  }

  // Scale bar below the plot.
  const double bar_m = nice_length(0.25 * plot_w / view.scale);
  const double bar_px = bar_m * view.scale;
  const Point2 s0{kMargin, 45}, s1{kMargin + bar_px, 45};
  f.polygons.push_back(
      {{{s0.x, s0.y}, {s0.x + bar_px / 2, s0.y}, {s0.x + bar_px / 2, s0.y + 8}, {s0.x, s0.y + 8}},
       {0, 0, 0}});
  f.lines.push_back({{s0, s1, {s1.x, s1.y + 8}, {s0.x, s0.y + 8}, s0}, {0, 0, 0}, 1.5});
  f.texts.push_back({{s0.x, 30}, "0", 12, {0, 0, 0}});
  char bar_label[32];
  std::snprintf(bar_label, sizeof bar_label, "%g m", bar_m);
  f.texts.push_back({{s1.x, 30}, bar_label, 12, {0, 0, 0}});
  f.texts.push_back(
      {{s1.x + 50, 49}, "x: east, y: north (plan frame W)", 12, {60, 60, 60}, post::HAlign::kLeft});

  // Legend.
  const double lx = f.width - legend_width + 10;
  double ly = f.height - kTitleHeight - 20;
  const auto entry = [&](const std::vector<Point2>& swatch, Rgb colour, const std::string& text) {
    std::vector<Point2> moved;
    for (Point2 p : swatch) moved.push_back({lx + 12 + p.x, ly + p.y});
    if (!moved.empty()) f.polygons.push_back({moved, colour});
    f.texts.push_back({{lx + 34, ly}, text, 13, {0, 0, 0}, post::HAlign::kLeft});
    ly -= 28;
  };
  for (const auto& [i, p] : name_at) {
    std::string name;
    for (const PlanSlab& s : site.slabs)
      if (s.structure == i) name = s.name;
    entry(square({0, 0}, 9), slab_fill(i), "slabs of " + name);
  }
  if (!site.walls.empty()) entry(square({0, 0}, 9), kWallColour, "wall");
  entry(square({0, 0}, 4), kColumnColour, "column (b x h, oriented)");
  entry(circle({0, 0}, 6), kBearingColour, "bearing");
  entry(circle({0, 0}, 7), kMassColour, "CM: centre of mass (all floors)");
  entry({}, kStiffnessColour, "CS: centre of stiffness");
  {
    std::vector<Point2> frame = square({lx + 12, ly + 28}, 8);
    frame.push_back(frame.front());
    f.lines.push_back({frame, kStiffnessColour, 3});
  }
  f.texts.push_back({{lx + 34, ly + 12},
                     "(bearings; fixed base: storey 1)",
                     11,
                     {60, 60, 60},
                     post::HAlign::kLeft,
                     post::VAlign::kTop});
  ly -= 28;
  if (!gaps.empty()) {
    f.lines.push_back({{{lx, ly}, {lx + 24, ly}}, dim, 1.5});
    f.texts.push_back(
        {{lx + 34, ly}, "gap at rest (measured)", 13, {0, 0, 0}, post::HAlign::kLeft});
    ly -= 28;
  }
  // Struck columns: the swatch, then each striking slab (structure, level, elevation) and the
  // storey it strikes between which floors, with how many columns.
  if (!struck.empty()) {
    f.markers.push_back({square({lx + 12, ly}, 6), kStruckColour, {0, 0, 0}, 1.0});
    f.texts.push_back(
        {{lx + 34, ly}, "struck column (a slab strikes it)", 13, {0, 0, 0}, post::HAlign::kLeft});
    ly -= 22;
    struct Group {
      std::string slab, storey;  // the two lines
      int columns = 0;
    };
    std::vector<Group> groups;
    for (const StruckColumnSite& s : struck) {
      char floors[64];
      std::snprintf(floors, sizeof floors, " (%.3g–%.3g m)", s.z_lower, s.z_upper);
      const Group g{s.striker_name + "/" + s.slab_level + " at z = " + metres(s.slab_elevation),
                    "strikes " + s.struck_name + " storey " + std::to_string(s.storey) + floors, 1};
      const auto it = std::find_if(groups.begin(), groups.end(), [&](const Group& o) {
        return o.slab == g.slab && o.storey == g.storey;
      });
      if (it == groups.end())
        groups.push_back(g);
      else
        ++it->columns;
    }
    for (const Group& g : groups) {
      f.texts.push_back({{lx + 34, ly}, g.slab, 11, kStruckColour, post::HAlign::kLeft});
      f.texts.push_back({{lx + 46, ly - 14},
                         g.storey + ": " + std::to_string(g.columns) + " columns",
                         11,
                         {0, 0, 0},
                         post::HAlign::kLeft});
      ly -= 34;
    }
    ly -= 6;
  }
  // L direction of the record pair (the arrow below the legend).
  if (options.angle) {
    const double a = *options.angle;
    const Point2 base{lx + 90, ly - 110};
    const Point2 tip{base.x + 70 * std::cos(a), base.y + 70 * std::sin(a)};
    const Point2 t_tip{base.x - 45 * std::sin(a), base.y + 45 * std::cos(a)};
    arrow(f, base, tip, {150, 0, 150}, 3);
    arrow(f, base, t_tip, {150, 0, 150}, 1);
    f.texts.push_back({{tip.x + 14 * std::cos(a), tip.y + 14 * std::sin(a)},
                       "L",
                       14,
                       {150, 0, 150},
                       post::HAlign::kCentre,
                       post::VAlign::kCentre,
                       0,
                       true});
    f.texts.push_back(
        {{t_tip.x - 12 * std::sin(a), t_tip.y + 12 * std::cos(a)}, "T", 12, {150, 0, 150}});
    char text[64];
    std::snprintf(text, sizeof text, "record L at %.1f\u00b0 from x (T at +90\u00b0)",
                  *options.angle * 180 / std::numbers::pi);
    f.lines.push_back({{{lx, ly}, {lx + 24, ly}}, {150, 0, 150}, 3});
    f.texts.push_back({{lx + 34, ly}, text, 13, {0, 0, 0}, post::HAlign::kLeft});
  }
  f.texts.push_back({{f.width / 2.0, f.height - 25.0},
                     options.title,
                     16,
                     {0, 0, 0},
                     post::HAlign::kCentre,
                     post::VAlign::kCentre,
                     0,
                     true});
  return f;
}

}  // namespace isopound::pre
