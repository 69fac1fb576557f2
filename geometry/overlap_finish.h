// Internal to geometry/: the part of an overlap both paths share once A ∩ B is known (crossings
// from edge labels, case flag, normal, δ_N) and the SAT axis of least penetration.
// Conventions as in overlap.h: n_AB from A into B, t_AB = n_AB turned +90°.
#pragma once

#include <span>

#include "geometry/overlap.h"

namespace isopound::detail {

// The largest SAT separation over the outward edge normals of A and B, and that normal oriented
// from A to B. Computed about `origin` (coordinates shifted there).
struct SatAxis {
  double separation = 0.0;  // < 0: penetration depth along the axis; > 0: a separating gap
  Vec2 n_AB;
};
SatAxis least_penetration_axis(const ConvexPolygon& a, const ConvexPolygon& b, Vec2 origin);

// Fills the remaining fields of an Overlap from A ∩ B given as its vertices counter-clockwise,
// shifted by `origin` (p_W = origin + vertex), with edge_on_a[k] telling whether edge k → k+1
// lies on A's boundary (an edge on both boundaries counts as A's). area and p_OC (centroid
// relative to origin) are the caller's. count = 0 means separated; count ≤ 2 or area == 0
// means touching. `out` must be a default Overlap (written in place: no copy of its arrays).
void finish_overlap(const ConvexPolygon& a, const ConvexPolygon& b, Vec2 origin,
                    std::span<const Vec2> vertices_O, std::span<const bool> edge_on_a, double area,
                    Vec2 p_OC, Overlap& out);

// The fast path without its exact fallback, writing into a default `out`: false if its topology
// were ever inconsistent (tests check that this never happens).
bool overlap_fast(const ConvexPolygon& a, const ConvexPolygon& b, Overlap& out);

}  // namespace isopound::detail
