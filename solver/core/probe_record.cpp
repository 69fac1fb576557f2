// Plan-probe peaks with a per-group bound that skips groups which cannot raise a peak.
#include "solver/core/probe_record.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <tuple>

namespace isopound {

namespace {

using Terms = std::vector<std::pair<int, double>>;

std::vector<int> dofs_of(const Terms& terms) {
  std::vector<int> dofs;
  for (const auto& term : terms) dofs.push_back(term.first);
  std::sort(dofs.begin(), dofs.end());
  dofs.erase(std::unique(dofs.begin(), dofs.end()), dofs.end());
  return dofs;
}

// Bounds are inflated by this factor, and get this share of the terms' magnitudes (sum_d |c_d|
// times the largest |q|) added: a probe's sum and the bound round differently (a drift cancels two
// large displacements), and a skipped group must never hide a raise.
constexpr double kBoundInflation = 1.0 + 1e-9;
constexpr double kRoundOffSlack = 1e-12;
// The same for a change between two states: two sums' round-off, and the basis's reproduction of
// the coefficients (within 1e-12 of their norm) times a difference of up to 2 q_max per DOF.
constexpr double kChangeSlack = 64 * kRoundOffSlack;
// A margin to a peak is shrunk by this share (the rounding of the difference, of the resultant's
// square root and of the peak's own value), and the change's resultant grown by it.
constexpr double kMarginShrink = 1e-14;
// x^2 + y^2 <= this share of R^2 proves sqrt(x^2 + y^2) <= R whatever the rounding of the
// squares, their sum and R^2 (each within 1.2e-16 relative); R^2 is capped at kLargest, so that
// an overflowing x^2 + y^2 (inf) never passes.
constexpr double kResultantMargin = 1.0 - 1e-14;
constexpr double kLargest = std::numeric_limits<double>::max();

}  // namespace

double ProbeRecorder::bound(const Bound& b, const double* q, double q_max, double* z) const {
  double sum = 0.0;
  std::size_t k = b.first;
  for (std::size_t j = 0; j < b.ends.size(); ++j) {
    double w_q = 0.0;
    for (const std::size_t end = b.first + b.ends[j]; k < end; ++k)
      w_q += bound_terms_[k].coefficient * q[bound_terms_[k].dof];
    z[j] = w_q;
    sum += b.weight[j] * std::abs(w_q);
  }
  return sum * kBoundInflation + kRoundOffSlack * b.magnitude * q_max;
}

double ProbeRecorder::change_bound(const Bound& b, const double* z, const double* z_last,
                                   double q_max) {
  double sum = 0.0;
  for (std::size_t j = 0; j < b.ends.size(); ++j) sum += b.weight[j] * std::abs(z[j] - z_last[j]);
  return sum * kBoundInflation + kChangeSlack * b.magnitude * q_max;
}

ProbeRecorder::ProbeRecorder(const std::vector<PlanProbe>& probes) {
  begin_.push_back(0);
  for (const PlanProbe& probe : probes) {
    for (const auto* terms : {&probe.x_terms, &probe.y_terms}) {
      for (const auto& [dof, c] : *terms) terms_.push_back({dof, c});
      begin_.push_back(terms_.size());
    }
    length_.push_back(probe.length);
    std::vector<int>& read =
        probe.quantity == PlanProbe::Quantity::kAbsoluteAcceleration ? dofs_a_ : dofs_u_;
    for (const auto* terms : {&probe.x_terms, &probe.y_terms})
      for (const auto& term : *terms) read.push_back(term.first);
  }
  for (std::vector<int>* read : {&dofs_u_, &dofs_a_}) {
    std::sort(read->begin(), read->end());
    read->erase(std::unique(read->begin(), read->end()), read->end());
  }
  // Group by quantity and DOFs, in order of first appearance.
  std::map<std::tuple<bool, std::vector<int>, std::vector<int>>, std::size_t> group_of;
  for (std::size_t p = 0; p < probes.size(); ++p) {
    const bool acceleration = probes[p].quantity == PlanProbe::Quantity::kAbsoluteAcceleration;
    const auto key =
        std::make_tuple(acceleration, dofs_of(probes[p].x_terms), dofs_of(probes[p].y_terms));
    const auto [it, added] = group_of.try_emplace(key, groups_.size());
    if (added) {
      groups_.emplace_back();
      groups_.back().acceleration = acceleration;
    }
    groups_[it->second].members.push_back(p);
  }
  // Each bound from the members' coefficient matrix C (DOFs x members): a basis W of C's columns
  // (rank-revealing QR) and the coordinates beta of every member in it; when the coordinates do
  // not reproduce C (never for probes of a rigid floor), the basis is every member itself.
  const auto make_bound = [&](const std::vector<std::size_t>& members, bool y) {
    const std::vector<int> dofs =
        dofs_of(y ? probes[members[0]].y_terms : probes[members[0]].x_terms);
    const Eigen::Index n_dofs = static_cast<Eigen::Index>(dofs.size());
    const Eigen::Index n_members = static_cast<Eigen::Index>(members.size());
    Eigen::MatrixXd C = Eigen::MatrixXd::Zero(n_dofs, n_members);
    for (Eigen::Index k = 0; k < n_members; ++k)
      for (const auto& [d, c] : y ? probes[members[k]].y_terms : probes[members[k]].x_terms)
        C(std::lower_bound(dofs.begin(), dofs.end(), d) - dofs.begin(), k) += c;
    Bound bound;
    for (Eigen::Index i = 0; i < n_dofs; ++i) bound.magnitude += C.row(i).cwiseAbs().maxCoeff();
    bound.first = bound_terms_.size();
    if (n_dofs == 0) return bound;
    const Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(C);
    const Eigen::Index rank = qr.rank();
    Eigen::MatrixXd W(n_dofs, rank);
    for (Eigen::Index j = 0; j < rank; ++j) W.col(j) = C.col(qr.colsPermutation().indices()[j]);
    Eigen::MatrixXd beta = W.colPivHouseholderQr().solve(C);
    if (!((W * beta - C).norm() <= 1e-12 * C.norm())) {
      W = C;
      beta = Eigen::MatrixXd::Identity(n_members, n_members);
    }
    for (Eigen::Index j = 0; j < W.cols(); ++j) {
      for (Eigen::Index i = 0; i < n_dofs; ++i)
        if (W(i, j) != 0.0) bound_terms_.push_back({dofs[i], W(i, j)});
      bound.ends.push_back(bound_terms_.size() - bound.first);
      bound.weight.push_back(beta.row(j).cwiseAbs().maxCoeff());
    }
    return bound;
  };
  std::size_t basis_size = 0;
  for (Group& g : groups_) {
    g.x = make_bound(g.members, false);
    g.y = make_bound(g.members, true);
    g.z_last.assign(g.x.ends.size() + g.y.ends.size(), 0.0);
    basis_size = std::max(basis_size, g.z_last.size());
  }
  z_now_.assign(basis_size, 0.0);
}

void ProbeRecorder::record(const double* u, const double* a_abs, double t,
                           std::vector<ProbePeaks>& peaks) {
  const auto largest = [](const std::vector<int>& dofs, const double* q) {
    double m = 0.0;
    for (const int d : dofs) m = std::max(m, std::abs(q[d]));
    return m;
  };
  const double u_max = largest(dofs_u_, u), a_max = largest(dofs_a_, a_abs);
  for (Group& g : groups_) {
    const double* q = g.acceleration ? a_abs : u;
    const double q_max = g.acceleration ? a_max : u_max;
    double* z_x = z_now_.data();
    double* z_y = z_x + g.x.ends.size();
    const double bx = bound(g.x, q, q_max, z_x), by = bound(g.y, q, q_max, z_y);
    // NaN bounds fail every test and fall through to the members (which record the NaN).
    if (bx <= g.limit_x && by <= g.limit_y &&
        (bx * bx + by * by) * kBoundInflation <= g.limit_resultant * g.limit_resultant)
      continue;
    // Moved too little since the last evaluation to leave any member's bands.
    const double q_max_both = std::max(q_max, g.q_max_last);
    const double dx = change_bound(g.x, z_x, g.z_last.data(), q_max_both);
    const double dy = change_bound(g.y, z_y, g.z_last.data() + g.x.ends.size(), q_max_both);
    // |r_k − r_k,last| <= dx + dy = d, so r_k^2 <= r_k,last^2 + d (2 R_k + d) stays within R_k^2
    // when d (2 max R + d) <= min (R_k^2 − r_k,last^2).
    const double d = dx + dy;
    if (dx <= g.margin_x && dy <= g.margin_y &&
        d * (2.0 * g.largest_resultant + d) * (1.0 + 8 * kMarginShrink) <= g.margin_squares)
      continue;
    // Member by member: only one outside its own band (x, y, or x^2 + y^2 beyond the resultant's
    // peak squared, with a margin that covers the rounding of the squares) can raise a peak, and
    // only then are its resultant (a square root) and peaks updated. The group's limits change
    // only when a peak did.
    evaluations_ += static_cast<long>(g.members.size());
    bool raised = false;
    double margin_x = std::numeric_limits<double>::infinity(), margin_y = margin_x,
           margin_squares = margin_x, largest_resultant = 0.0;
    // Each member's distance to its peaks after this step (its value inside them); for the
    // resultant R_k^2 − r_k^2, without a square root.
    const auto margins = [&](double x, double y, double r_sq, const ProbePeaks& pk) {
      const double shrink = 1.0 - kMarginShrink;
      margin_x = std::min({margin_x, (pk.x.positive - x) * shrink, (x - pk.x.negative) * shrink});
      margin_y = std::min({margin_y, (pk.y.positive - y) * shrink, (y - pk.y.negative) * shrink});
      const double peak_r = pk.resultant.value;
      margin_squares = std::min(margin_squares, peak_r * peak_r * (1.0 - 2 * kMarginShrink) -
                                                    r_sq * (1.0 + kMarginShrink));
      largest_resultant = std::max(largest_resultant, peak_r);
    };
    for (const std::size_t p : g.members) {
      const auto sum = [&](std::size_t begin, std::size_t end) {
        double x = 0.0;
        for (std::size_t k = begin; k < end; ++k) x += terms_[k].coefficient * q[terms_[k].dof];
        return x;
      };
      const double x = sum(begin_[2 * p], begin_[2 * p + 1]);
      const double y = sum(begin_[2 * p + 1], begin_[2 * p + 2]);
      ProbePeaks& pk = peaks[p];
      const double r_sq = x * x + y * y;
      const double peak_r = pk.resultant.value;
      // A NaN fails every test and goes on (update_peak ignores it).
      if (x <= pk.x.positive && x >= pk.x.negative && y <= pk.y.positive && y >= pk.y.negative &&
          r_sq <= std::min(peak_r * peak_r, kLargest) * kResultantMargin) {
        margins(x, y, r_sq, pk);
        continue;
      }
      raised = true;
      update_peak(pk.x, x, t);
      update_peak(pk.y, y, t);
      const double r = std::sqrt(r_sq);
      update_peak(pk.resultant, r, t);
      if (length_[p] > 0) update_peak(pk.ratio, r / length_[p], t);
      margins(x, y, r_sq, pk);
    }
    // The baseline of the change test (a NaN margin fails it: the next step evaluates again).
    std::copy(z_x, z_x + g.z_last.size(), g.z_last.begin());
    g.q_max_last = q_max;
    if (!std::isfinite(q_max)) margin_x = margin_y = margin_squares = -1.0;  // no baseline
    g.margin_x = margin_x;
    g.margin_y = margin_y;
    g.margin_squares = margin_squares;
    g.largest_resultant = largest_resultant;
    if (!raised) continue;
    g.limit_x = g.limit_y = g.limit_resultant = std::numeric_limits<double>::infinity();
    for (const std::size_t p : g.members) {
      const ProbePeaks& pk = peaks[p];
      g.limit_x = std::min({g.limit_x, pk.x.positive, -pk.x.negative});
      g.limit_y = std::min({g.limit_y, pk.y.positive, -pk.y.negative});
      g.limit_resultant = std::min(g.limit_resultant, pk.resultant.value);
    }
  }
}

}  // namespace isopound
