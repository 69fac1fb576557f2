// SimplePolygon: validation of any simple outline (messages name the vertex or the two edges),
// its convex partition (ear clipping, then Hertel–Mehlhorn), rigid placement and area
// properties. Tolerances as ConvexPolygon's: a turn with |sin| below kCollinearSine is straight,
// vertices closer than kRepeatedFraction of the plan's size are the same vertex.
#include "geometry/simple_polygon.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>

#include "geometry/outline_rules.h"

namespace isopound {
namespace {

using detail::kCollinearSine;
using detail::kRepeatedFraction;
using detail::turn_sine;
// Two non-adjacent edges closer than this fraction of the plan's size touch: the outline is not
// simple (a drawing's separate rooms joined at a point, or a notch closed to nothing).
constexpr double kTouchingFraction = 1e-9;

double length(Vec2 a) {
  return std::hypot(a.x, a.y);
}

double point_segment_distance(Vec2 p, Vec2 a, Vec2 b) {
  return std::sqrt(detail::point_segment_distance_sq(p, a, b));
}

// Segments ab and cd cross at a point inside both (strict signs: not at an end, not collinear).
bool properly_cross(Vec2 a, Vec2 b, Vec2 c, Vec2 d) {
  const double s1 = cross(b - a, c - a), s2 = cross(b - a, d - a);
  const double s3 = cross(d - c, a - c), s4 = cross(d - c, b - c);
  return ((s1 > 0 && s2 < 0) || (s1 < 0 && s2 > 0)) && ((s3 > 0 && s4 < 0) || (s3 < 0 && s4 > 0));
}

// Distance between segments ab and cd (0 when they cross).
double segment_distance(Vec2 a, Vec2 b, Vec2 c, Vec2 d) {
  if (properly_cross(a, b, c, d)) return 0.0;
  return std::min({point_segment_distance(a, c, d), point_segment_distance(b, c, d),
                   point_segment_distance(c, a, b), point_segment_distance(d, a, b)});
}

// Strictly convex (every turn left beyond the collinear tolerance), counter-clockwise.
bool strictly_convex(const std::vector<Vec2>& polygon) {
  const int n = int(polygon.size());
  for (int i = 0; i < n; ++i)
    if (turn_sine(polygon[(i + n - 1) % n], polygon[i], polygon[(i + 1) % n]) <= kCollinearSine)
      return false;
  return true;
}

// p inside or on triangle abc (counter-clockwise), with a tolerance of `slack` (length) outward.
bool in_triangle(Vec2 p, Vec2 a, Vec2 b, Vec2 c, double slack) {
  const auto side = [&](Vec2 u, Vec2 v) { return cross(v - u, p - u) / length(v - u); };
  return side(a, b) >= -slack && side(b, c) >= -slack && side(c, a) >= -slack;
}

// Ear clipping of the (collinear-free, counter-clockwise) outline `core` from vertex `first`,
// then Hertel–Mehlhorn; nullopt when no ear is found (round-off at nearly touching edges).
struct Partition {
  std::vector<std::vector<int>> pieces;  // core indices, counter-clockwise; empty: merged away
  std::vector<std::pair<int, int>> diagonals;
  std::vector<bool> kept;  // diagonals still between two pieces
  int count() const {
    int n = 0;
    for (const auto& p : pieces) n += !p.empty();
    return n;
  }
};

// Position of the directed edge u -> v in piece q, or -1.
int edge_at(const std::vector<int>& q, int u, int v) {
  for (int i = 0; i < int(q.size()); ++i)
    if (q[i] == u && q[(i + 1) % q.size()] == v) return i;
  return -1;
}

// The pieces left and right of the directed diagonal u -> v.
void pieces_of(const Partition& p, int u, int v, int& left, int& right) {
  left = right = -1;
  for (int k = 0; k < int(p.pieces.size()); ++k) {
    if (p.pieces[k].empty()) continue;
    if (edge_at(p.pieces[k], u, v) >= 0) left = k;
    if (edge_at(p.pieces[k], v, u) >= 0) right = k;
  }
}

std::optional<Partition> partition_from(const std::vector<Vec2>& core, int first, double slack) {
  Partition out;
  auto& pieces = out.pieces;
  auto& diagonals = out.diagonals;
  auto& kept = out.kept;
  const int m = int(core.size());
  // Ear clipping: pieces as lists of core indices (counter-clockwise), diagonals as index pairs.
  std::vector<int> ring(m);
  for (int i = 0; i < m; ++i) ring[i] = (i + first) % m;
  while (ring.size() > 3) {
    const int r = int(ring.size());
    int ear = -1;
    for (int k = 0; k < r && ear < 0; ++k) {
      const int a = ring[(k + r - 1) % r], b = ring[k], c = ring[(k + 1) % r];
      if (turn_sine(core[a], core[b], core[c]) <= kCollinearSine) continue;
      bool empty = true;
      for (int q = 0; q < r && empty; ++q) {
        const int v = ring[q];
        if (v == a || v == b || v == c) continue;
        empty = !in_triangle(core[v], core[a], core[b], core[c], slack);
      }
      if (empty) ear = k;
    }
    if (ear < 0) return std::nullopt;
    const int a = ring[(ear + r - 1) % r], b = ring[ear], c = ring[(ear + 1) % r];
    pieces.push_back({a, b, c});
    diagonals.push_back({a, c});
    ring.erase(ring.begin() + ear);
  }
  pieces.push_back({ring[0], ring[1], ring[2]});
  // Hertel–Mehlhorn: remove a diagonal when the union of its two pieces is strictly convex.
  // Diagonals between two convex vertices first: removing one always leaves a convex union (its
  // angles there are parts of the outline's), so the reflex vertices' diagonals are tried last,
  // against the largest pieces (an L becomes its two rectangles).
  std::vector<bool> reflex(m);
  for (int i = 0; i < m; ++i)
    reflex[i] = turn_sine(core[(i + m - 1) % m], core[i], core[(i + 1) % m]) < 0.0;
  std::vector<std::size_t> order;
  for (int pass = 0; pass < 2; ++pass)
    for (std::size_t k = 0; k < diagonals.size(); ++k)
      if ((reflex[diagonals[k].first] || reflex[diagonals[k].second]) == (pass == 1))
        order.push_back(k);
  kept.assign(diagonals.size(), true);
  for (const std::size_t k : order) {
    const auto [u, v] = diagonals[k];
    int pl, pr;
    pieces_of(out, u, v, pl, pr);
    if (pl < 0 || pr < 0) continue;
    const std::vector<int>& a = pieces[pl];  // holds u -> v
    const std::vector<int>& b = pieces[pr];  // holds v -> u
    const int ia = edge_at(a, u, v), ib = edge_at(b, v, u);
    // All of a from v round to u, then b after u up to before v.
    std::vector<int> merged;
    for (std::size_t i = 0; i < a.size(); ++i) merged.push_back(a[(ia + 1 + i) % a.size()]);
    for (std::size_t i = 2; i < b.size(); ++i) merged.push_back(b[(ib + i) % b.size()]);
    if (int(merged.size()) > kMaxPolygonVertices) continue;
    std::vector<Vec2> points;
    for (const int w : merged) points.push_back(core[w]);
    if (!strictly_convex(points)) continue;
    pieces[pl] = std::move(merged);
    pieces[pr].clear();
    kept[k] = false;
  }
  return out;
}

}  // namespace

SimplePolygon::SimplePolygon(std::initializer_list<Vec2> vertices)
    : SimplePolygon(std::span<const Vec2>(vertices.begin(), vertices.size())) {}

SimplePolygon::SimplePolygon(std::span<const Vec2> in) {
  const int n = int(in.size());
  if (n < 3)
    throw InvalidPolygon(-1, "a polygon needs at least 3 vertices, got " + std::to_string(n));
  if (n > kMaxPlanVertices)
    throw InvalidPolygon(-1, "a plan may have at most " + std::to_string(kMaxPlanVertices) +
                                 " vertices, got " + std::to_string(n));
  for (int i = 0; i < n; ++i)
    if (!std::isfinite(in[i].x) || !std::isfinite(in[i].y))
      throw InvalidPolygon(
          i, detail::describe_vertex(i, in[i]) + ": coordinate is not a finite number");
  Vec2 lo = in[0], hi = in[0];
  for (const Vec2& p : in) {
    lo = {std::min(lo.x, p.x), std::min(lo.y, p.y)};
    hi = {std::max(hi.x, p.x), std::max(hi.y, p.y)};
  }
  const double size = std::max(hi.x - lo.x, hi.y - lo.y);
  for (int i = 1; i < n; ++i)
    for (int j = 0; j < i; ++j)
      if (length(in[i] - in[j]) <= kRepeatedFraction * size)
        throw InvalidPolygon(
            i, detail::describe_vertex(i, in[i]) + ": repeats vertex " + std::to_string(j));
  double twice_area = 0.0;
  for (int i = 1; i + 1 < n; ++i) twice_area += cross(in[i] - in[0], in[i + 1] - in[0]);
  // Zero area: a bow tie (its halves cancel) or points on one line.
  if (std::abs(twice_area) <= kCollinearSine * size * size) {
    for (int i = 0; i < n; ++i)
      for (int j = i + 2; j < n; ++j) {
        if (i == 0 && j == n - 1) continue;
        if (properly_cross(in[i], in[(i + 1) % n], in[j], in[(j + 1) % n]))
          throw InvalidPolygon(-1, "the outline touches or crosses itself (edge " +
                                       std::to_string(i) + "-" + std::to_string((i + 1) % n) +
                                       " meets edge " + std::to_string(j) + "-" +
                                       std::to_string((j + 1) % n) + "): a self-crossing plan");
      }
    throw InvalidPolygon(-1, "zero area: all " + std::to_string(n) + " vertices lie on one line");
  }
  // A spike: the outline runs back along the edge it came from.
  for (int i = 0; i < n; ++i) {
    const Vec2 p = in[(i + n - 1) % n], q = in[i], r = in[(i + 1) % n];
    if (std::abs(turn_sine(p, q, r)) <= kCollinearSine && dot(q - p, r - q) < 0.0)
      throw InvalidPolygon(i, detail::describe_vertex(i, q) +
                                  ": the outline turns back along the edge it came from "
                                  "(a spike of zero width)");
  }
  for (int i = 0; i < n; ++i)
    for (int j = i + 2; j < n; ++j) {
      if (i == 0 && j == n - 1) continue;  // adjacent through vertex 0
      const Vec2 a = in[i], b = in[(i + 1) % n], c = in[j], d = in[(j + 1) % n];
      if (segment_distance(a, b, c, d) <= kTouchingFraction * size)
        throw InvalidPolygon(
            -1, "the outline touches or crosses itself (edge " + std::to_string(i) + "-" +
                    std::to_string((i + 1) % n) + " meets edge " + std::to_string(j) + "-" +
                    std::to_string((j + 1) % n) +
                    "): a self-crossing plan; list the vertices in order around the outline");
    }
  reversed_ = twice_area < 0.0;
  vertices_.resize(n);
  for (int i = 0; i < n; ++i) vertices_[i] = reversed_ ? in[n - 1 - i] : in[i];
  update_box();
  partition();
}

void SimplePolygon::update_box() {
  box_min_ = box_max_ = vertices_[0];
  for (const Vec2& p : vertices_) {
    box_min_ = {std::min(box_min_.x, p.x), std::min(box_min_.y, p.y)};
    box_max_ = {std::max(box_max_.x, p.x), std::max(box_max_.y, p.y)};
  }
}

void SimplePolygon::partition() {
  const int n = size();
  // The outline without its straight-through vertices.
  std::vector<Vec2> core;
  for (int i = 0; i < n; ++i)
    if (std::abs(turn_sine(vertices_[(i + n - 1) % n], vertices_[i], vertices_[(i + 1) % n])) >
        kCollinearSine)
      core.push_back(vertices_[i]);
  if (int(core.size()) <= kMaxPolygonVertices && strictly_convex(core)) {
    pieces_.emplace_back(core);
    return;
  }
  const int m = int(core.size());
  const double slack = 1e-12 * std::max(box_max_.x - box_min_.x, box_max_.y - box_min_.y);
  // Hertel–Mehlhorn depends on the triangulation: every starting vertex is tried (the plan is
  // split once, when read), the fewest pieces kept.
  std::optional<Partition> best;
  for (int first = 0; first < m; ++first) {
    std::optional<Partition> p = partition_from(core, first, slack);
    if (p && (!best || p->count() < best->count())) best = std::move(p);
  }
  if (!best)
    throw InvalidPolygon(-1,
                         "the outline could not be split into convex pieces (edges nearly "
                         "touching?)");
  const auto& pieces = best->pieces;
  const auto& diagonals = best->diagonals;
  const auto& kept = best->kept;
  std::vector<int> index(pieces.size(), -1);
  for (std::size_t p = 0; p < pieces.size(); ++p) {
    if (pieces[p].empty()) continue;
    index[p] = int(pieces_.size());
    std::vector<Vec2> points;
    for (const int v : pieces[p]) points.push_back(core[v]);
    pieces_.emplace_back(points);
  }
  for (std::size_t k = 0; k < diagonals.size(); ++k) {
    if (!kept[k]) continue;
    const auto [u, v] = diagonals[k];
    int pl, pr;
    pieces_of(*best, u, v, pl, pr);
    diagonals_.push_back({core[u], core[v]});
    diagonal_pieces_.push_back({index[pl], index[pr]});
  }
}

bool SimplePolygon::adjacent(int p, int q) const {
  for (const auto& [a, b] : diagonal_pieces_)
    if ((a == p && b == q) || (a == q && b == p)) return true;
  return false;
}

void SimplePolygon::placed_into(const Placement2& x, Vec2 about, SimplePolygon& out) const {
  const double c = std::cos(x.theta), s = std::sin(x.theta);
  const auto move = [&](Vec2 p) {
    const Vec2 r = p - about;
    return Vec2{about.x + c * r.x - s * r.y + x.u, about.y + s * r.x + c * r.y + x.v};
  };
  out.vertices_.resize(vertices_.size());
  for (std::size_t i = 0; i < vertices_.size(); ++i) out.vertices_[i] = move(vertices_[i]);
  out.reversed_ = reversed_;
  // ConvexPolygon has no default constructor in public: grow by copies, then overwrite.
  if (out.pieces_.size() != pieces_.size()) out.pieces_ = pieces_;
  for (std::size_t k = 0; k < pieces_.size(); ++k) out.pieces_[k] = pieces_[k].placed(x, about);
  out.diagonals_.resize(diagonals_.size());
  for (std::size_t k = 0; k < diagonals_.size(); ++k)
    out.diagonals_[k] = {move(diagonals_[k].from), move(diagonals_[k].to)};
  out.diagonal_pieces_ = diagonal_pieces_;
  out.update_box();
}

SimplePolygon SimplePolygon::placed(const Placement2& x, Vec2 about) const {
  SimplePolygon out;
  placed_into(x, about, out);
  return out;
}

AreaProperties area_properties(const SimplePolygon& polygon) {
  return outline_area_properties(polygon.vertices());
}

bool contains(const SimplePolygon& polygon, Vec2 p) {
  const int n = polygon.size();
  const double slack = 1e-12 * std::max(polygon.box_max().x - polygon.box_min().x,
                                        polygon.box_max().y - polygon.box_min().y);
  int winding = 0;
  for (int i = 0; i < n; ++i) {
    const Vec2 a = polygon[i], b = polygon[(i + 1) % n];
    if (point_segment_distance(p, a, b) <= slack) return true;
    const double side = cross(b - a, p - a);
    if (a.y <= p.y) {
      if (b.y > p.y && side > 0) ++winding;
    } else if (b.y <= p.y && side < 0) {
      --winding;
    }
  }
  return winding != 0;
}

}  // namespace isopound
