// Fast overlap of two convex polygons: exact topology from CGAL's filtered orientation predicate
// (Epick) on the input coordinates, coordinates in double shifted near the overlap.
// Also the shared finishing step (crossings, case, normal n_AB from A into B, δ_N) and the SAT.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "geometry/overlap.h"
#include "geometry/overlap_finish.h"

namespace isopound {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;

// Sign of the turn p → q → r: +1 left (r left of the directed line pq), 0 collinear, −1 right.
// Exact for every input (CGAL's static filter, then interval and exact arithmetic if needed).
inline signed char turn(const Vec2& p, const Vec2& q, const Vec2& r) {
  return static_cast<signed char>(CGAL::orientation(
      Kernel::Point_2(p.x, p.y), Kernel::Point_2(q.x, q.y), Kernel::Point_2(r.x, r.y)));
}

// Plain sqrt, not hypot (slower): the lengths here are far from overflow or underflow.
inline double norm(Vec2 v) {
  return std::sqrt(dot(v, v));
}

bool boxes_disjoint(const ConvexPolygon& a, const ConvexPolygon& b) {
  return a.box_max().x < b.box_min().x || b.box_max().x < a.box_min().x ||
         a.box_max().y < b.box_min().y || b.box_max().y < a.box_min().y;
}

// Where segment a0→a1 crosses segment b0→b1 properly (the caller knows they do), in shifted
// coordinates. The parameter along a0→a1 comes from the two turns of its endpoints about the
// b-line, which have opposite signs, so the division never cancels and the point stays on a0a1.
Vec2 crossing_point(Vec2 a0, Vec2 a1, Vec2 b0, Vec2 b1) {
  const Vec2 d = b1 - b0;
  const double h0 = cross(d, a0 - b0);
  const double h1 = cross(d, a1 - b0);
  const double t = std::clamp(h0 / (h0 - h1), 0.0, 1.0);
  return a0 + t * (a1 - a0);
}

// A slot of the overlap walk: the overlap vertex where an edge's part inside the other polygon
// starts or ends. Setting it twice to different vertices would be a contradiction.
inline bool set_slot(signed char& slot, int id) {
  if (slot >= 0 && slot != id) return false;
  slot = static_cast<signed char>(id);
  return true;
}

}  // namespace

std::string_view to_string(OverlapCase c) {
  switch (c) {
    case OverlapCase::kSeparated:
      return "separated";
    case OverlapCase::kTouching:
      return "touching";
    case OverlapCase::kTwoCrossings:
      return "two_crossings";
    case OverlapCase::kMultipleCrossings:
      return "multiple_crossings";
    case OverlapCase::kContained:
      return "contained";
  }
  return "?";
}

namespace detail {

SatAxis least_penetration_axis(const ConvexPolygon& a, const ConvexPolygon& b, Vec2 origin) {
  SatAxis best{-std::numeric_limits<double>::infinity(), {}};
  // Edges of `face` against the vertices of `other`; `sign` orients the normal from A to B.
  auto scan = [&](const ConvexPolygon& face, const ConvexPolygon& other, double sign) {
    const int n = face.size();
    for (int k = 0; k < n; ++k) {
      const Vec2 p = face[k] - origin;
      const Vec2 e = face[k + 1 == n ? 0 : k + 1] - face[k];
      const double length = norm(e);
      const Vec2 m{e.y / length + 0.0, -e.x / length + 0.0};  // outward: right of the edge
      double s = std::numeric_limits<double>::infinity();
      for (const Vec2& q : other.vertices()) s = std::min(s, dot(m, (q - origin) - p));
      if (s > best.separation) best = {s, sign * m};
    }
  };
  scan(a, b, 1.0);
  scan(b, a, -1.0);
  return best;
}

void finish_overlap(const ConvexPolygon& a, const ConvexPolygon& b, Vec2 origin,
                    std::span<const Vec2> vertices_O, std::span<const bool> edge_on_a, double area,
                    Vec2 p_OC, Overlap& out) {
  const int count = int(vertices_O.size());
  if (count == 0) return;
  out.vertex_count = count;
  for (int k = 0; k < count; ++k) out.vertices[k] = origin + vertices_O[k];

  Vec2 p1_O, p2_O;  // crossing points relative to origin
  bool have_chord = false;
  if (count >= 3) {
    int transitions = 0, entry = -1, exit = -1;
    for (int k = 0; k < count; ++k) {
      const bool in_on_a = edge_on_a[(k + count - 1) % count];
      if (in_on_a == edge_on_a[k]) continue;
      ++transitions;
      // B's boundary then A's: A's boundary enters B here (P1); A's then B's: it leaves (P2).
      (edge_on_a[k] ? entry : exit) = k;
    }
    out.kind = transitions == 0   ? OverlapCase::kContained
               : transitions == 2 ? OverlapCase::kTwoCrossings
                                  : OverlapCase::kMultipleCrossings;
    if (transitions == 2) {
      p1_O = vertices_O[entry];
      p2_O = vertices_O[exit];
      const Vec2 chord = p2_O - p1_O;
      const double length = norm(chord);
      if (length > 0.0) {
        out.t_AB = {chord.x / length, chord.y / length};
        out.n_AB = {out.t_AB.y + 0.0, -out.t_AB.x + 0.0};  // + 0.0: no negative zeros
        out.chord_entry = entry;
        out.chord_exit = exit;
        have_chord = true;
      }
    }
    out.area = area;
    out.p_WC = origin + p_OC;
  } else {
    out.kind = OverlapCase::kTouching;
  }
  if (!have_chord) {
    out.n_AB = least_penetration_axis(a, b, origin).n_AB;
    out.t_AB = {-out.n_AB.y + 0.0, out.n_AB.x + 0.0};
    // Extreme vertices along the tangent.
    int lo = 0, hi = 0;
    for (int k = 1; k < count; ++k) {
      if (dot(out.t_AB, vertices_O[k]) < dot(out.t_AB, vertices_O[lo])) lo = k;
      if (dot(out.t_AB, vertices_O[k]) > dot(out.t_AB, vertices_O[hi])) hi = k;
    }
    p1_O = vertices_O[lo];
    p2_O = vertices_O[hi];
    if (count < 3) out.p_WC = origin + 0.5 * (p1_O + p2_O);
  }
  out.p_WP1 = origin + p1_O;
  out.p_WP2 = origin + p2_O;
  const double width = dot(out.t_AB, p2_O - p1_O);
  if (out.area > 0.0 && width > 0.0) {
    out.mean_depth = out.area / width;
    out.indentation = (count == 3 ? 2.0 : 1.0) * out.mean_depth;
  }
}

// Pseudocode of the fast path:
//   reject on bounding boxes;
//   turn signs of every vertex of A about every edge of B and vice versa (exact); an edge with
//     all of the other polygon strictly outside separates them (SAT, exact);
//   the vertices of A ∩ B are exactly: A's vertices in closed B, B's vertices in closed A (one
//     copy of a vertex shared by both), and the proper crossings of an A edge with a B edge;
//   each edge of A (of B) holds the part of A ∩ B's boundary between a "start" and an "end" of
//     those vertices, told apart by turn signs only; linking start → end on every edge gives
//     the counter-clockwise cycle of A ∩ B, each link labelled A or B;
//   coordinates: crossings, area and centroid (triangle fan) in double about the box overlap.
bool overlap_fast(const ConvexPolygon& a, const ConvexPolygon& b, Overlap& out) {
  if (boxes_disjoint(a, b)) return true;
  constexpr int kMax = kMaxPolygonVertices;
  const int n = a.size(), m = b.size();
  // side_of_b[i][j]: turn of A's vertex i about B's edge j (b_j → b_j+1): +1 inside its
  // half-plane, 0 on its line, −1 outside. side_of_a[j][i]: B's vertex j about A's edge i.
  signed char side_of_b[kMax][kMax], side_of_a[kMax][kMax];
  for (int j = 0; j < m; ++j) {
    const Vec2& b0 = b[j];
    const Vec2& b1 = b[j + 1 == m ? 0 : j + 1];
    bool all_outside = true;
    for (int i = 0; i < n; ++i) {
      side_of_b[i][j] = turn(b0, b1, a[i]);
      all_outside = all_outside && side_of_b[i][j] < 0;
    }
    if (all_outside) return true;
  }
  for (int i = 0; i < n; ++i) {
    const Vec2& a0 = a[i];
    const Vec2& a1 = a[i + 1 == n ? 0 : i + 1];
    bool all_outside = true;
    for (int j = 0; j < m; ++j) {
      side_of_a[j][i] = turn(a0, a1, b[j]);
      all_outside = all_outside && side_of_a[j][i] < 0;
    }
    if (all_outside) return true;
  }

  // Shift near the overlap: differences of nearby doubles are exact (Sterbenz), so the
  // crossings, area and centroid below carry round-off relative to the overlap, not to |p_W|.
  const Vec2 origin{
      0.5 * (std::max(a.box_min().x, b.box_min().x) + std::min(a.box_max().x, b.box_max().x)),
      0.5 * (std::max(a.box_min().y, b.box_min().y) + std::min(a.box_max().y, b.box_max().y))};

  VertexArray<kMaxOverlapVertices> vertex_O;  // overlap vertices, shifted, unordered
  OverlapVertexSource source[kMaxOverlapVertices];
  int count = 0;
  signed char id_a[kMax], id_b[kMax];  // overlap vertex at A's (B's) vertex, or −1
  signed char own_b[kMax];             // 1 when B's vertex j is not also one of A's vertices
  for (int i = 0; i < n; ++i) {
    bool inside = true;
    for (int j = 0; j < m && inside; ++j) inside = side_of_b[i][j] >= 0;
    id_a[i] = -1;
    if (inside) {
      id_a[i] = static_cast<signed char>(count);
      source[count] = {OverlapVertexKind::kVertexOfA, static_cast<signed char>(i), -1};
      vertex_O[count++] = a[i] - origin;
    }
  }
  for (int j = 0; j < m; ++j) {
    bool inside = true, on_boundary = false;
    for (int i = 0; i < n && inside; ++i) {
      inside = side_of_a[j][i] >= 0;
      on_boundary = on_boundary || side_of_a[j][i] == 0;
    }
    id_b[j] = -1;
    own_b[j] = 0;
    if (!inside) continue;
    if (on_boundary) {  // it may be one of A's vertices (then that one stands for both)
      for (int i = 0; i < n; ++i) {
        if (id_a[i] >= 0 && a[i].x == b[j].x && a[i].y == b[j].y) id_b[j] = id_a[i];
      }
    }
    if (id_b[j] < 0) {
      if (count == kMaxOverlapVertices) return false;
      id_b[j] = static_cast<signed char>(count);
      own_b[j] = 1;
      source[count] = {OverlapVertexKind::kVertexOfB, -1, static_cast<signed char>(j)};
      vertex_O[count++] = b[j] - origin;
    }
  }

  // Where each edge's part inside the other polygon starts and ends (overlap vertex ids).
  signed char start_a[kMax], end_a[kMax], start_b[kMax], end_b[kMax];
  std::fill_n(start_a, n, -1);
  std::fill_n(end_a, n, -1);
  std::fill_n(start_b, m, -1);
  std::fill_n(end_b, m, -1);
  bool consistent = true;
  for (int i = 0; i < n; ++i) {
    if (id_a[i] < 0) continue;
    consistent &= set_slot(start_a[i], id_a[i]);
    consistent &= set_slot(end_a[i == 0 ? n - 1 : i - 1], id_a[i]);
  }
  for (int j = 0; j < m; ++j) {
    if (id_b[j] < 0) continue;
    consistent &= set_slot(start_b[j], id_b[j]);
    consistent &= set_slot(end_b[j == 0 ? m - 1 : j - 1], id_b[j]);
  }
  // Proper crossings: each edge strictly straddles the other's line.
  for (int i = 0; i < n; ++i) {
    const int i1 = i + 1 == n ? 0 : i + 1;
    for (int j = 0; j < m; ++j) {
      const int j1 = j + 1 == m ? 0 : j + 1;
      if (side_of_b[i][j] * side_of_b[i1][j] >= 0 || side_of_a[j][i] * side_of_a[j1][i] >= 0) {
        continue;
      }
      if (count == kMaxOverlapVertices) return false;
      const int id = count;
      source[count] = {OverlapVertexKind::kCrossing, static_cast<signed char>(i),
                       static_cast<signed char>(j)};
      vertex_O[count++] =
          crossing_point(a[i] - origin, a[i1] - origin, b[j] - origin, b[j1] - origin);
      // A's edge enters B where its start vertex is outside B's edge line; likewise for B.
      consistent &= set_slot(side_of_b[i][j] < 0 ? start_a[i] : end_a[i], id);
      consistent &= set_slot(side_of_a[j][i] < 0 ? start_b[j] : end_b[j], id);
    }
  }
  // A vertex of one polygon inside an edge of the other: it starts that edge's part inside if
  // the edge, continued forwards, runs into its polygon's corner (both incident half-planes).
  for (int j = 0; j < m; ++j) {
    if (!own_b[j]) continue;
    const int jm = j == 0 ? m - 1 : j - 1;
    for (int i = 0; i < n; ++i) {
      if (side_of_a[j][i] != 0) continue;
      const int i1 = i + 1 == n ? 0 : i + 1;
      if (side_of_b[i1][j] >= 0 && side_of_b[i1][jm] >= 0) {
        consistent &= set_slot(start_a[i], id_b[j]);
      }
      if (side_of_b[i][j] >= 0 && side_of_b[i][jm] >= 0) {
        consistent &= set_slot(end_a[i], id_b[j]);
      }
    }
  }
  for (int i = 0; i < n; ++i) {
    if (id_a[i] < 0) continue;
    const int im = i == 0 ? n - 1 : i - 1;
    for (int j = 0; j < m; ++j) {
      const int j1 = j + 1 == m ? 0 : j + 1;
      if (side_of_b[i][j] != 0 || id_b[j] == id_a[i] || id_b[j1] == id_a[i]) continue;
      if (side_of_a[j1][i] >= 0 && side_of_a[j1][im] >= 0) {
        consistent &= set_slot(start_b[j], id_a[i]);
      }
      if (side_of_a[j][i] >= 0 && side_of_a[j][im] >= 0) {
        consistent &= set_slot(end_b[j], id_a[i]);
      }
    }
  }
  if (!consistent || count == 0) return false;

  // Link start → end along every edge; a link along both boundaries (shared edge) is A's.
  signed char next[kMaxOverlapVertices];
  bool on_a[kMaxOverlapVertices];
  std::fill_n(next, count, -1);
  auto link = [&](int from, int to, bool along_a) {
    if (from < 0 || to < 0 || from == to) return true;
    if (next[from] < 0) {
      next[from] = static_cast<signed char>(to);
      on_a[from] = along_a;
      return true;
    }
    on_a[from] = on_a[from] || along_a;
    return next[from] == to;
  };
  for (int i = 0; i < n; ++i) consistent &= link(start_a[i], end_a[i], true);
  for (int j = 0; j < m; ++j) consistent &= link(start_b[j], end_b[j], false);
  if (!consistent) return false;

  VertexArray<kMaxOverlapVertices> ordered;
  bool edge_on_a[kMaxOverlapVertices];
  double area = 0.0;
  Vec2 p_OC;
  if (count <= 2) {  // a common point or segment: touching
    for (int k = 0; k < count; ++k) ordered[k] = vertex_O[k];
  } else {
    int k = 0;
    for (int v = 0; k < count; ++k) {
      if (v < 0 || (k > 0 && v == 0)) return false;
      ordered[k] = vertex_O[v];
      out.sources[k] = source[v];
      edge_on_a[k] = on_a[v];
      v = next[v];
      if (k == count - 1 && v != 0) return false;
    }
    // Triangle fan about the first vertex: round-off relative to the overlap's own size. For a
    // sliver as thin as the round-off a fan triangle may come out negative: the centroid uses
    // the weights clamped at 0 (then the vertex mean), so it stays a convex combination of
    // points of A ∩ B — inside it — however ill-conditioned its position along the sliver.
    double twice_area = 0.0, weight_sum = 0.0;
    Vec2 moment, vertex_sum = ordered[0];
    for (int q = 1; q + 1 < count; ++q) {
      const Vec2 d1 = ordered[q] - ordered[0], d2 = ordered[q + 1] - ordered[0];
      const double w = cross(d1, d2);
      twice_area += w;
      weight_sum += std::max(w, 0.0);
      moment = moment + std::max(w, 0.0) * (d1 + d2);
      vertex_sum = vertex_sum + ordered[q];
    }
    vertex_sum = vertex_sum + ordered[count - 1];
    area = std::max(0.5 * twice_area, 0.0);
    p_OC = weight_sum > 0.0 ? ordered[0] + (1.0 / (3.0 * weight_sum)) * moment
                            : (1.0 / count) * vertex_sum;
  }
  finish_overlap(a, b, origin, std::span<const Vec2>(ordered.data(), count),
                 std::span<const bool>(edge_on_a, count), area, p_OC, out);
  out.sources_known = count > 2;
  return true;
}

}  // namespace detail

Overlap overlap_of(const ConvexPolygon& a, const ConvexPolygon& b) {
  Overlap out;
  if (boxes_disjoint(a, b)) return out;
  // The fallback has never been taken (tests count it); it is there so that a contradiction
  // in the fast path's topology could never give a wrong polygon.
  if (!detail::overlap_fast(a, b, out)) out = overlap_of_exact(a, b);
  return out;
}

Separation separation_of(const ConvexPolygon& a, const ConvexPolygon& b) {
  const Vec2 origin = 0.5 * (a[0] + b[0]);
  const detail::SatAxis axis = detail::least_penetration_axis(a, b, origin);
  if (axis.separation <= 0.0) return {axis.separation, axis.n_AB};
  // Apart: the Euclidean distance, the least over vertex–edge pairs of both polygons.
  double best_sq = std::numeric_limits<double>::infinity();
  Vec2 best_gap;
  double best_sign = 1.0;
  auto scan = [&](const ConvexPolygon& edges, const ConvexPolygon& points, double sign) {
    const int n = edges.size();
    for (int k = 0; k < n; ++k) {
      const Vec2 p = edges[k] - origin;
      const Vec2 e = edges[k + 1 == n ? 0 : k + 1] - edges[k];
      const double ee = dot(e, e);
      for (const Vec2& q_W : points.vertices()) {
        const Vec2 q = q_W - origin;
        const double s = std::clamp(dot(q - p, e) / ee, 0.0, 1.0);
        const Vec2 gap = q - (p + s * e);  // from the edge to the point
        const double distance_sq = dot(gap, gap);
        if (distance_sq < best_sq) {
          best_sq = distance_sq;
          best_gap = gap;
          best_sign = sign;
        }
      }
    }
  };
  scan(a, b, 1.0);
  scan(b, a, -1.0);
  const double distance = std::sqrt(best_sq);
  return {distance, {best_sign * best_gap.x / distance, best_sign * best_gap.y / distance}};
}

}  // namespace isopound
