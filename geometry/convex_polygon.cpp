// ConvexPolygon: validation (with messages naming the vertex), rigid placement, area properties.
// Orientation: counter-clockwise; clockwise input is reversed, the index in messages is the
// input's.
#include "geometry/convex_polygon.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "geometry/outline_rules.h"

namespace isopound {
namespace {

using detail::kCollinearSine;
using detail::kRepeatedFraction;

[[noreturn]] void reject(int i, Vec2 p, const std::string& what) {
  throw InvalidPolygon(i, detail::describe_vertex(i, p) + ": " + what);
}

// Two edges of the outline that cross (not at a shared vertex), as "edge 0-1 crosses edge 2-3";
// empty when none do. Only called on the way to an error: O(n^2).
std::string crossing_edges(std::span<const Vec2> in) {
  const int n = int(in.size());
  const auto side = [](Vec2 a, Vec2 b, Vec2 p) { return cross(b - a, p - a); };
  for (int i = 0; i < n; ++i) {
    const Vec2 a = in[i], b = in[(i + 1) % n];
    for (int j = i + 2; j < n; ++j) {
      if (i == 0 && j == n - 1) continue;  // adjacent through vertex 0
      const Vec2 c = in[j], d = in[(j + 1) % n];
      const double s1 = side(a, b, c), s2 = side(a, b, d), s3 = side(c, d, a), s4 = side(c, d, b);
      if (((s1 > 0 && s2 < 0) || (s1 < 0 && s2 > 0)) && ((s3 > 0 && s4 < 0) || (s3 < 0 && s4 > 0)))
        return "edge " + std::to_string(i) + "-" + std::to_string((i + 1) % n) + " crosses edge " +
               std::to_string(j) + "-" + std::to_string((j + 1) % n);
    }
  }
  return {};
}

[[noreturn]] void reject_self_crossing(const std::string& crossing) {
  throw InvalidPolygon(-1, "the outline crosses itself (" + crossing +
                               "): a self-crossing plan; list the vertices in order around the "
                               "outline");
}

}  // namespace

ConvexPolygon::ConvexPolygon(std::initializer_list<Vec2> vertices)
    : ConvexPolygon(std::span<const Vec2>(vertices.begin(), vertices.size())) {}

ConvexPolygon::ConvexPolygon(std::span<const Vec2> in) {
  const int n = int(in.size());
  if (n < 3) {
    throw InvalidPolygon(-1, "a polygon needs at least 3 vertices, got " + std::to_string(n));
  }
  if (n > kMaxPolygonVertices) {
    throw InvalidPolygon(-1, "a polygon may have at most " + std::to_string(kMaxPolygonVertices) +
                                 " vertices, got " + std::to_string(n));
  }
  for (int i = 0; i < n; ++i) {
    if (!std::isfinite(in[i].x) || !std::isfinite(in[i].y)) {
      reject(i, in[i], "coordinate is not a finite number");
    }
  }
  Vec2 lo = in[0], hi = in[0];
  for (const Vec2& p : in) {
    lo = {std::min(lo.x, p.x), std::min(lo.y, p.y)};
    hi = {std::max(hi.x, p.x), std::max(hi.y, p.y)};
  }
  const double size = std::max(hi.x - lo.x, hi.y - lo.y);
  for (int i = 1; i < n; ++i) {
    for (int j = 0; j < i; ++j) {
      const Vec2 d = in[i] - in[j];
      if (std::hypot(d.x, d.y) <= kRepeatedFraction * size) {
        reject(i, in[i], "repeats vertex " + std::to_string(j));
      }
    }
  }
  // Twice the signed area about vertex 0: > 0 counter-clockwise.
  double twice_area = 0.0;
  for (int i = 1; i + 1 < n; ++i) twice_area += cross(in[i] - in[0], in[i + 1] - in[0]);
  if (std::abs(twice_area) <= kCollinearSine * size * size) {
    if (const std::string crossing = crossing_edges(in); !crossing.empty())
      reject_self_crossing(crossing);
    throw InvalidPolygon(-1, "zero area: all " + std::to_string(n) + " vertices lie on one line");
  }
  const double orientation = twice_area > 0.0 ? 1.0 : -1.0;
  // Every turn strictly left (in the polygon's own orientation), and one turn around in total.
  double turned = 0.0;
  for (int i = 0; i < n; ++i) {
    const Vec2 e_in = in[i] - in[(i + n - 1) % n];
    const Vec2 e_out = in[(i + 1) % n] - in[i];
    const double c = orientation * cross(e_in, e_out);
    const double scale = std::hypot(e_in.x, e_in.y) * std::hypot(e_out.x, e_out.y);
    if (std::abs(c) <= kCollinearSine * scale) {
      reject(i, in[i], "lies on the straight line through its neighbours (remove it)");
    }
    if (c < 0.0) {
      const std::string crossing = crossing_edges(in);
      const std::string turn = orientation > 0.0
                                   ? "the outline turns right here: not convex"
                                   : "the outline (clockwise) turns left here: not convex";
      reject(i, in[i],
             crossing.empty() ? turn
                              : turn + " (the outline crosses itself, " + crossing +
                                    ": a self-crossing plan; list the vertices in order around "
                                    "the outline)");
    }
    turned += std::atan2(c, dot(e_in, e_out));
    if (turned > 2.0 * std::numbers::pi * (1.0 + 1e-9)) {
      reject(i, in[i],
             "the outline has turned more than 360 degrees by here (it crosses itself): "
             "not convex");
    }
  }
  count_ = n;
  reversed_ = orientation < 0.0;
  for (int i = 0; i < n; ++i) vertices_[i] = reversed_ ? in[n - 1 - i] : in[i];
  update_box();
}

void ConvexPolygon::update_box() {
  box_min_ = box_max_ = vertices_[0];
  for (int i = 1; i < count_; ++i) {
    box_min_ = {std::min(box_min_.x, vertices_[i].x), std::min(box_min_.y, vertices_[i].y)};
    box_max_ = {std::max(box_max_.x, vertices_[i].x), std::max(box_max_.y, vertices_[i].y)};
  }
}

ConvexPolygon ConvexPolygon::placed(const Placement2& x, Vec2 about) const {
  return placed(x, about, std::cos(x.theta), std::sin(x.theta));
}

ConvexPolygon ConvexPolygon::placed(const Placement2& x, Vec2 about, double c, double s) const {
  ConvexPolygon out;
  out.count_ = count_;
  out.reversed_ = reversed_;
  for (int i = 0; i < count_; ++i) {
    const Vec2 r = vertices_[i] - about;
    out.vertices_[i] = {about.x + c * r.x - s * r.y + x.u, about.y + s * r.x + c * r.y + x.v};
  }
  out.update_box();
  return out;
}

AreaProperties area_properties(const ConvexPolygon& polygon) {
  return outline_area_properties(polygon.vertices());
}

AreaProperties outline_area_properties(std::span<const Vec2> polygon) {
  const int n = int(polygon.size());
  Vec2 origin;
  for (int i = 0; i < n; ++i) origin = origin + polygon[i];
  origin = (1.0 / n) * origin;
  // Shoelace sums about `origin`: 2A, 6A·C, and 12·(I_xx + I_yy) about `origin`.
  double twice_area = 0.0, cx = 0.0, cy = 0.0, twelve_j = 0.0;
  for (int i = 0; i < n; ++i) {
    const Vec2 p = polygon[i] - origin;
    const Vec2 q = polygon[(i + 1) % n] - origin;
    const double w = cross(p, q);
    twice_area += w;
    cx += w * (p.x + q.x);
    cy += w * (p.y + q.y);
    twelve_j += w * (p.x * p.x + p.x * q.x + q.x * q.x + p.y * p.y + p.y * q.y + q.y * q.y);
  }
  AreaProperties out;
  out.area = 0.5 * twice_area;
  const Vec2 p_OC{cx / (3.0 * twice_area), cy / (3.0 * twice_area)};
  out.p_WC = origin + p_OC;
  // Parallel axes: J_origin = J_c + A·|OC|².
  out.polar_moment_c = twelve_j / 12.0 - out.area * dot(p_OC, p_OC);
  return out;
}

}  // namespace isopound
