// Shared overlap geometry of the contact slots of one pair of plans (plan_pair.h).
#include "solver/elements/plan_pair.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <stdexcept>

namespace isopound {

PlanPair::PlanPair(PlanPairBody a, PlanPairBody b, int slots, OverlapMethod method)
    : a_(std::move(a)), b_(std::move(b)), method_(method) {
  if (slots < 1 || slots > kMaxOverlapComponents)
    throw std::invalid_argument("plan pair: between 1 and " +
                                std::to_string(kMaxOverlapComponents) + " contact slots");
  committed_.resize(slots);
  for (const SimplePolygon* p : {&a_.outline_W, &b_.outline_W})
    size_ = std::max(size_,
                     std::hypot(p->box_max().x - p->box_min().x, p->box_max().y - p->box_min().y));
  for (Entry& e : cache_) {
    e.placed_a = a_.outline_W;
    e.placed_b = b_.outline_W;
    e.component.assign(slots, -1);
    e.piece_separation.resize(a_.outline_W.pieces().size() * b_.outline_W.pieces().size());
  }
}

const PlanPair::Entry& PlanPair::at(const Placement6& q) const {
  for (const Entry& e : cache_)
    if (e.valid && e.generation == generation_ && std::memcmp(e.q.data(), q.data(), sizeof q) == 0)
      return e;
  Entry& e = cache_[next_];
  next_ = (next_ + 1) % kCached;
  e.q = q;
  e.generation = generation_;
  e.valid = true;
  if (a_.moves) a_.outline_W.placed_into({q[0], q[1], q[2]}, a_.p_WO, e.placed_a);
  if (b_.moves) b_.outline_W.placed_into({q[3], q[4], q[5]}, b_.p_WO, e.placed_b);
  e.separation_known = 0;
  plan_overlap(e.placed_a, e.placed_b, e.overlap, method_);
  merge_slivers(e.overlap);
  most_components_ = std::max(most_components_, e.overlap.count + e.overlap.dropped);
  assign(e);
  return e;
}

// Two parts closer than kNearFraction of the size are one contact: slivers along one face that a
// diagonal of the plan splits (their common stretch of the diagonal is shorter than the overlap's
// gluing tolerance) would otherwise be two contacts trading one episode at every touch. The
// larger part's shape (chord, normal) with the sum of the areas and their centroid.
void PlanPair::merge_slivers(PlanOverlap& o) const {
  const double near = kNearFraction * size_;
  const auto close = [&](const Overlap& p, const Overlap& q) {
    for (int i = 0; i < p.vertex_count; ++i)
      for (int j = 0; j < q.vertex_count; ++j) {
        const Vec2 d = p.vertices[i] - q.vertices[j];
        if (dot(d, d) <= near * near) return true;
      }
    return false;
  };
  for (int k = 0; k < o.count; ++k)
    for (int m = k + 1; m < o.count;) {
      if (!close(o.components[k], o.components[m])) {
        ++m;
        continue;
      }
      Overlap& p = o.components[k];
      const Overlap& q = o.components[m];
      const double area = p.area + q.area;
      const Vec2 p_WC = (1.0 / area) * (p.area * p.p_WC + q.area * q.p_WC);
      if (q.area > p.area) p = q;
      const double scale = p.area > 0 ? area / p.area : 1.0;
      p.mean_depth *= scale;
      p.indentation *= scale;
      p.area = area;
      p.p_WC = p_WC;
      o.piece_pairs[k] |= o.piece_pairs[m];
      for (int r = m; r + 1 < o.count; ++r) {
        o.components[r] = o.components[r + 1];
        o.piece_pairs[r] = o.piece_pairs[r + 1];
      }
      --o.count;
    }
}

void PlanPair::assign(Entry& e) const {
  const PlanOverlap& ov = e.overlap;
  e.owner.fill(-1);
  std::fill(e.component.begin(), e.component.end(), -1);
  // Closed slots follow their component: sharing a piece pair, nearest centroid.
  for (int s = 0; s < slots(); ++s) {
    const Committed& c = committed_[s];
    if (!c.closed) continue;
    int best = -1;
    double best_d2 = std::numeric_limits<double>::infinity();
    for (int k = 0; k < ov.count; ++k) {
      if (e.owner[k] >= 0) continue;
      if (c.piece_pairs != 0 && (ov.piece_pairs[k] & c.piece_pairs) == 0) continue;
      const Vec2 d = ov.components[k].p_WC - c.p_WC;
      const double d2 = dot(d, d);
      if (d2 < best_d2) best_d2 = d2, best = k;
    }
    if (best >= 0) e.owner[best] = s, e.component[s] = best;
  }
  // The others go to the open slots in order.
  int s = 0;
  for (int k = 0; k < ov.count; ++k) {
    if (e.owner[k] >= 0) continue;
    while (s < slots() && (committed_[s].closed || e.component[s] >= 0)) ++s;
    if (s == slots()) break;
    e.owner[k] = s;
    e.component[s] = k;
  }
}

const Overlap& PlanPair::overlap(int slot, const Placement6& q) const {
  const Entry& e = at(q);
  const int k = e.component[slot];
  return k >= 0 ? e.overlap.components[k] : none_;
}

// plan_separation(e.placed_a, e.placed_b, ~pairs), each piece pair's separation computed once per
// entry: the same pairs in the same order, the same least (bit for bit).
Separation PlanPair::least_separation(const Entry& e, std::uint64_t pairs) const {
  const auto& pieces_a = e.placed_a.pieces();
  const auto& pieces_b = e.placed_b.pieces();
  const int na = int(pieces_a.size()), nb = int(pieces_b.size());
  // Beyond 64 pairs the bits alias (piece_pair_bit): nothing is kept then. (piece_separation
  // is sized na * nb by the constructor: placing a plan keeps its pieces.)
  const bool keep = na * nb <= 64;
  Separation best{std::numeric_limits<double>::infinity(), {}};
  for (int i = 0; i < na; ++i)
    for (int j = 0; j < nb; ++j) {
      const std::uint64_t bit = piece_pair_bit(i, j, nb);
      if (!(pairs & bit)) continue;
      Separation s;
      if (!keep) {
        s = separation_of(pieces_a[i], pieces_b[j]);
      } else if (e.separation_known & bit) {
        s = e.piece_separation[static_cast<std::size_t>(i * nb + j)];
      } else {
        s = separation_of(pieces_a[i], pieces_b[j]);
        e.piece_separation[static_cast<std::size_t>(i * nb + j)] = s;
        e.separation_known |= bit;
      }
      if (s.distance < best.distance) best = s;
    }
  if (!std::isfinite(best.distance)) best = {size_, {1.0, 0.0}};  // nothing left: far
  return best;
}

int PlanPair::first_open_slot() const {
  for (int s = 0; s < slots(); ++s)
    if (!committed_[s].closed) return s;
  return -1;
}

Separation PlanPair::separation(int slot, const Placement6& q) const {
  const Entry& e = at(q);
  const int k = e.component[slot];
  if (k >= 0) return least_separation(e, e.overlap.piece_pairs[k]);
  std::uint64_t others = 0;  // what other slots' components are made of
  for (int j = 0; j < e.overlap.count; ++j)
    if (e.owner[j] >= 0 && e.owner[j] != slot) others |= e.overlap.piece_pairs[j];
  const Committed& c = committed_[slot];
  if (c.closed) {  // separating: its own pairs
    const std::uint64_t own = c.piece_pairs & ~others;
    return least_separation(e, own != 0 ? own : c.piece_pairs);
  }
  for (int s = 0; s < slots(); ++s)
    if (s != slot && committed_[s].closed) others |= committed_[s].piece_pairs;
  Separation sep = least_separation(e, ~others);
  sep.distance = std::max(sep.distance, 0.0);
  if (slot != first_open_slot()) sep.distance += size_;
  return sep;
}

void PlanPair::set_committed(int slot, bool closed, const Placement6& q) {
  Committed next;
  next.closed = closed;
  if (closed) {
    const Entry& e = at(q);
    int k = e.component[slot];
    const Entry* in = &e;
    const Separation sep = k < 0 ? separation(slot, q) : Separation{};
    if (k < 0 && sep.distance < 1e-6 * size_) {  // at touch: the component a sliver deeper
      const double shift = std::max(sep.distance, 0.0) + kSurfaceSliverFraction * size_;
      Placement6 deeper = q;
      deeper[3] -= shift * sep.n_AB.x;
      deeper[4] -= shift * sep.n_AB.y;
      in = &at(deeper);
      k = in->component[slot];
    }
    if (k >= 0) {
      next.p_WC = in->overlap.components[k].p_WC;
      next.piece_pairs = in->overlap.piece_pairs[k];
    }
  }
  Committed& c = committed_[slot];
  if (c.closed == next.closed && c.piece_pairs == next.piece_pairs && c.p_WC.x == next.p_WC.x &&
      c.p_WC.y == next.p_WC.y)
    return;
  c = next;
  ++generation_;
}

}  // namespace isopound
