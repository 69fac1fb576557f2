// Exact overlap of two convex polygons: Sutherland–Hodgman clipping of A by B's closed
// half-planes in rational arithmetic (CGAL::Exact_rational), rounded to double at the end.
// Independent of the fast path's algorithm; shares only the finishing step (overlap_finish.h).
#include <CGAL/Exact_rational.h>

#include <vector>

#include "geometry/overlap.h"
#include "geometry/overlap_finish.h"

namespace isopound {
namespace {

using Q = CGAL::Exact_rational;

struct QPoint {
  Q x, y;
};

QPoint exact(Vec2 p) {
  return {Q(p.x), Q(p.y)};
}

// Sign of the turn p → q → r (+1 left, 0 collinear, −1 right), exactly.
int turn(const QPoint& p, const QPoint& q, const QPoint& r) {
  const Q c = (q.x - p.x) * (r.y - p.y) - (q.y - p.y) * (r.x - p.x);
  return c > 0 ? 1 : (c < 0 ? -1 : 0);
}

// A directed line through two input vertices (an edge of A or of B).
struct Line {
  QPoint from, to;
};

// Where line `s` meets line `clip` (not parallel). Built from input coordinates only, so the
// rationals stay small however many clips came before.
QPoint meet(const Line& s, const Line& clip) {
  const Q dx = clip.to.x - clip.from.x, dy = clip.to.y - clip.from.y;
  const Q ex = s.to.x - s.from.x, ey = s.to.y - s.from.y;
  const Q t = (dx * (clip.from.y - s.from.y) - dy * (clip.from.x - s.from.x)) / (dx * ey - dy * ex);
  return {s.from.x + t * ex, s.from.y + t * ey};
}

bool same(const QPoint& p, const QPoint& q) {
  return p.x == q.x && p.y == q.y;
}

// A vertex of the clipped polygon and the line its outgoing edge lies on.
struct ClipVertex {
  QPoint p;
  int line;
};

}  // namespace

Overlap overlap_of_exact(const ConvexPolygon& a, const ConvexPolygon& b) {
  const int n = a.size(), m = b.size();
  std::vector<Line> lines;  // A's edges 0..n−1, then B's edges n..n+m−1
  for (int i = 0; i < n; ++i) lines.push_back({exact(a[i]), exact(a[(i + 1) % n])});
  for (int j = 0; j < m; ++j) lines.push_back({exact(b[j]), exact(b[(j + 1) % m])});

  std::vector<ClipVertex> polygon, clipped;
  for (int i = 0; i < n; ++i) polygon.push_back({lines[i].from, i});
  for (int j = 0; j < m && !polygon.empty(); ++j) {
    const Line& clip = lines[n + j];
    clipped.clear();
    const int count = int(polygon.size());
    std::vector<int> side(count);
    for (int k = 0; k < count; ++k) side[k] = turn(clip.from, clip.to, polygon[k].p);
    for (int k = 0; k < count; ++k) {
      const int k1 = (k + 1) % count;
      const ClipVertex& s = polygon[k];
      if (side[k] >= 0) {  // kept; from a vertex on the clip line the edge may go on along it
        clipped.push_back({s.p, side[k] == 0 && side[k1] < 0 ? n + j : s.line});
      }
      if (side[k] < 0 && side[k1] > 0) clipped.push_back({meet(lines[s.line], clip), s.line});
      if (side[k] > 0 && side[k1] < 0) clipped.push_back({meet(lines[s.line], clip), n + j});
    }
    polygon.swap(clipped);
  }

  // Clean up: no repeated vertex, no vertex on the segment of its neighbours.
  std::vector<QPoint> v;
  for (const ClipVertex& c : polygon) {
    if (v.empty() || !same(v.back(), c.p)) v.push_back(c.p);
  }
  while (v.size() > 1 && same(v.front(), v.back())) v.pop_back();
  Q twice_area = 0;
  for (size_t k = 1; k + 1 < v.size(); ++k) {
    twice_area +=
        (v[k].x - v[0].x) * (v[k + 1].y - v[0].y) - (v[k].y - v[0].y) * (v[k + 1].x - v[0].x);
  }
  if (twice_area > 0) {
    for (bool removed = true; removed && v.size() > 3;) {
      removed = false;
      for (size_t k = 0; k < v.size(); ++k) {
        if (turn(v[(k + v.size() - 1) % v.size()], v[k], v[(k + 1) % v.size()]) == 0) {
          v.erase(v.begin() + long(k));
          removed = true;
          break;
        }
      }
    }
  } else if (!v.empty()) {
    // Zero area: the common set is a point or a segment; keep its two ends.
    auto less = [](const QPoint& p, const QPoint& q) {
      return p.x < q.x || (p.x == q.x && p.y < q.y);
    };
    QPoint lo = v[0], hi = v[0];
    for (const QPoint& p : v) {
      if (less(p, lo)) lo = p;
      if (less(hi, p)) hi = p;
    }
    v = same(lo, hi) ? std::vector<QPoint>{lo} : std::vector<QPoint>{lo, hi};
  }
  if (v.empty()) return Overlap{};
  if (v.size() > size_t(kMaxOverlapVertices)) v.resize(kMaxOverlapVertices);  // cannot happen

  // Edge labels: an edge lies on A's boundary when both ends are on one of A's edge lines.
  const int count = int(v.size());
  bool edge_on_a[kMaxOverlapVertices] = {};
  if (twice_area > 0) {
    for (int k = 0; k < count; ++k) {
      const QPoint& p = v[k];
      const QPoint& q = v[(k + 1) % count];
      for (int i = 0; i < n && !edge_on_a[k]; ++i) {
        edge_on_a[k] =
            turn(lines[i].from, lines[i].to, p) == 0 && turn(lines[i].from, lines[i].to, q) == 0;
      }
    }
  }

  // Round to double about the first vertex (differences taken exactly, then rounded).
  const Vec2 origin{CGAL::to_double(v[0].x), CGAL::to_double(v[0].y)};
  const QPoint origin_q = exact(origin);
  std::array<Vec2, kMaxOverlapVertices> vertices_O;
  for (int k = 0; k < count; ++k) {
    vertices_O[k] = {CGAL::to_double(v[k].x - origin_q.x), CGAL::to_double(v[k].y - origin_q.y)};
  }
  double area = 0.0;
  Vec2 p_OC;
  if (twice_area > 0) {
    Q cx = 0, cy = 0;
    for (int k = 1; k + 1 < count; ++k) {
      const Q x1 = v[k].x - origin_q.x, y1 = v[k].y - origin_q.y;
      const Q x2 = v[k + 1].x - origin_q.x, y2 = v[k + 1].y - origin_q.y;
      const Q x0 = v[0].x - origin_q.x, y0 = v[0].y - origin_q.y;
      const Q w = (x1 - x0) * (y2 - y0) - (y1 - y0) * (x2 - x0);
      cx += w * (x0 + x1 + x2);
      cy += w * (y0 + y1 + y2);
    }
    area = CGAL::to_double(twice_area / 2);
    p_OC = {CGAL::to_double(cx / (3 * twice_area)), CGAL::to_double(cy / (3 * twice_area))};
  }
  Overlap out;
  detail::finish_overlap(a, b, origin, std::span<const Vec2>(vertices_O.data(), count),
                         std::span<const bool>(edge_on_a, count), area, p_OC, out);
  return out;
}

}  // namespace isopound
