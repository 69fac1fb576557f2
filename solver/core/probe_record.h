// Peaks of the model's plan probes (model.h): x = sum c_k q_k, y likewise, and the resultant
// sqrt(x^2 + y^2) at each instant, q the displacements or the absolute accelerations.
#pragma once

#include <cstddef>
#include <vector>

#include "solver/core/model.h"
#include "solver/core/peak.h"

namespace isopound {

// Peaks of a PlanProbe.
struct ProbePeaks {
  Peak x, y, resultant;  // m or m/s^2
  Peak ratio;            // resultant / length, when length > 0
};

// Records the probes' peaks every step, exactly as evaluating every probe would, but cheaply.
// Probes of one quantity over the same DOFs (a floor's centre and corners, a storey's columns)
// form a group. Their x coefficient vectors span a small space (rank 2 for the columns of a
// storey: drift - y dtheta) with a basis w_j taken from the members, c_k = sum_j beta_kj w_j, so
//   |x_k| <= sum_j max_k |beta_kj| |w_j . q|.
// A group whose bounds (inflated well beyond round-off) cannot raise any member's peak is skipped
// whole: after the strong motion almost no probe is evaluated. So is a group that has moved too
// little since its members were last evaluated to leave their bands: |x_k − x_k,last| <=
// sum_j max_k |beta_kj| |w_j . (q − q_last)|, against the smallest distance of a member's last
// value to its peaks (a floor swaying about a permanent offset, steps short against the motion:
// contact steps). In a group that is not, a member inside its own bands (x, y, and x^2 + y^2
// against its resultant's peak squared) is left there, without its square root.
class ProbeRecorder {
 public:
  explicit ProbeRecorder(const std::vector<PlanProbe>& probes);

  // u: displacements, a_abs: absolute accelerations (per DOF); t: the time, s.
  void record(const double* u, const double* a_abs, double t, std::vector<ProbePeaks>& peaks);
  // How many probe evaluations record() has made (the rest were skipped with their group).
  long evaluations() const { return evaluations_; }

 private:
  struct Term {
    int dof;
    double coefficient;
  };
  // A bound of |x| (or |y|) over a group: sum_j weight_j |w_j . q| + slack sum_d c_d |q_d|,
  // stored flat in bound_terms_: basis vector j's terms [first + ends[j-1], first + ends[j]).
  struct Bound {
    std::size_t first = 0;          // in bound_terms_
    std::vector<std::size_t> ends;  // per basis vector, relative to first
    std::vector<double> weight;     // max_k |beta_kj|
    double magnitude = 0.0;         // sum_d max_k |c_kd|: times max_d |q_d|, the round-off's scale
  };
  // q_max = max_d |q_d| over the quantity's DOFs; z gets the basis values w_j . q.
  double bound(const Bound& b, const double* q, double q_max, double* z) const;
  // The bound of the change of any member since z_last (the basis values then): sum_j weight_j
  // |z_j − z_last_j|, inflated, plus the round-off of both states' sums.
  static double change_bound(const Bound& b, const double* z, const double* z_last, double q_max);
  struct Group {
    bool acceleration = false;  // the members read a_abs (else u)
    std::vector<std::size_t> members;
    Bound x, y;
    // The members' smallest margins: no |x| <= limit_x raises an x peak, etc.
    double limit_x = 0.0, limit_y = 0.0, limit_resultant = 0.0;
    // At the members' last evaluation: the basis values (x's then y's), the largest |q|, the
    // smallest distance of any member's x (y) to its peaks, the smallest R_k^2 − r_k^2 (R_k the
    // resultant's peak, r_k the value then) and the largest R_k; none before the first.
    std::vector<double> z_last;
    double q_max_last = 0.0;
    double margin_x = -1.0, margin_y = -1.0, margin_squares = -1.0, largest_resultant = 0.0;
  };
  std::vector<double> z_now_;  // scratch: a group's basis values this step
  // Probe p's x terms are terms_[begin_[2p], begin_[2p + 1]), its y terms up to begin_[2p + 2].
  std::vector<Term> terms_;
  std::vector<std::size_t> begin_;
  std::vector<double> length_;
  std::vector<Term> bound_terms_;
  std::vector<int> dofs_u_, dofs_a_;  // the DOFs the displacement / acceleration probes read
  std::vector<Group> groups_;
  long evaluations_ = 0;
};

}  // namespace isopound
