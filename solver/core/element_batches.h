// The model's elements in runs of one Element::batch_key(): every hot call goes to a run's first
// element at once, with the same results, bit for bit, as calling each element in turn.
#pragma once

#include <Eigen/Dense>
#include <memory>
#include <utility>
#include <vector>

#include "solver/core/element.h"

namespace isopound {

class ElementBatches {
 public:
  explicit ElementBatches(const std::vector<std::unique_ptr<Element>>& elements);

  void set_trials(const Eigen::VectorXd& u, const Eigen::VectorXd& v) const;
  void add_forces(Eigen::VectorXd& f) const;
  void add_tangents(Eigen::MatrixXd& K, double velocity_factor) const;
  void add_stiffness_products(const Eigen::VectorXd& x, Eigen::VectorXd& y) const;
  // Every element's outputs, one element after the other from out (output_count() each).
  void outputs(double* out) const;
  // power += sum of power(v), stored += sum of stored_energy(), in element order.
  void add_energy(const Eigen::VectorXd& v, double& power, double& stored) const;

 private:
  // single(element) for a run of one, batch(first, run, count) otherwise.
  template <class Single, class Batch>
  void for_each_run(Single&& single, Batch&& batch) const {
    for (const auto& [begin, count] : runs_) {
      Element* const* run = elements_.data() + begin;
      if (count == 1)
        single(*run[0]);
      else
        batch(*run[0], run, count);
    }
  }

  std::vector<Element*> elements_;
  std::vector<std::pair<int, int>> runs_;  // (first index, count)
};

}  // namespace isopound
