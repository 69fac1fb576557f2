// Batched bearing calls (Element::batch_key): a run of coupled Bouc-Wen bearings handed to the
// first one's *_batch() gives, bit for bit, what the single calls on each give: trials (the n = 2
// closed form and the general path, with reversals and large increments), forces, tangents and
// stiffness products, over runs that mix two diaphragms and bearings off a 3D diaphragm.
#include <gtest/gtest.h>

#include <cstring>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "solver/elements/bearing_link.h"
#include "solver/materials/bouc_wen_coupled.h"

namespace isopound {
namespace {

BoucWenParameters bearing_parameters() {
  BoucWenParameters p;
  p.yield_displacement = 0.01;
  p.yield_force = 1.2e5;
  p.elastic_stiffness = 1.2e7;
  p.alpha = 0.05;
  p.n = 2.0;
  p.beta = 0.5;
  p.gamma = 0.5;
  p.A = 1.0;
  return p;
}

// Two 3D diaphragms (DOFs 0-2 and 3-5), a slab whose DOFs are not consecutive (6, 8, 7) and a
// planar bearing (DOF 9): 5 + 4 + 2 + 1 bearings, in an order that makes several runs.
std::vector<std::unique_ptr<BearingLink>> bearings() {
  std::vector<std::unique_ptr<BearingLink>> links;
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> plan(-8.0, 8.0);
  const auto add = [&](DiaphragmDofs dofs) {
    std::string label = "B";
    label += std::to_string(links.size());
    links.push_back(std::make_unique<BearingLink>(
        label, dofs, Eigen::Vector2d(plan(rng), plan(rng)),
        std::make_unique<CoupledBoucWenMaterial>(bearing_parameters())));
  };
  for (int i = 0; i < 5; ++i) add({0, 1, 2});
  for (int i = 0; i < 4; ++i) add({3, 4, 5});
  add({6, 8, 7});
  add({0, 1, 2});
  add({9, -1, -1});
  add({6, 8, 7});
  return links;
}

bool same_bits(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b) {
  return a.size() == b.size() &&
         std::memcmp(a.data(), b.data(), sizeof(double) * static_cast<std::size_t>(a.size())) == 0;
}

TEST(BearingBatch, BatchesGiveTheSingleCallsBitForBit) {
  auto single = bearings();
  auto batched = bearings();
  std::vector<Element*> run;
  for (auto& link : batched) run.push_back(link.get());
  ASSERT_NE(run[0]->batch_key(), nullptr);
  for (const Element* e : run) ASSERT_EQ(e->batch_key(), run[0]->batch_key());
  const int count = static_cast<int>(run.size());

  std::mt19937 rng(11);
  std::normal_distribution<double> normal(0.0, 1.0);
  Eigen::VectorXd u = Eigen::VectorXd::Zero(10), v = Eigen::VectorXd::Zero(10);
  for (int step = 0; step < 400; ++step) {
    // Increments of ~0.4 u_y (mostly the n = 2 closed form) and, every 7th step, ~5 u_y (the
    // general path: full sub-increments, branch splits at reversals).
    const double scale = step % 7 == 0 ? 0.05 : 0.004;
    Eigen::VectorXd du(10);
    for (int i = 0; i < 10; ++i)
      du[i] = scale * normal(rng) * (i == 2 || i == 5 || i == 7 ? 0.02 : 1.0);
    for (int trial = 0; trial < 2; ++trial) {
      const Eigen::VectorXd u1 = u + du * (trial == 0 ? 0.9 : 1.0);
      for (auto& link : single) link->set_trial(u1, v);
      run[0]->set_trial_batch(run.data(), count, u1, v);

      Eigen::VectorXd f_single = Eigen::VectorXd::Random(10), f_batch = f_single;
      for (auto& link : single) link->add_force(f_single);
      run[0]->add_force_batch(run.data(), count, f_batch);
      EXPECT_TRUE(same_bits(f_single, f_batch)) << "force, step " << step;

      for (const double velocity_factor : {0.0, 800.0}) {
        Eigen::MatrixXd K_single = Eigen::MatrixXd::Random(10, 10), K_batch = K_single;
        for (auto& link : single) link->add_tangent(K_single, velocity_factor);
        run[0]->add_tangent_batch(run.data(), count, K_batch, velocity_factor);
        EXPECT_TRUE(same_bits(K_single, K_batch)) << "tangent, step " << step;
      }

      const Eigen::VectorXd x = Eigen::VectorXd::Random(10);
      Eigen::VectorXd y_single = Eigen::VectorXd::Random(10), y_batch = y_single;
      for (auto& link : single) link->add_stiffness_product(x, y_single);
      run[0]->add_stiffness_product_batch(run.data(), count, x, y_batch);
      EXPECT_TRUE(same_bits(y_single, y_batch)) << "stiffness product, step " << step;
    }
    for (std::size_t i = 0; i < single.size(); ++i) {
      double a[9], b[9];
      single[i]->outputs(a);
      batched[i]->outputs(b);
      ASSERT_EQ(
          std::memcmp(a, b, sizeof(double) * static_cast<std::size_t>(single[i]->output_count())),
          0)
          << "bearing " << i << ", step " << step;
    }
    // The batch's outputs (the resultants' square roots taken together), one after the other.
    std::vector<double> outputs_single, outputs_batch;
    for (auto& link : single) {
      double a[9];
      link->outputs(a);
      outputs_single.insert(outputs_single.end(), a, a + link->output_count());
    }
    outputs_batch.resize(outputs_single.size());
    run[0]->outputs_batch(run.data(), count, outputs_batch.data());
    ASSERT_EQ(std::memcmp(outputs_single.data(), outputs_batch.data(),
                          sizeof(double) * outputs_single.size()),
              0)
        << "outputs_batch, step " << step;
    for (auto& link : single) link->commit();
    for (auto& link : batched) link->commit();
    u += du;
    if (::testing::Test::HasFailure()) return;
  }
}

}  // namespace
}  // namespace isopound
