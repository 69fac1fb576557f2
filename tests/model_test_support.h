// Test helpers for models written inline and their histories: a model from YAML text (file name
// "model.yaml", paths relative to the working directory) and a history column by its name.
#pragma once

#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "solver/core/analysis.h"
#include "solver/excitation/ground_motion.h"
#include "solver/io/model_input.h"
#include "tests/test_support.h"

namespace isopound::test {

// A shipped config (configs/NAME) with its records read from wherever ../shared is
// (ISOPOUND_SHARED), not only next to the source tree.
inline ModelConfig load_shipped_config(const std::string& name) {
  const std::filesystem::path file = source_dir() / "configs" / name;
  std::ifstream in(file);
  std::stringstream text;
  text << in.rdbuf();
  std::string yaml = text.str();
  const std::string from = "../../shared/records";
  for (std::size_t at = yaml.find(from); at != std::string::npos; at = yaml.find(from))
    yaml.replace(at, from.size(), records_dir().string());
  return load_model(YAML::Load(yaml), file.string(), file.parent_path().string());
}

// No ground motion: `duration` s of zero acceleration at step dt (free vibration from the
// initial state).
inline GroundMotion still(double duration, double dt) {
  GroundMotion g;
  g.name = "still";
  g.dt = dt;
  g.acceleration.assign(static_cast<std::size_t>(std::round(duration / dt)) + 1, 0.0);
  return g;
}

inline ModelConfig load_model_text(const std::string& text) {
  return load_model(YAML::Load(text), "model.yaml", "");
}

// The index of the column `name` (with its unit, e.g. "main/base u [m]"); a test failure if none.
inline int history_column(const History& h, const std::string& name) {
  for (std::size_t c = 0; c < h.columns.size(); ++c)
    if (h.columns[c] == name) return static_cast<int>(c);
  ADD_FAILURE() << "no column '" << name << "'";
  return 0;
}

}  // namespace isopound::test
