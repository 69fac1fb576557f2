// Runs of consecutive elements with one batch key, and the calls that go to them.
#include "solver/core/element_batches.h"

namespace isopound {

ElementBatches::ElementBatches(const std::vector<std::unique_ptr<Element>>& elements) {
  for (const auto& e : elements) {
    const void* key = e->batch_key();
    const int i = static_cast<int>(elements_.size());
    if (key && i > 0 && elements_.back()->batch_key() == key)
      ++runs_.back().second;
    else
      runs_.emplace_back(i, 1);
    elements_.push_back(e.get());
  }
}

void ElementBatches::set_trials(const Eigen::VectorXd& u, const Eigen::VectorXd& v) const {
  for_each_run([&](Element& e) { e.set_trial(u, v); },
               [&](Element& first, Element* const* run, int count) {
                 first.set_trial_batch(run, count, u, v);
               });
}

void ElementBatches::add_forces(Eigen::VectorXd& f) const {
  for_each_run([&](Element& e) { e.add_force(f); },
               [&](Element& first, Element* const* run, int count) {
                 first.add_force_batch(run, count, f);
               });
}

void ElementBatches::add_tangents(Eigen::MatrixXd& K, double velocity_factor) const {
  for_each_run([&](Element& e) { e.add_tangent(K, velocity_factor); },
               [&](Element& first, Element* const* run, int count) {
                 first.add_tangent_batch(run, count, K, velocity_factor);
               });
}

void ElementBatches::add_stiffness_products(const Eigen::VectorXd& x, Eigen::VectorXd& y) const {
  for_each_run([&](Element& e) { e.add_stiffness_product(x, y); },
               [&](Element& first, Element* const* run, int count) {
                 first.add_stiffness_product_batch(run, count, x, y);
               });
}

void ElementBatches::outputs(double* out) const {
  for (const auto& [begin, count] : runs_) {
    Element* const* run = elements_.data() + begin;
    if (count == 1)
      run[0]->outputs(out);
    else
      run[0]->outputs_batch(run, count, out);
    for (int i = 0; i < count; ++i) out += run[i]->output_count();
  }
}

void ElementBatches::add_energy(const Eigen::VectorXd& v, double& power, double& stored) const {
  for_each_run(
      [&](Element& e) {
        power += e.power(v);
        stored += e.stored_energy();
      },
      [&](Element& first, Element* const* run, int count) {
        first.add_energy_batch(run, count, v, power, stored);
      });
}

}  // namespace isopound
