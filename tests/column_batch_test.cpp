// Batched column calls (Element::batch_key): runs of yielding 3D columns handed to the first one's
// *_batch() give, bit for bit, what the single calls on each give (trials, forces, tangents),
// for the coupled Bouc-Wen law (trials taken together) and the biaxial bilinear law, over runs
// that mix storeys (columns on the ground, between two diaphragms) and orientations.
#include <gtest/gtest.h>

#include <cstring>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "solver/elements/column_link.h"
#include "solver/materials/bilinear_biaxial.h"
#include "solver/materials/bouc_wen_coupled.h"

namespace isopound {
namespace {

constexpr double kAlpha = 0.05;

// Storey 1: 5 columns on the ground under diaphragm (0, 1, 2); storey 2: 4 columns between
// (3, 4, 5) and (0, 1, 2); then 1 more of storey 1 (a new run), all with the same law.
std::vector<std::unique_ptr<ColumnLink>> columns(bool coupled) {
  std::vector<std::unique_ptr<ColumnLink>> links;
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> plan(-8.0, 8.0), turn(0.0, 3.0), spread(0.8, 1.25);
  const auto add = [&](DiaphragmDofs upper, DiaphragmDofs lower) {
    ColumnLinkGeometry g{Eigen::Vector2d(plan(rng), plan(rng)), turn(rng),
                         Eigen::Vector2d(0.016 * spread(rng), 0.016 * spread(rng)),
                         Eigen::Vector2d(2e6 * spread(rng), 2e6 * spread(rng))};
    std::unique_ptr<BiaxialMaterial> law;
    if (coupled) {
      BoucWenParameters bw;
      bw.elastic_stiffness = bw.yield_force = bw.yield_displacement = 1.0;
      bw.alpha = kAlpha;
      law = std::make_unique<CoupledBoucWenMaterial>(bw);
    } else {
      law = std::make_unique<BilinearBiaxialMaterial>(1.0, kAlpha, 1.0);
    }
    std::string label = "C";  // (not "C" + ...: GCC 12's -Wrestrict false positive)
    label += std::to_string(links.size());
    links.push_back(std::make_unique<ColumnLink>(label, upper, lower, g, std::move(law), kAlpha));
  };
  for (int i = 0; i < 5; ++i) add({0, 1, 2}, {});
  for (int i = 0; i < 4; ++i) add({3, 4, 5}, {0, 1, 2});
  add({0, 1, 2}, {});
  return links;
}

bool same_bits(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b) {
  return a.size() == b.size() &&
         std::memcmp(a.data(), b.data(), sizeof(double) * static_cast<std::size_t>(a.size())) == 0;
}

TEST(ColumnBatch, BatchesGiveTheSingleCallsBitForBit) {
  for (const bool coupled : {true, false}) {
    auto single = columns(coupled);
    auto batched = columns(coupled);
    std::vector<Element*> run;
    for (auto& link : batched) run.push_back(link.get());
    for (const Element* e : run) ASSERT_EQ(e->batch_key(), run[0]->batch_key());
    ASSERT_NE(columns(!coupled)[0]->batch_key(), run[0]->batch_key());  // laws never mix
    const int count = static_cast<int>(run.size());
    std::mt19937 rng(11);
    std::normal_distribution<double> normal(0.0, 1.0);
    Eigen::VectorXd u = Eigen::VectorXd::Zero(6), v = Eigen::VectorXd::Zero(6);
    for (int step = 0; step < 300; ++step) {
      // Increments of ~0.25 d_y and, every 7th step, ~3 d_y (yielding, reversals).
      const double scale = step % 7 == 0 ? 0.05 : 0.004;
      Eigen::VectorXd du(6);
      for (int i = 0; i < 6; ++i) du[i] = scale * normal(rng) * (i % 3 == 2 ? 0.02 : 1.0);
      for (int trial = 0; trial < 2; ++trial) {
        const Eigen::VectorXd u1 = u + du * (trial == 0 ? 0.9 : 1.0);
        for (auto& link : single) link->set_trial(u1, v);
        run[0]->set_trial_batch(run.data(), count, u1, v);

        Eigen::VectorXd f_single = Eigen::VectorXd::Random(6), f_batch = f_single;
        for (auto& link : single) link->add_force(f_single);
        run[0]->add_force_batch(run.data(), count, f_batch);
        EXPECT_TRUE(same_bits(f_single, f_batch)) << "force, step " << step;

        Eigen::MatrixXd K_single = Eigen::MatrixXd::Random(6, 6), K_batch = K_single;
        for (auto& link : single) link->add_tangent(K_single, 0.0);
        run[0]->add_tangent_batch(run.data(), count, K_batch, 0.0);
        EXPECT_TRUE(same_bits(K_single, K_batch)) << "tangent, step " << step;
      }
      double yielded = 0.0;
      for (std::size_t i = 0; i < single.size(); ++i) {
        double a[11], b[11];
        single[i]->outputs(a);
        batched[i]->outputs(b);
        ASSERT_EQ(std::memcmp(a, b, sizeof a), 0) << "column " << i << ", step " << step;
        yielded = std::max(yielded, a[9]);
      }
      for (auto& link : single) link->commit();
      for (auto& link : batched) link->commit();
      u += du;
      if (step == 299) {
        EXPECT_EQ(yielded, 1.0) << "the columns yield during the test";
      }
      if (::testing::Test::HasFailure()) return;
    }
  }
}

}  // namespace
}  // namespace isopound
