// The hysteresis-law table (solver/materials/hysteresis_law.h, issue 37 item 6): each shape key
// is validated at its own key; the factory's laws against closed forms (bilinear corner, Bouc-Wen
// n = 1 skeleton); the circular biaxial form is the uniaxial law on a uniaxial path, the square
// form two uniaxial laws; what has no law is refused.
#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <stdexcept>
#include <string>

#include <Eigen/Dense>

#include "solver/materials/hysteresis_law.h"

namespace isopound {
namespace {

HysteresisLawConfig valid(HysteresisModel model) {
  HysteresisLawConfig c;
  c.model = model;
  c.peak_oriented = {0.02, 0.1, 0.2, 0.0};
  return c;
}

// K_el 1e8 N/m, F_y 1e6 N, u_y 1 cm, alpha 5 %, a 3 m member.
constexpr YieldPoint kYield{1e8, 1e6, 0.01, 0.05, 3.0};

TEST(HysteresisLaw, TheTableNamesEachModelAndItsKeys) {
  const auto names = hysteresis_model_names();
  ASSERT_EQ(names.size(), 4u);
  EXPECT_EQ(hysteresis_model_name(HysteresisModel::kBoucWen), "bouc_wen");
  EXPECT_EQ(hysteresis_model_name(HysteresisModel::kPeakOriented), "peak_oriented");
  EXPECT_TRUE(hysteresis_shape_keys(HysteresisModel::kElastic).empty());
  EXPECT_TRUE(hysteresis_shape_keys(HysteresisModel::kBilinear).empty());
  EXPECT_EQ(hysteresis_shape_keys(HysteresisModel::kBoucWen).size(), 4u);
  EXPECT_EQ(hysteresis_shape_keys(HysteresisModel::kPeakOriented).size(), 4u);
  std::set<std::string_view> keys;
  for (const HysteresisShapeKey& k : all_hysteresis_shape_keys()) keys.insert(k.key);
  EXPECT_EQ(keys.size(), 8u);  // no key in two laws
  // The defaults are a valid law (the readers note them as used).
  EXPECT_FALSE(hysteresis_law_problem(valid(HysteresisModel::kBoucWen)));
  EXPECT_FALSE(hysteresis_law_problem(valid(HysteresisModel::kPeakOriented)));
  EXPECT_FALSE(hysteresis_law_problem(valid(HysteresisModel::kBilinear)));
}

// Each key's field, set to -1, is reported at that key (beta at gamma's rule, naming beta).
TEST(HysteresisLaw, EachShapeKeyIsValidatedAtItsOwnKey) {
  int checked = 0;
  for (const HysteresisModel model : {HysteresisModel::kBoucWen, HysteresisModel::kPeakOriented})
    for (const HysteresisShapeKey& k : hysteresis_shape_keys(model)) {
      HysteresisLawConfig c = valid(model);
      k.field(c) = -1.0;
      const auto problem = hysteresis_law_problem(c);
      ASSERT_TRUE(problem) << k.key;
      EXPECT_TRUE(problem->key == k.key || problem->other_key == k.key)
          << k.key << ": reported at " << problem->key;
      EXPECT_NE(problem->what.find("(got "), std::string::npos) << problem->what;
      ++checked;
    }
  EXPECT_EQ(checked, 8);
}

// One rule for n: >= 1 for every member (the coupled law needs it), so 0.5 is refused and 1 is not.
TEST(HysteresisLaw, BoucWenExponentIsAtLeastOne) {
  HysteresisLawConfig c = valid(HysteresisModel::kBoucWen);
  c.bouc_wen.n = 0.5;
  ASSERT_TRUE(hysteresis_law_problem(c));
  EXPECT_EQ(hysteresis_law_problem(c)->key, "n");
  EXPECT_NE(hysteresis_law_problem(c)->what.find("must be >= 1"), std::string::npos);
  EXPECT_THROW(make_uniaxial_hysteresis(c, kYield), std::invalid_argument);
  c.bouc_wen.n = 1.0;
  EXPECT_FALSE(hysteresis_law_problem(c));
  EXPECT_NO_THROW(make_biaxial_hysteresis(c, kYield));
  EXPECT_TRUE(post_yield_ratio_problem(1.0));
  EXPECT_TRUE(post_yield_ratio_problem(-0.01));
  EXPECT_FALSE(post_yield_ratio_problem(0.0));
}

// Bilinear: past yield F = F_y + alpha K (d - u_y). Bouc-Wen n = 1 on monotonic loading from rest:
// dz/dx = A - (beta + gamma) z, z = A/(beta + gamma) (1 - exp(-(beta + gamma) x)), x = d/u_y.
TEST(HysteresisLaw, UniaxialLawsAgainstClosedForms) {
  const double K = kYield.elastic_stiffness, Fy = kYield.yield_force,
               uy = kYield.yield_displacement;
  const double alpha = kYield.post_yield_ratio;
  auto bilinear = make_uniaxial_hysteresis(valid(HysteresisModel::kBilinear), kYield);
  bilinear->set_trial(3 * uy);
  EXPECT_NEAR(bilinear->force(), Fy + alpha * K * 2 * uy, 1e-9 * Fy);
  EXPECT_NEAR(bilinear->tangent(), alpha * K, 1e-9 * K);

  HysteresisLawConfig bw = valid(HysteresisModel::kBoucWen);
  bw.bouc_wen = {1.0, 1.0, 0.3, 0.7};
  auto law = make_uniaxial_hysteresis(bw, kYield);
  double worst = 0.0;
  for (int i = 1; i <= 400; ++i) {
    const double d = i * uy / 100;
    law->set_trial(d);
    law->commit();
    const double z = 1.0 - std::exp(-d / uy);
    worst = std::max(worst, std::abs(law->force() - (alpha * K * d + (1 - alpha) * Fy * z)));
  }
  EXPECT_LT(worst, 1e-4 * Fy);  // second-order steps of u_y/100
}

// A uniaxial path through both forms: the circular form's force along x is the uniaxial law's (to
// round-off: the coupled scheme reduces to the uniaxial one there) and nothing along y; the
// square form is two uniaxial laws, one per axis, on any path.
TEST(HysteresisLaw, BiaxialFormsReduceToTheUniaxialLaw) {
  for (const HysteresisModel model : {HysteresisModel::kBilinear, HysteresisModel::kBoucWen}) {
    SCOPED_TRACE(std::string(hysteresis_model_name(model)));
    const HysteresisLawConfig c = valid(model);
    auto uniaxial = make_uniaxial_hysteresis(c, kYield);
    auto uniaxial_y = make_uniaxial_hysteresis(c, kYield);
    auto circular = make_biaxial_hysteresis(c, kYield, BiaxialInteraction::kCircular);
    auto square = make_biaxial_hysteresis(c, kYield, BiaxialInteraction::kSquare);
    double worst_circular = 0.0, worst_square = 0.0;
    for (int i = 1; i <= 600; ++i) {
      const double t = i / 600.0;
      const double dx = 0.04 * std::sin(6.0 * t) * t, dy = 0.03 * std::cos(9.0 * t) * t;
      uniaxial->set_trial(dx);
      uniaxial_y->set_trial(dy);
      circular->set_trial(Eigen::Vector2d(dx, 0.0), Eigen::Vector2d::Zero());
      square->set_trial(Eigen::Vector2d(dx, dy), Eigen::Vector2d::Zero());
      worst_circular = std::max({worst_circular, std::abs(circular->force()[0] - uniaxial->force()),
                                 std::abs(circular->force()[1])});
      worst_square = std::max({worst_square, std::abs(square->force()[0] - uniaxial->force()),
                               std::abs(square->force()[1] - uniaxial_y->force())});
      for (auto* m : {uniaxial.get(), uniaxial_y.get()}) m->commit();
      circular->commit();
      square->commit();
    }
    EXPECT_LT(worst_circular, 1e-9 * kYield.yield_force);
    EXPECT_EQ(worst_square, 0.0);
  }
}

TEST(HysteresisLaw, WhatHasNoLawIsRefused) {
  EXPECT_THROW(make_uniaxial_hysteresis(valid(HysteresisModel::kElastic), kYield),
               std::invalid_argument);
  EXPECT_THROW(make_biaxial_hysteresis(valid(HysteresisModel::kElastic), kYield),
               std::invalid_argument);
  // peak_oriented has a uniaxial form and a square one, but no circular one.
  const HysteresisLawConfig peak = valid(HysteresisModel::kPeakOriented);
  EXPECT_NO_THROW(make_uniaxial_hysteresis(peak, kYield));
  EXPECT_NO_THROW(make_biaxial_hysteresis(peak, kYield, BiaxialInteraction::kSquare));
  EXPECT_THROW(make_biaxial_hysteresis(peak, kYield), std::invalid_argument);
  // An invalid shape is refused by the factory too, naming its key.
  HysteresisLawConfig bad = valid(HysteresisModel::kBoucWen);
  bad.bouc_wen.A = 0.0;
  try {
    make_biaxial_hysteresis(bad, kYield);
    ADD_FAILURE() << "A = 0 accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("A must be > 0"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace isopound
