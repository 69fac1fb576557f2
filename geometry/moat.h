// Walls that follow a plan's outline at a gap (issue 40): one wall per straight run of the
// outline (collinear vertices do not split a wall), the band between the offsets `gap` and
// `gap + thickness` outward of the run. At a convex corner each wall runs on `extension` beyond
// it, as the four sides of a rectangular slab's moat do (so a rectangle gets today's four walls);
// at a re-entrant corner the two walls meet on the line through the corners of their faces
// (mitred), so that no region belongs to both and a slab in the corner meets each wall once.
#pragma once

#include <utility>
#include <vector>

#include "geometry/convex_polygon.h"
#include "geometry/simple_polygon.h"

namespace isopound {

struct MoatWall {
  ConvexPolygon outline;  // counter-clockwise, plan frame W, m
  Vec2 p_WS;              // the plan's run this wall faces: its start ...
  Vec2 p_WE;              // ... and end vertex (counter-clockwise along the plan)
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

}  // namespace isopound
