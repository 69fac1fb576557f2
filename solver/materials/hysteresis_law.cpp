// The hysteresis-law table: names, shape keys, the one validation and the one factory of the
// uniaxial and biaxial forms (interface and laws: hysteresis_law.h).
#include "solver/materials/hysteresis_law.h"

#include <array>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "solver/materials/biaxial_uncoupled.h"
#include "solver/materials/bilinear.h"
#include "solver/materials/bilinear_biaxial.h"
#include "solver/materials/bouc_wen_coupled.h"
#include "solver/materials/peak_oriented.h"

namespace isopound {
namespace {

constexpr std::array<std::string_view, 4> kNames{"elastic", "bilinear", "bouc_wen",
                                                 "peak_oriented"};

// Bouc-Wen's four, then peak_oriented's four (hysteresis_shape_keys takes the halves).
constexpr std::array<HysteresisShapeKey, 8> kShapeKeys{{
    {"n", false, [](HysteresisLawConfig& c) -> double& { return c.bouc_wen.n; }},
    {"A", false, [](HysteresisLawConfig& c) -> double& { return c.bouc_wen.A; }},
    {"beta", false, [](HysteresisLawConfig& c) -> double& { return c.bouc_wen.beta; }},
    {"gamma", false, [](HysteresisLawConfig& c) -> double& { return c.bouc_wen.gamma; }},
    {"capping_drift_ratio", true,
     [](HysteresisLawConfig& c) -> double& { return c.peak_oriented.capping_drift_ratio; }},
    {"post_capping_ratio", true,
     [](HysteresisLawConfig& c) -> double& { return c.peak_oriented.post_capping_ratio; }},
    {"residual_strength_ratio", false,
     [](HysteresisLawConfig& c) -> double& { return c.peak_oriented.residual_strength_ratio; }},
    {"deterioration", false,
     [](HysteresisLawConfig& c) -> double& { return c.peak_oriented.deterioration; }, "none"},
}};

HysteresisProblem problem(std::string_view key, const char* what, double value,
                          std::string_view other_key = {}) {
  char got[48];
  std::snprintf(got, sizeof got, " (got %g)", value);
  return {key, other_key, std::string(what).append(got)};
}

}  // namespace

std::span<const std::string_view> hysteresis_model_names() {
  return kNames;
}

std::string_view hysteresis_model_name(HysteresisModel model) {
  return kNames[static_cast<std::size_t>(model)];
}

std::span<const HysteresisShapeKey> hysteresis_shape_keys(HysteresisModel model) {
  const std::span<const HysteresisShapeKey> all(kShapeKeys);
  switch (model) {
    case HysteresisModel::kBoucWen:
      return all.first(4);
    case HysteresisModel::kPeakOriented:
      return all.last(4);
    case HysteresisModel::kElastic:
    case HysteresisModel::kBilinear:
      break;
  }
  return {};
}

std::span<const HysteresisShapeKey> all_hysteresis_shape_keys() {
  return kShapeKeys;
}

std::optional<HysteresisProblem> hysteresis_law_problem(const HysteresisLawConfig& c) {
  if (c.model == HysteresisModel::kBoucWen) {
    const BoucWenShape& s = c.bouc_wen;
    if (!(s.n >= 1.0 && std::isfinite(s.n)))
      return problem("n", "must be >= 1, in every member (the coupled law needs it)", s.n);
    if (!(s.A > 0.0 && std::isfinite(s.A))) return problem("A", "must be > 0", s.A);
    if (!std::isfinite(s.beta)) return problem("beta", "must be finite", s.beta);
    if (!(s.beta + s.gamma > 0.0 && std::isfinite(s.gamma)))
      return problem("gamma", "beta + gamma must be > 0", s.beta + s.gamma, "beta");
  }
  if (c.model == HysteresisModel::kPeakOriented) {
    const PeakOrientedShape& s = c.peak_oriented;
    if (!(s.capping_drift_ratio > 0.0 && std::isfinite(s.capping_drift_ratio)))
      return problem("capping_drift_ratio", "must be > 0", s.capping_drift_ratio);
    if (!(s.post_capping_ratio > 0.0 && std::isfinite(s.post_capping_ratio)))
      return problem("post_capping_ratio", "must be > 0", s.post_capping_ratio);
    if (!(s.residual_strength_ratio >= 0.0 && s.residual_strength_ratio <= 1.0))
      return problem("residual_strength_ratio",
                     "must be in [0, 1] (a fraction of the yield strength)",
                     s.residual_strength_ratio);
    if (!(s.deterioration >= 0.0 && std::isfinite(s.deterioration)))
      return problem("deterioration", "must be >= 0 (0: no deterioration)", s.deterioration);
  }
  return std::nullopt;
}

std::optional<HysteresisProblem> post_yield_ratio_problem(double alpha) {
  if (alpha >= 0.0 && alpha < 1.0) return std::nullopt;
  return problem("post_yield_ratio", "must be in [0, 1): post-yield / elastic stiffness", alpha);
}

BoucWenParameters bouc_wen_parameters(const BoucWenShape& shape, const YieldPoint& yield) {
  BoucWenParameters p;
  p.elastic_stiffness = yield.elastic_stiffness;
  p.alpha = yield.post_yield_ratio;
  p.yield_force = yield.yield_force;
  p.yield_displacement = yield.yield_displacement;
  p.A = shape.A;
  p.beta = shape.beta;
  p.gamma = shape.gamma;
  p.n = shape.n;
  return p;
}

namespace {

void check(const HysteresisLawConfig& c) {
  if (c.model == HysteresisModel::kElastic)
    throw std::invalid_argument("an elastic member has no hysteresis law");
  if (const auto p = hysteresis_law_problem(c))
    throw std::invalid_argument(std::string(hysteresis_model_name(c.model)) + ": " +
                                std::string(p->key) + " " + p->what);
}

}  // namespace

std::unique_ptr<UniaxialMaterial> make_uniaxial_hysteresis(const HysteresisLawConfig& c,
                                                           const YieldPoint& y) {
  check(c);
  if (c.model == HysteresisModel::kBilinear)
    return std::make_unique<BilinearMaterial>(y.elastic_stiffness, y.post_yield_ratio,
                                              y.yield_force);
  if (c.model == HysteresisModel::kBoucWen)
    return std::make_unique<BoucWenMaterial>(bouc_wen_parameters(c.bouc_wen, y));
  const PeakOrientedShape& s = c.peak_oriented;
  PeakOrientedParameters p;
  p.elastic_stiffness = y.elastic_stiffness;
  p.yield_deformation = y.yield_displacement;
  p.post_yield_ratio = y.post_yield_ratio;
  p.capping_deformation = s.capping_drift_ratio * y.length;
  p.post_capping_ratio = s.post_capping_ratio;
  p.residual_strength_ratio = s.residual_strength_ratio;
  p.deterioration = s.deterioration;
  return std::make_unique<PeakOrientedMaterial>(p);
}

std::unique_ptr<BiaxialMaterial> make_biaxial_hysteresis(const HysteresisLawConfig& c,
                                                         const YieldPoint& y,
                                                         BiaxialInteraction interaction) {
  check(c);
  if (interaction == BiaxialInteraction::kSquare)
    return std::make_unique<UncoupledBiaxialMaterial>(make_uniaxial_hysteresis(c, y),
                                                      make_uniaxial_hysteresis(c, y));
  if (c.model == HysteresisModel::kBilinear)
    return std::make_unique<BilinearBiaxialMaterial>(y.elastic_stiffness, y.post_yield_ratio,
                                                     y.yield_force);
  if (c.model == HysteresisModel::kBoucWen)
    return std::make_unique<CoupledBoucWenMaterial>(bouc_wen_parameters(c.bouc_wen, y));
  throw std::invalid_argument(
      "peak_oriented has no biaxial form with a circular interaction (only two uniaxial laws)");
}

}  // namespace isopound
