// Overlap of two convex polygons in plan (area, centroid, boundary crossings, contact normal,
// indentation δ_N) and their signed separation: the geometry of 3D slab-to-slab contact (§6).
// Conventions: n_AB points from A into B (a force along +n_AB on B pushes the bodies apart);
// t_AB is n_AB turned +90°; separation < 0 is penetration depth. Details: THEORY-notes.md.
#pragma once

#include <array>
#include <span>
#include <string_view>

#include "geometry/convex_polygon.h"

namespace isopound {

// Two convex polygons of ≤ N_a and ≤ N_b vertices meet in at most N_a + N_b vertices.
inline constexpr int kMaxOverlapVertices = 2 * kMaxPolygonVertices;

// Which situation an Overlap describes (decided with exact predicates: never a rounding artefact).
enum class OverlapCase {
  kSeparated,          // no common point; every other field is zero
  kTouching,           // common boundary points (a point or a segment), zero area
  kTwoCrossings,       // the usual contact: the boundaries cross at exactly two points P1, P2
  kMultipleCrossings,  // the boundaries cross at 4, 6, ... points (deep or crosswise overlap)
  kContained,          // positive area, no crossing: one polygon inside the other (or equal)
};
std::string_view to_string(OverlapCase c);  // "separated", "touching", "two_crossings", ...

// Where a vertex of A ∩ B comes from: A's vertex `a`, B's vertex `b`, or the crossing of A's edge
// a → a+1 with B's edge b → b+1 (indices into the polygons as given, −1 where unused). With the
// sources a caller can follow the same vertices as the polygons move (a derivative of the overlap
// with its topology held).
enum class OverlapVertexKind : signed char { kVertexOfA, kVertexOfB, kCrossing };
struct OverlapVertexSource {
  OverlapVertexKind kind;
  signed char a, b;
};

// The overlap A ∩ B as a plain value. Lengths in metres, plan frame W.
struct Overlap {
  OverlapCase kind = OverlapCase::kSeparated;
  // A_c = area of A ∩ B, m², ≥ 0 (0 unless kTwoCrossings, kMultipleCrossings or kContained).
  double area = 0.0;
  // C: centroid of A ∩ B (the action point of the contact force). For kTouching the midpoint of
  // the common segment (or the common point).
  Vec2 p_WC;
  // Crossing points. kTwoCrossings: P1 is where A's boundary, run counter-clockwise, enters B and
  // P2 where it leaves B, so A's boundary from P1 to P2 is the part of A inside B. Other cases
  // with a common point: the extreme points of A ∩ B along t_AB (P1 at the lower end).
  Vec2 p_WP1;
  Vec2 p_WP2;
  // Unit contact normal, pointing from A into B: moving B along +n_AB (or A along −n_AB)
  // separates them. kTwoCrossings: ⊥ P1P2, n_AB = (P2 − P1) turned −90°, normalised (the side of
  // the chord where A's boundary inside B lies). Otherwise the axis of least penetration (the edge
  // normal of A or B with the largest SAT separation, oriented from A to B). Zero when kSeparated.
  Vec2 n_AB;
  // Unit tangent of the contact plane, n_AB turned +90° (= (P2 − P1)/|P2 − P1| for kTwoCrossings).
  Vec2 t_AB;
  // Equivalent indentation δ_N, m (thesis eq. 5.20): 2A_c/w for a triangular overlap, A_c/w for
  // any other (quadrilateral and up), w = |P1P2| measured along t_AB; 0 when A_c = 0.
  double indentation = 0.0;
  // The mean depth A_c/w for every shape (continuous where δ_N jumps by 2× as a triangle turns
  // into a quadrilateral): the alternative to δ_N a contact model may choose. 0 when A_c = 0.
  double mean_depth = 0.0;
  // Vertices of A ∩ B, counter-clockwise: vertex_count of them (0 separated, 1–2 touching).
  int vertex_count = 0;
  VertexArray<kMaxOverlapVertices> vertices;  // the first vertex_count are set
  // kTwoCrossings: P1 and P2 are vertices[chord_entry] and vertices[chord_exit]; else −1.
  int chord_entry = -1, chord_exit = -1;
  // The fast path (overlap_of) only: each vertex's source, the first vertex_count (unset when
  // sources_known is false: the exact path, a touching or separated pair).
  bool sources_known = false;
  std::array<OverlapVertexSource, kMaxOverlapVertices> sources;
};

// Overlap on the fast path: bounding-box rejection, then topology (which vertex is inside, which
// edges cross, the order of the overlap's vertices) from CGAL's filtered exact orientation
// predicates on the input coordinates, and coordinates (crossing points, area, centroid) in
// double shifted near the overlap. No allocation (CGAL's predicate falls back to exact
// arithmetic, which may, only for inputs within round-off of a degeneracy).
Overlap overlap_of(const ConvexPolygon& a, const ConvexPolygon& b);

// The same overlap with exact rational arithmetic (CGAL::Exact_rational) and an independent
// algorithm (Sutherland–Hodgman clipping); results rounded to double at the end. The reference
// for tests, and an option for whole analyses. Allocates; ~130× slower (~30 µs for two
// quadrilaterals).
Overlap overlap_of_exact(const ConvexPolygon& a, const ConvexPolygon& b);

enum class OverlapMethod { kFast, kExact };
inline Overlap overlap_of(const ConvexPolygon& a, const ConvexPolygon& b, OverlapMethod method) {
  return method == OverlapMethod::kExact ? overlap_of_exact(a, b) : overlap_of(a, b);
}

// Signed separation of A and B, a continuous witness of contact onset.
struct Separation {
  // > 0: Euclidean distance between the polygons; ≤ 0: −(penetration depth), the shortest
  // translation that separates them (the largest SAT separation over all edge normals).
  // Continuous in the placement; 0 exactly when they touch.
  double distance = 0.0;
  // Unit direction from A to B: moving B by (−distance)·n_AB (when ≤ 0) just separates them;
  // when > 0, the direction from A's closest point to B's closest point.
  Vec2 n_AB;
};
Separation separation_of(const ConvexPolygon& a, const ConvexPolygon& b);

}  // namespace isopound
