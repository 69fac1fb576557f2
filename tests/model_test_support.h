// Test helpers for models written inline and their histories: a model from YAML text (file name
// "model.yaml", paths relative to the working directory) and a history column by its name.
#pragma once

#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <algorithm>
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

// Contact episodes in a history (columns `force` and `dissipated`: a contact is open where its
// force is 0): each is checked passive, the net work of the contact force on the bodies over it
// <= 0, i.e. the contact's dissipated energy, read whenever it opens, never decreases. Returns
// the number of episodes that ended.
// The largest peak over every element output whose name starts with `prefix` ("ductility_":
// how far any hinge of the model yielded).
inline double largest_output_peak(const Model& model, const AnalysisResult& r,
                                  const std::string& prefix) {
  double largest = 0.0;
  for (std::size_t e = 0; e < model.elements.size(); ++e) {
    const Element& el = *model.elements[e];
    for (int k = 0; k < el.output_count(); ++k)
      if (el.output_name(k).starts_with(prefix))
        largest = std::max(largest, r.element_outputs[e][k].value);
  }
  return largest;
}

inline int passive_episodes(const History& h, int force, int dissipated) {
  const std::size_t cols = h.columns.size();
  double last_open = 0.0;
  int episodes = 0;
  bool was_open = true;
  for (std::size_t row = 0; row < h.rows(); ++row) {
    const double* v = &h.values[row * cols];
    const bool open = v[force] == 0.0;
    if (open && !was_open) {
      ++episodes;
      EXPECT_GE(v[dissipated], last_open - 1e-9 * std::abs(last_open)) << "row " << row;
      last_open = v[dissipated];
    }
    was_open = open;
  }
  return episodes;
}

}  // namespace isopound::test
