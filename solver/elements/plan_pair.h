// The geometry two plans of any simple outline share when their overlap may have several
// components (issue 40): each connected component of A ∩ B (geometry/plan_overlap.h) is one
// contact, a slot: a PolygonContact with its own force-law state (friction spring, status,
// events, episodes), all slots of a body pair asking this one object for their overlap.
//
// Which component is whose (a contact's identity from one placement to the next): a slot closed
// at its committed state takes, of the components sharing a piece pair with its committed one
// (any, if it had none), the one whose centroid is nearest its committed centroid (slots in
// order, one component each); the components left go to the open slots in order. So
// a component that splits keeps its slot on the nearer part while the other part starts a
// contact in a free slot, and of two that merge the nearer slot keeps the union while the other
// separates. Components beyond the slots get no force; they are counted (most_components()).
//
// A slot's witness (its onsets and separations are located as a convex pair's are) is −distance
// of a set of piece pairs (the least SAT separation: their penetration depth when they overlap):
// with a component, its piece pairs; closed without one (separating), the pairs it was made of;
// the first open slot, every pair no other slot's component (at the placement or committed) is
// made of, so a second component's onset is found while a first one is in contact. The other
// open slots' distance is that plus the bodies' size: they never reach an onset by the witness,
// only by a component appearing in a step (two at once), as an unlocated onset.
//
// Parts closer than 1e-6 of the bodies' size are one contact: slivers along one face split by a
// diagonal of the plan (plan_overlap glues parts only along a common stretch longer than 1e-9 of
// the size) keep one slot, the larger part's shape with the sum of their areas.
//
// Two convex plans are one slot whose overlap is overlap_of's (the contact element keeps its own
// convex path for them; this is for tests).
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "geometry/plan_overlap.h"
#include "geometry/simple_polygon.h"

namespace isopound {

// One body of a plan pair: its outline at rest (plan frame W, m), the point its (u, v, θ) are
// taken at, and whether it moves (a fixed body's outline is used as it is).
struct PlanPairBody {
  SimplePolygon outline_W;
  Vec2 p_WO;
  bool moves = true;
};

class PlanPair {
 public:
  // How much deeper than touch a slot closed at touch looks for its component (of size()).
  static constexpr double kSurfaceSliverFraction = 1e-8;
  // Parts of the overlap closer than this (of size()) are one contact (merge_slivers).
  static constexpr double kNearFraction = 1e-6;

  using Placement6 = std::array<double, 6>;  // (u, v, θ) of A, then of B

  PlanPair(PlanPairBody a, PlanPairBody b, int slots, OverlapMethod method = OverlapMethod::kFast);

  int slots() const { return int(committed_.size()); }
  const PlanPairBody& a() const { return a_; }
  const PlanPairBody& b() const { return b_; }

  // The overlap component slot `slot` has at placement q (area 0, kind kSeparated if none).
  const Overlap& overlap(int slot, const Placement6& q) const;
  // The slot's signed distance (witness = −distance, above) with the normal of its pair.
  Separation separation(int slot, const Placement6& q) const;

  // A slot's committed status: closed (in contact) or open, at placement q. Called by the slot
  // whenever its committed state changes; the assignment follows it. A slot closed at touch
  // (no area yet) is given the component it will have: that of the placement a sliver deeper.
  void set_committed(int slot, bool closed, const Placement6& q);

  // The most components any placement asked for had (more than slots(): some got no force).
  int most_components() const { return most_components_; }

 private:
  struct Entry {
    Placement6 q{};
    std::uint64_t generation = 0;
    bool valid = false;
    SimplePolygon placed_a, placed_b;
    PlanOverlap overlap;
    std::array<int, kMaxOverlapComponents> owner{};  // the slot of each component, or −1
    std::vector<int> component;                      // the component of each slot, or −1
    // Each piece pair's separation, computed when first asked (the slots' witnesses at one
    // placement share them): bit piece_pair_bit set in separation_known when stored.
    mutable std::uint64_t separation_known = 0;
    mutable std::vector<Separation> piece_separation;
  };
  struct Committed {
    bool closed = false;
    Vec2 p_WC;
    std::uint64_t piece_pairs = 0;  // of its component at the committed placement
  };

  // The entry for placement q under the current committed statuses (computed if not cached).
  const Entry& at(const Placement6& q) const;
  void assign(Entry& e) const;
  void merge_slivers(PlanOverlap& o) const;
  // The least separation of the piece pairs of `pairs` (bit set: taken), distance kFar if none.
  Separation least_separation(const Entry& e, std::uint64_t pairs) const;
  int first_open_slot() const;

  PlanPairBody a_, b_;
  OverlapMethod method_;
  double size_ = 0.0;  // m, the larger body's bounding-box diagonal
  std::vector<Committed> committed_;
  std::uint64_t generation_ = 1;
  // A few recent placements: the slots of a pair evaluate the same trial (and, for the tangent
  // and the witness, the same perturbed placements) one after the other.
  static constexpr int kCached = 8;
  mutable std::array<Entry, kCached> cache_;
  mutable int next_ = 0;
  mutable int most_components_ = 0;
  Overlap none_;
};

}  // namespace isopound
