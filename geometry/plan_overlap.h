// Overlap of two plans of any simple outline (issue 40): every connected component of A ∩ B is
// one contact with its own area, centroid and contact plane, from the crossings of the TRUE
// boundaries (a slab pressing into a re-entrant corner of a neighbour overlaps it in two places
// and gets two forces; an overlap cut by a piece's internal edge is still one contact).
//
// Method: A and B are unions of convex pieces (simple_polygon.h); each pair of pieces whose
// boxes meet gives a convex overlap (overlap.h, fast or exact); overlaps of neighbouring pieces
// that share a segment of a diagonal are one component (as sets they are glued along it); a
// component's boundary is its pieces' edges minus those inside A and B (on a diagonal, off both
// outlines), chained counter-clockwise and finished as a convex overlap is (overlap_finish.h:
// crossings, normal ⊥ the chord, δ_N). Two convex plans: exactly overlap_of (bit-identical).
// Choices (documented in docs/non-convex-plans.md): a component without exactly two crossings
// takes the least-penetration axis of its largest piece overlap; components touching only at a
// point are separate contacts.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "geometry/overlap.h"
#include "geometry/simple_polygon.h"

namespace isopound {

inline constexpr int kMaxOverlapComponents = 8;

struct PlanOverlap {
  // Components of A ∩ B with positive area, largest first is NOT guaranteed: in the order of
  // their first piece pair (A's pieces, then B's), which is stable while they persist.
  int count = 0;
  std::array<Overlap, kMaxOverlapComponents> components;
  // Which piece pairs (i of A, j of B) each component is made of: bit (i · B's pieces + j) mod 64
  // (two convex plans: bit 0). What lets a caller follow a component from one placement to the
  // next and tell which piece pairs another component already takes.
  std::array<std::uint64_t, kMaxOverlapComponents> piece_pairs{};
  // Components beyond kMaxOverlapComponents (never seen in a building's plans; counted so that a
  // caller can report them).
  int dropped = 0;
  // Common boundary points without common area (and no component).
  bool touching = false;
};

// A ∩ B of two placed plans, into `out` (a contact keeps one: a PlanOverlap is ~5 kB).
// Allocates nothing once the thread has met plans of this size.
void plan_overlap(const SimplePolygon& a, const SimplePolygon& b, PlanOverlap& out,
                  OverlapMethod method = OverlapMethod::kFast);
PlanOverlap plan_overlap(const SimplePolygon& a, const SimplePolygon& b,
                         OverlapMethod method = OverlapMethod::kFast);

// Signed separation of A and B: the least over piece pairs (the distance of the plans when
// apart, continuous, ≤ 0 exactly when they touch or overlap).
Separation plan_separation(const SimplePolygon& a, const SimplePolygon& b);
// The same, over the piece pairs whose bit (as PlanOverlap::piece_pairs) is not in `excluded`
// (distance +inf when none is left).
Separation plan_separation(const SimplePolygon& a, const SimplePolygon& b, std::uint64_t excluded);
// The bit of piece pair (i of A, j of B) in PlanOverlap::piece_pairs.
inline std::uint64_t piece_pair_bit(int i, int j, int b_pieces) {
  return std::uint64_t{1} << ((i * b_pieces + j) % 64);
}

// The reference: the components of A ∩ B from CGAL's Boolean set operations on the outlines in
// exact arithmetic (an algorithm independent of the pieces), each with its area (m²) and
// centroid rounded to double at the end, sorted by centroid x then y. For tests; allocates.
struct ComponentArea {
  double area = 0.0;
  Vec2 p_WC;
};
std::vector<ComponentArea> plan_overlap_areas_exact(const SimplePolygon& a, const SimplePolygon& b);

}  // namespace isopound
