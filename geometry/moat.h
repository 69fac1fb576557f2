// Walls that follow a plan's outline at a gap (issue 40): one wall per straight run of the
// outline (collinear vertices do not split a wall), the band between the offsets `gap` and
// `gap + thickness` outward of the run. At a convex corner each wall runs on `extension` beyond
// it, as the four sides of a rectangular slab's moat do (so a rectangle gets today's four walls);
// at a re-entrant corner the two walls meet on the line through the corners of their faces
// (mitred), so that no region belongs to both and a slab in the corner meets each wall once.
#pragma once

#include <span>
#include <utility>
#include <vector>

#include "geometry/convex_polygon.h"
#include "geometry/simple_polygon.h"

namespace isopound {

struct MoatWall {
  ConvexPolygon outline;  // counter-clockwise, plan frame W, m
  Vec2 p_WS;              // the run this wall faces (the plan's, or a polyline wall's own face):
  Vec2 p_WE;              // its start and end, the wall to the run's right
};

// The straight runs of the outline (collinear vertices dropped), counter-clockwise: start and
// end vertex of each, in the order following_moat gives their walls.
std::vector<std::pair<Vec2, Vec2>> outline_runs(const SimplePolygon& plan);

// Throws InvalidPolygon when a wall would be degenerate (a run shorter than the mitres of its
// re-entrant corners need at this gap and thickness), naming the run's first vertex.
std::vector<MoatWall> following_moat(const SimplePolygon& plan, double gap, double thickness,
                                     double extension);
// Each run at its own gap (gaps[k] for outline_runs(plan)[k]): at a re-entrant corner the two
// walls' faces meet where the two offset lines cross, their back faces likewise.
std::vector<MoatWall> following_moat(const SimplePolygon& plan, const std::vector<double>& gaps,
                                     double thickness, double extension);
// ... and each its own thickness (thicknesses[k]): the back faces meet where their offsets cross.
std::vector<MoatWall> following_moat(const SimplePolygon& plan, const std::vector<double>& gaps,
                                     const std::vector<double>& thicknesses, double extension);

// Walls along a polyline of their own (walls: {follow: polyline}), not derived from a slab: one
// wall per straight run of `line` (collinear vertices dropped), in the order drawn, the band
// between the run (its face) and the run's offset `thickness` to its right (to its left with
// walls_left), so a polyline drawn counter-clockwise around a slab has its walls outside it, as a
// following moat's. Where two runs meet, their walls
// are mitred (cut on the line through the face's corner and the crossing of their backs), so no
// region belongs to both and none is left between them; the polyline's two ends are square.
// Throws InvalidPolygon naming the vertex (index in `line`) when there are fewer than two
// distinct points, a vertex repeats, the line turns back along itself, or a run is too short for
// its mitres at this thickness.
std::vector<MoatWall> polyline_walls(std::span<const Vec2> line, double thickness,
                                     bool walls_left = false);
// ... each run's wall its own thickness (thicknesses[k] for polyline_runs(line)[k]): where two
// runs meet, the backs' offsets cross at the mitre.
std::vector<MoatWall> polyline_walls(std::span<const Vec2> line,
                                     const std::vector<double>& thicknesses, bool walls_left);
// The straight runs of `line` (collinear points dropped), start and end point of each in the
// order drawn, as polyline_walls gives their walls; throws as it does.
std::vector<std::pair<Vec2, Vec2>> polyline_runs(std::span<const Vec2> line);
// Whether `polygon` lies to the left of the open polyline `line` as drawn: the side its vertex
// nearest the line lies on, at the run that vertex is nearest (on the line: left). The side a
// polyline's walls do not stand on (walls: {follow: polyline}).
bool lies_left_of(std::span<const Vec2> polygon, std::span<const Vec2> line);

// A straight wall's extent across its normal n (unit, from the slab into the wall): [lo, hi] of
// t·x over its corners, t = (−n_y, n_x), and its face, the least n·x of its corners.
struct WallExtent {
  double lo = 0.0, hi = 0.0;  // m along t
  double face = 0.0;          // m along n
};
WallExtent wall_extent(std::span<const Vec2> wall, Vec2 n);

// The clearance of a straight wall from a slab along the wall's normal n (unit, from the slab
// into the wall), over the wall's extent across n: the wall's face (the least n·x of its
// corners) less the slab's furthest point along n within that extent (a vertex inside it, or
// where an edge crosses its bounds), and that point. +inf (p_WA unset) when no part of the slab
// lies across the wall's extent. `slab` may be any simple polygon.
struct NormalClearance {
  double clearance = 0.0;  // m; negative: the slab reaches past the wall's face
  Vec2 p_WA;               // the slab's point nearest the face along n
};
NormalClearance normal_clearance(std::span<const Vec2> slab, std::span<const Vec2> wall, Vec2 n);

}  // namespace isopound
