// Overlap of two simple plans from their convex pieces (plan_overlap.h for the method). Lengths
// are compared with a tolerance of kOnLineFraction of the pair's size: computed crossing points
// are rounded (~1e-13 relative at 10³ m), far below anything a drawing means.
#include "geometry/plan_overlap.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "geometry/outline_rules.h"
#include "geometry/overlap_finish.h"

namespace isopound {
namespace {

constexpr double kOnLineFraction = 1e-9;

double length(Vec2 v) {
  return std::hypot(v.x, v.y);
}

using detail::point_segment_distance_sq;  // squares: no square root in the inner loops

bool boxes_apart(Vec2 a_min, Vec2 a_max, Vec2 b_min, Vec2 b_max) {
  return a_max.x < b_min.x || b_max.x < a_min.x || a_max.y < b_min.y || b_max.y < a_min.y;
}

bool on_outline(const SimplePolygon& polygon, Vec2 p, double tolerance) {
  const int n = polygon.size();
  for (int i = 0; i < n; ++i)
    if (point_segment_distance_sq(p, polygon[i], polygon[i + 1 == n ? 0 : i + 1]) <=
        tolerance * tolerance)
      return true;
  return false;
}

// A segment lies on the outline when its ends and its midpoint do (an overlap's edge lies on one
// piece edge: a stretch of outline, possibly across collinear vertices, or a diagonal, whose
// interior is inside the plan).
bool segment_on_outline(const SimplePolygon& polygon, Vec2 p, Vec2 q, double tolerance) {
  return on_outline(polygon, p, tolerance) && on_outline(polygon, q, tolerance) &&
         on_outline(polygon, 0.5 * (p + q), tolerance);
}

// A segment on one of the plan's diagonals (inside the plan unless it is also on an outline).
bool segment_on_diagonal(const SimplePolygon& polygon, Vec2 p, Vec2 q, double tolerance) {
  const double t2 = tolerance * tolerance;
  for (const Segment2& d : polygon.diagonals())
    if (point_segment_distance_sq(p, d.from, d.to) <= t2 &&
        point_segment_distance_sq(q, d.from, d.to) <= t2)
      return true;
  return false;
}

// Whether some diagonal of the plan comes within `tolerance` of the overlap's bounding box.
bool near_a_diagonal(const SimplePolygon& polygon, const Overlap& o, double tolerance) {
  if (polygon.diagonals().empty() || o.vertex_count == 0) return false;
  Vec2 lo = o.vertices[0], hi = o.vertices[0];
  for (int k = 1; k < o.vertex_count; ++k) {
    lo = {std::min(lo.x, o.vertices[k].x), std::min(lo.y, o.vertices[k].y)};
    hi = {std::max(hi.x, o.vertices[k].x), std::max(hi.y, o.vertices[k].y)};
  }
  lo = lo - Vec2{tolerance, tolerance};
  hi = hi + Vec2{tolerance, tolerance};
  for (const Segment2& d : polygon.diagonals())
    if (!boxes_apart({std::min(d.from.x, d.to.x), std::min(d.from.y, d.to.y)},
                     {std::max(d.from.x, d.to.x), std::max(d.from.y, d.to.y)}, lo, hi))
      return true;
  return false;
}

// An edge of a piece overlap inside both plans: on a diagonal, off both outlines.
bool inside_edge(const SimplePolygon& a, const SimplePolygon& b, Vec2 p, Vec2 q, double tolerance) {
  if (!segment_on_diagonal(a, p, q, tolerance) && !segment_on_diagonal(b, p, q, tolerance))
    return false;
  return !segment_on_outline(a, p, q, tolerance) && !segment_on_outline(b, p, q, tolerance);
}

// Two convex overlaps glued along a common segment of positive length (on a diagonal).
bool share_segment(const Overlap& p, const Overlap& q, double tolerance) {
  for (int e = 0; e < p.vertex_count; ++e) {
    const Vec2 a = p.vertices[e], b = p.vertices[(e + 1) % p.vertex_count];
    const Vec2 d = b - a;
    const double l = length(d);
    if (l <= tolerance) continue;
    const Vec2 t = (1.0 / l) * d;
    for (int f = 0; f < q.vertex_count; ++f) {
      const Vec2 c = q.vertices[f], g = q.vertices[(f + 1) % q.vertex_count];
      if (std::abs(cross(t, c - a)) > tolerance || std::abs(cross(t, g - a)) > tolerance) continue;
      const double s0 = std::min(dot(t, c - a), dot(t, g - a));
      const double s1 = std::max(dot(t, c - a), dot(t, g - a));
      if (std::min(s1, l) - std::max(s0, 0.0) > tolerance) return true;
    }
  }
  return false;
}

struct PieceOverlap {
  int a_piece = 0;
  int b_piece = 0;
  int root = 0;  // union-find
  Overlap overlap;
};

struct BoundaryEdge {
  Vec2 from, to;
  bool on_a = false;
  bool used = false;
};

// Per-thread scratch: sized by the first plans a thread meets, then reused.
struct Workspace {
  std::vector<PieceOverlap> pieces;
  std::vector<BoundaryEdge> edges;
  std::vector<Vec2> chain;
  std::vector<bool> chain_on_a;
};

int root_of(std::vector<PieceOverlap>& p, int k) {
  while (p[k].root != k) k = p[k].root = p[p[k].root].root;
  return k;
}

// Fills `out` for the component whose piece overlaps have root `root`.
void finish_component(const SimplePolygon& a, const SimplePolygon& b, Workspace& w, int root,
                      double tolerance, Overlap& out) {
  double area = 0.0;
  Vec2 moment;
  int members = 0, largest = -1;
  for (int k = 0; k < int(w.pieces.size()); ++k) {
    if (root_of(w.pieces, k) != root) continue;
    const Overlap& o = w.pieces[k].overlap;
    ++members;
    area += o.area;
    moment = moment + o.area * o.p_WC;
    if (largest < 0 || o.area > w.pieces[largest].overlap.area) largest = k;
  }
  const Overlap& big = w.pieces[largest].overlap;
  if (members == 1) {     // one convex overlap, as it is unless an edge lies inside both plans
    bool inside = false;  // no diagonal near: every edge is on an outline
    if (near_a_diagonal(a, big, tolerance) || near_a_diagonal(b, big, tolerance))
      for (int e = 0; e < big.vertex_count && !inside; ++e)
        inside =
            inside_edge(a, b, big.vertices[e], big.vertices[(e + 1) % big.vertex_count], tolerance);
    if (!inside) {
      out = big;
      return;
    }
  }
  // The boundary: every piece overlap's edge that lies on A's or B's outline.
  w.edges.clear();
  for (int k = 0; k < int(w.pieces.size()); ++k) {
    if (root_of(w.pieces, k) != root) continue;
    const Overlap& o = w.pieces[k].overlap;
    for (int e = 0; e < o.vertex_count; ++e) {
      const Vec2 p = o.vertices[e], q = o.vertices[(e + 1) % o.vertex_count];
      if (length(q - p) <= tolerance) continue;
      if (inside_edge(a, b, p, q, tolerance)) continue;
      w.edges.push_back({p, q, segment_on_outline(a, p, q, tolerance), false});
    }
  }
  // Chained head to tail (counter-clockwise, as every piece overlap is), merging collinear runs
  // of one outline.
  w.chain.clear();
  w.chain_on_a.clear();
  for (std::size_t start = 0; start < w.edges.size(); ++start) {
    if (w.edges[start].used) continue;
    std::size_t k = start;
    while (!w.edges[k].used) {
      BoundaryEdge& e = w.edges[k];
      e.used = true;
      w.chain.push_back(e.from);
      w.chain_on_a.push_back(e.on_a);
      std::size_t next = k;
      for (std::size_t j = 0; j < w.edges.size(); ++j)
        if (!w.edges[j].used && length(w.edges[j].from - e.to) <= tolerance) {
          next = j;
          break;
        }
      if (next == k) break;
      k = next;
    }
  }
  // Drop the vertices inside a straight run of one outline.
  const int raw = int(w.chain.size());
  std::vector<Vec2>& c = w.chain;
  int kept = 0;
  std::array<Vec2, kMaxOverlapVertices> vertices_O;
  std::array<bool, kMaxOverlapVertices> on_a;
  const Vec2 origin = big.vertices[0];
  bool fits = true;
  for (int k = 0; k < raw; ++k) {
    const int prev = (k + raw - 1) % raw, next = (k + 1) % raw;
    const Vec2 e_in = c[k] - c[prev], e_out = c[next] - c[k];
    const bool straight =
        std::abs(cross(e_in, e_out)) <= tolerance * length(e_in) && dot(e_in, e_out) > 0.0;
    if (straight && w.chain_on_a[prev] == w.chain_on_a[k]) continue;
    if (kept == kMaxOverlapVertices) {
      fits = false;
      break;
    }
    vertices_O[kept] = c[k] - origin;
    on_a[kept] = w.chain_on_a[k];
    ++kept;
  }
  if (!fits || kept < 3) {
    // A boundary longer than an Overlap holds (or broken by round-off): the largest piece
    // overlap's plane, the component's area and centroid.
    out = big;
    out.area = area;
    out.p_WC = (1.0 / area) * moment;
    out.mean_depth *= area / big.area;
    out.indentation *= area / big.area;
    out.vertex_count = 0;
    return;
  }
  const Vec2 p_OC = (1.0 / area) * moment - origin;
  detail::finish_overlap(a.pieces()[w.pieces[largest].a_piece],
                         b.pieces()[w.pieces[largest].b_piece], origin,
                         std::span<const Vec2>(vertices_O.data(), kept),
                         std::span<const bool>(on_a.data(), kept), area, p_OC, out);
}

}  // namespace

void plan_overlap(const SimplePolygon& a, const SimplePolygon& b, PlanOverlap& out,
                  OverlapMethod method) {
  out.count = 0;
  out.dropped = 0;
  out.touching = false;
  if (boxes_apart(a.box_min(), a.box_max(), b.box_min(), b.box_max())) return;
  if (a.convex() && b.convex()) {
    Overlap& o = out.components[0];
    o = overlap_of(a.pieces()[0], b.pieces()[0], method);
    out.touching = o.kind == OverlapCase::kTouching;
    out.count = o.area > 0.0 ? 1 : 0;
    out.piece_pairs[0] = 1;
    return;
  }
  thread_local Workspace w;
  w.pieces.clear();
  const double size = std::max({a.box_max().x - a.box_min().x, a.box_max().y - a.box_min().y,
                                b.box_max().x - b.box_min().x, b.box_max().y - b.box_min().y});
  const double tolerance = kOnLineFraction * size;
  const auto& pa = a.pieces();
  const auto& pb = b.pieces();
  for (int i = 0; i < int(pa.size()); ++i)
    for (int j = 0; j < int(pb.size()); ++j) {
      if (boxes_apart(pa[i].box_min(), pa[i].box_max(), pb[j].box_min(), pb[j].box_max())) continue;
      const Overlap o = overlap_of(pa[i], pb[j], method);
      if (o.kind == OverlapCase::kTouching) out.touching = true;
      if (!(o.area > 0.0)) continue;
      const int k = int(w.pieces.size());
      w.pieces.push_back({i, j, k, o});
    }
  const int n = int(w.pieces.size());
  for (int p = 0; p < n; ++p)
    for (int q = p + 1; q < n; ++q) {
      const PieceOverlap& x = w.pieces[p];
      const PieceOverlap& y = w.pieces[q];
      const bool a_near = x.a_piece == y.a_piece || a.adjacent(x.a_piece, y.a_piece);
      const bool b_near = x.b_piece == y.b_piece || b.adjacent(x.b_piece, y.b_piece);
      if (!a_near || !b_near) continue;
      if (root_of(w.pieces, p) == root_of(w.pieces, q)) continue;
      if (share_segment(x.overlap, y.overlap, tolerance))
        w.pieces[root_of(w.pieces, q)].root = root_of(w.pieces, p);
    }
  for (int k = 0; k < n; ++k) {
    if (root_of(w.pieces, k) != k) continue;
    if (out.count == kMaxOverlapComponents) {
      ++out.dropped;
      continue;
    }
    std::uint64_t pairs = 0;
    for (int m = 0; m < n; ++m)
      if (root_of(w.pieces, m) == k)
        pairs |= piece_pair_bit(w.pieces[m].a_piece, w.pieces[m].b_piece, int(pb.size()));
    out.piece_pairs[out.count] = pairs;
    finish_component(a, b, w, k, tolerance, out.components[out.count++]);
  }
  if (out.count > 0) out.touching = false;
}

PlanOverlap plan_overlap(const SimplePolygon& a, const SimplePolygon& b, OverlapMethod method) {
  PlanOverlap out;
  plan_overlap(a, b, out, method);
  return out;
}

Separation plan_separation(const SimplePolygon& a, const SimplePolygon& b) {
  return plan_separation(a, b, 0);
}

Separation plan_separation(const SimplePolygon& a, const SimplePolygon& b, std::uint64_t excluded) {
  Separation best{std::numeric_limits<double>::infinity(), {}};
  const int nb = int(b.pieces().size());
  for (int i = 0; i < int(a.pieces().size()); ++i)
    for (int j = 0; j < nb; ++j) {
      if (excluded & piece_pair_bit(i, j, nb)) continue;
      const Separation s = separation_of(a.pieces()[i], b.pieces()[j]);
      if (s.distance < best.distance) best = s;
    }
  return best;
}

}  // namespace isopound
