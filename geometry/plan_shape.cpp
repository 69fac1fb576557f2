// Plans as vertex lists, convex or not (plan_shape.h).
#include "geometry/plan_shape.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "geometry/outline_rules.h"

namespace isopound {

bool is_convex_list(std::span<const Vec2> v) {
  const std::size_t n = v.size();
  if (n < 3) return false;
  int sign = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const double turn = cross(v[(i + 1) % n] - v[i], v[(i + 2) % n] - v[(i + 1) % n]);
    const int s = turn > 0 ? 1 : (turn < 0 ? -1 : 0);
    if (s == 0 || (sign != 0 && s != sign)) return false;
    sign = s;
  }
  return true;
}

ConvexPolygon convex_hull(std::span<const Vec2> v) {
  if (is_convex_list(v)) return ConvexPolygon(v);
  std::vector<Vec2> p(v.begin(), v.end());
  if (p.size() < 3) return ConvexPolygon(std::span<const Vec2>(p.data(), p.size()));  // refuses
  std::sort(p.begin(), p.end(),
            [](Vec2 a, Vec2 b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
  std::vector<Vec2> hull(2 * p.size());
  std::size_t k = 0;
  const auto left = [](Vec2 o, Vec2 a, Vec2 b) { return cross(a - o, b - o) > 0; };
  for (std::size_t i = 0; i < p.size(); ++i) {  // lower chain
    while (k >= 2 && !left(hull[k - 2], hull[k - 1], p[i])) --k;
    hull[k++] = p[i];
  }
  for (std::size_t i = p.size() - 1, t = k + 1; i-- > 0;) {  // upper chain
    while (k >= t && !left(hull[k - 2], hull[k - 1], p[i])) --k;
    hull[k++] = p[i];
  }
  hull.resize(k - 1);
  return ConvexPolygon(std::span<const Vec2>(hull.data(), hull.size()));
}

AreaProperties plan_area_properties(std::span<const Vec2> plan) {
  if (is_convex_list(plan)) return area_properties(ConvexPolygon(plan));
  return area_properties(SimplePolygon(plan));
}

double plan_overlap_area(std::span<const Vec2> a, std::span<const Vec2> b) {
  if (is_convex_list(a) && is_convex_list(b))
    return overlap_of(ConvexPolygon(a), ConvexPolygon(b)).area;
  const PlanOverlap o = plan_overlap(SimplePolygon(a), SimplePolygon(b));
  double area = 0.0;
  for (int k = 0; k < o.count; ++k) area += o.components[k].area;
  return area;
}

Separation plan_separation(std::span<const Vec2> a, std::span<const Vec2> b) {
  if (is_convex_list(a) && is_convex_list(b))
    return separation_of(ConvexPolygon(a), ConvexPolygon(b));
  return plan_separation(SimplePolygon(a), SimplePolygon(b));
}

bool plan_contains(std::span<const Vec2> plan, Vec2 p, double tolerance) {
  // On the outline within the tolerance, else inside by the winding number (contains()).
  const std::size_t n = plan.size();
  for (std::size_t i = 0; i < n; ++i)
    if (detail::point_segment_distance_sq(p, plan[i], plan[(i + 1) % n]) <= tolerance * tolerance)
      return true;
  return contains(SimplePolygon(plan), p);
}

}  // namespace isopound
