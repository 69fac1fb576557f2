// The exact reference of plan_overlap: CGAL's regularised Boolean intersection of the two
// outlines with exact constructions (Epeck), areas and centroids by the shoelace sums in the
// kernel's exact number type, rounded once.
#include <CGAL/Boolean_set_operations_2.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Polygon_2.h>
#include <CGAL/Polygon_with_holes_2.h>

#include <algorithm>
#include <iterator>
#include <vector>

#include "geometry/plan_overlap.h"

namespace isopound {
namespace {

using Kernel = CGAL::Exact_predicates_exact_constructions_kernel;
using FT = Kernel::FT;
using Polygon = CGAL::Polygon_2<Kernel>;

Polygon exact(const SimplePolygon& p) {
  Polygon out;
  for (const Vec2& v : p.vertices()) out.push_back(Kernel::Point_2(v.x, v.y));
  return out;
}

// Twice the area and six times the first moments of a closed outline (signed by orientation).
void add_sums(const Polygon& p, FT& twice_area, FT& mx, FT& my) {
  const auto n = p.size();
  for (std::size_t i = 0; i < n; ++i) {
    const auto& s = p[i];
    const auto& t = p[(i + 1) % n];
    const FT w = s.x() * t.y() - t.x() * s.y();
    twice_area += w;
    mx += w * (s.x() + t.x());
    my += w * (s.y() + t.y());
  }
}

}  // namespace

std::vector<ComponentArea> plan_overlap_areas_exact(const SimplePolygon& a,
                                                    const SimplePolygon& b) {
  std::vector<CGAL::Polygon_with_holes_2<Kernel>> parts;
  CGAL::intersection(exact(a), exact(b), std::back_inserter(parts));
  std::vector<ComponentArea> out;
  for (const auto& part : parts) {
    FT twice_area = 0, mx = 0, my = 0;
    add_sums(part.outer_boundary(), twice_area, mx, my);
    for (auto h = part.holes_begin(); h != part.holes_end(); ++h)
      add_sums(*h, twice_area, mx, my);  // holes run clockwise: their sums subtract
    if (twice_area == 0) continue;
    // CGAL::exact first: to_double of a lazy number is only its interval's approximation.
    const auto rounded = [](const FT& x) { return CGAL::to_double(CGAL::exact(x)); };
    out.push_back({rounded(twice_area / 2),
                   {rounded(mx / (3 * twice_area)), rounded(my / (3 * twice_area))}});
  }
  std::sort(out.begin(), out.end(), [](const ComponentArea& p, const ComponentArea& q) {
    return p.p_WC.x < q.p_WC.x || (p.p_WC.x == q.p_WC.x && p.p_WC.y < q.p_WC.y);
  });
  return out;
}

}  // namespace isopound
