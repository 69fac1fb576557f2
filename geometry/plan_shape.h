// Plans as vertex lists (as model configs and site tables carry them), convex or not (issue 40):
// a convex list takes the convex polygon's functions (today's arithmetic, bit for bit), any other
// the simple polygon's (simple_polygon.h, plan_overlap.h). Lengths in metres, plan frame W.
#pragma once

#include <span>

#include "geometry/overlap.h"
#include "geometry/plan_overlap.h"
#include "geometry/simple_polygon.h"

namespace isopound {

// True when every turn of the list goes the same way, strictly (a convex polygon's list).
bool is_convex_list(std::span<const Vec2> vertices);

// The smallest convex polygon holding the list (Andrew's monotone chain, collinear points
// dropped); the list itself, as ConvexPolygon takes it, when it is convex.
ConvexPolygon convex_hull(std::span<const Vec2> vertices);

// Area, centroid and polar moment of the outline (the same numbers either way).
AreaProperties plan_area_properties(std::span<const Vec2> plan);

// The total overlap area of two plans (every part), m².
double plan_overlap_area(std::span<const Vec2> a, std::span<const Vec2> b);

// Signed separation of two plans (separation_of for convex ones; the least over piece pairs).
Separation plan_separation(std::span<const Vec2> a, std::span<const Vec2> b);

// Inside or on the outline, within `tolerance` (m).
bool plan_contains(std::span<const Vec2> plan, Vec2 p, double tolerance);

}  // namespace isopound
