// YAML input of the friction pendulum isolator: keys, units, defaults and the errors that name
// the key (model_input.cpp, read_friction_pendulum).
#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <string>

#include "solver/io/model_input.h"
#include "solver/io/yaml_reader.h"

namespace isopound {
namespace {

ModelConfig load_text(const std::string& text) {
  return load_model(YAML::Load(text), "fp.yaml", "/models");
}

const std::string kBase =
    "building: {base: {mass: 340 t}, floors: {count: 2, mass: 340 t, stiffness: 600 MN/m, "
    "height: 3.2 m}, ";

TEST(FrictionPendulumInput, KeysWithUnitsAndTheDefaultPreSlidingTravel) {
  const ModelConfig m = load_text(kBase +
                                  "isolator: {model: friction_pendulum, R: 2.2 m, mu_slow: 4 %, "
                                  "mu_fast: 0.1, rate_parameter: 0.3 s/cm}}");
  const IsolatorConfig& iso = m.building.isolator;
  EXPECT_EQ(iso.model, IsolatorConfig::Model::kFrictionPendulum);
  EXPECT_DOUBLE_EQ(iso.radius, 2.2);
  EXPECT_DOUBLE_EQ(iso.mu_slow, 0.04);
  EXPECT_DOUBLE_EQ(iso.mu_fast, 0.1);
  EXPECT_DOUBLE_EQ(iso.rate_parameter, 30.0);  // 0.3 s/cm = 30 s/m
  EXPECT_DOUBLE_EQ(iso.yield_displacement, 5e-4);
  EXPECT_FALSE(iso.smooth_friction);

  const ModelConfig smooth = load_text(
      kBase +
      "isolator: {model: friction_pendulum, R: 3 m, mu_slow: 0.05, mu_fast: 0.05, uy: 1 mm, "
      "friction_hysteresis: bouc_wen}}");
  EXPECT_DOUBLE_EQ(smooth.building.isolator.yield_displacement, 1e-3);
  EXPECT_DOUBLE_EQ(smooth.building.isolator.rate_parameter, 0.0);  // not needed: mu constant
  EXPECT_TRUE(smooth.building.isolator.smooth_friction);
}

void expect_error(const std::string& isolator, const std::string& key, const std::string& what) {
  try {
    load_text(kBase + "isolator: " + isolator + "}");
    ADD_FAILURE() << "no error for " << isolator;
  } catch (const InputError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find(key), std::string::npos) << message;
    EXPECT_NE(message.find(what), std::string::npos) << message;
  }
}

TEST(FrictionPendulumInput, BadInputNamesTheKey) {
  expect_error("{model: friction_pendulum, mu_slow: 0.04, mu_fast: 0.1, rate_parameter: 30}",
               "building.isolator", "R");
  expect_error("{model: friction_pendulum, R: 2 m, mu_slow: 0.04, mu_fast: 0.1}",
               "building.isolator", "rate_parameter");
  expect_error("{model: friction_pendulum, R: -2 m, mu_slow: 0.04, mu_fast: 0.04}",
               "building.isolator.R", "");
  expect_error("{model: friction_pendulum, R: 2 s, mu_slow: 0.04, mu_fast: 0.04}",
               "building.isolator.R", "");
  expect_error("{model: bouc_wen, R: 2 m}", "building.isolator.R", "not used with model: bouc_wen");
  expect_error("{model: friction_pendulum, R: 2 m, mu_slow: 0.04, mu_fast: 0.04, Tb: 2 s}",
               "building.isolator.Tb", "not used with model: friction_pendulum");
  expect_error(
      "{model: friction_pendulum, R: 2 m, mu_slow: 0.04, mu_fast: 0.04, friction_hysteresis: x}",
      "building.isolator.friction_hysteresis", "");
}

}  // namespace
}  // namespace isopound
