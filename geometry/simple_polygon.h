// SimplePolygon: a plan of any simple outline (L-, T-, U-shaped floors and neighbours, issue 40)
// and its partition into convex pieces, the units the overlap's fast path works on
// (plan_overlap.h). Vertices counter-clockwise, metres, plan frame W.
//
// Partition: the outline without its collinear vertices, triangulated by ear clipping, then
// Hertel–Mehlhorn: a diagonal is removed when the two pieces it separates form a strictly convex
// polygon of at most kMaxPolygonVertices vertices (at most 4× the fewest convex pieces). A
// convex outline is one piece, the outline itself (so convex plans keep today's arithmetic).
// The pieces' internal edges (diagonals) are kept: an overlap's edge on a diagonal is inside the
// plan and never a contact chord.
#pragma once

#include <array>
#include <span>
#include <utility>
#include <vector>

#include "geometry/convex_polygon.h"

namespace isopound {

// Most vertices of a plan outline (a drawing's L or U with chamfers fits many times over).
inline constexpr int kMaxPlanVertices = 64;

// A segment of the plan frame, from `from` to `to`.
struct Segment2 {
  Vec2 from;
  Vec2 to;
};

// Invariants (checked on construction, InvalidPolygon naming the vertex): 3..kMaxPlanVertices
// finite vertices, no two equal, no edge touching or crossing a non-adjacent edge, no spike (an
// edge doubling back on the previous one), area > 0. Collinear vertices are allowed (drawings
// have them); clockwise input is reversed.
class SimplePolygon {
 public:
  explicit SimplePolygon(std::span<const Vec2> vertices);
  SimplePolygon(std::initializer_list<Vec2> vertices);
  SimplePolygon() = default;  // empty: only to be assigned or filled by placed_into

  int size() const { return int(vertices_.size()); }
  const Vec2& operator[](int i) const { return vertices_[i]; }
  std::span<const Vec2> vertices() const { return vertices_; }
  bool was_reversed() const { return reversed_; }
  // True when the outline (collinear vertices dropped) is convex: one piece.
  bool convex() const { return pieces_.size() == 1; }

  const std::vector<ConvexPolygon>& pieces() const { return pieces_; }
  // Internal edges between pieces, with the two pieces each separates.
  const std::vector<Segment2>& diagonals() const { return diagonals_; }
  const std::vector<std::pair<int, int>>& diagonal_pieces() const { return diagonal_pieces_; }
  // True when pieces p and q share a diagonal.
  bool adjacent(int p, int q) const;
  Vec2 box_min() const { return box_min_; }
  Vec2 box_max() const { return box_max_; }

  // This plan moved rigidly (as ConvexPolygon::placed), into `out`, whose storage is reused: no
  // allocation once `out` has held a placement of this plan.
  void placed_into(const Placement2& x, Vec2 about, SimplePolygon& out) const;
  SimplePolygon placed(const Placement2& x, Vec2 about = {0.0, 0.0}) const;

 private:
  void partition();
  void update_box();

  std::vector<Vec2> vertices_;
  bool reversed_ = false;
  std::vector<ConvexPolygon> pieces_;
  std::vector<Segment2> diagonals_;
  std::vector<std::pair<int, int>> diagonal_pieces_;
  Vec2 box_min_;
  Vec2 box_max_;
};

// Area, centroid and polar second moment about the centroid of the outline itself (shoelace
// about the vertex mean, as for a ConvexPolygon); the same numbers for a convex outline.
AreaProperties area_properties(const SimplePolygon& polygon);

// True when p is inside or on the outline (winding number).
bool contains(const SimplePolygon& polygon, Vec2 p);

}  // namespace isopound
