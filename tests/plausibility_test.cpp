// Issue 24 item 1: plausibility as part of the key rule. Angles need a unit; every numeric key
// whose bare number is easily meant in another unit is range-checked against the one table
// (solver/io/plausibility.h, docs/plausibility.md): impossible -> error with a hint, implausible
// -> a warning (in summary.json; --strict refuses it).
#include <gtest/gtest.h>

#include <unistd.h>
#include <yaml-cpp/yaml.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <numbers>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "solver/io/model_input.h"
#include "solver/io/plausibility.h"
#include "solver/io/units.h"
#include "solver/io/yaml_reader.h"
#include "tests/test_support.h"

namespace isopound {
namespace {

namespace fs = std::filesystem;

ModelConfig load_text(const std::string& text) {
  return load_model(YAML::Load(text), "model.yaml", "");
}

InputError error_of(const std::string& text) {
  try {
    load_text(text);
  } catch (const InputError& e) {
    return e;
  }
  ADD_FAILURE() << "accepted:\n" << text;
  return InputError("", 0, 0, "", "");
}

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

constexpr const char* kBuilding2d = R"(
building:
  base: {mass: 340 t}
  floors: {count: 3, mass: 340 t, roof_mass: 250 t, stiffness: 600 MN/m, height: 3.2 m}
)";

// --- angles: a bare number is refused, naming both readings ---

TEST(Angles, ParseAngleNeedsDegOrRad) {
  EXPECT_DOUBLE_EQ(parse_angle("30 deg"), 30.0 * std::numbers::pi / 180.0);
  EXPECT_DOUBLE_EQ(parse_angle("0.5 rad"), 0.5);
  EXPECT_DOUBLE_EQ(parse_angle("-90 \xC2\xB0"), -std::numbers::pi / 2);
  try {
    parse_angle("30");
    ADD_FAILURE() << "a bare 30 was accepted";
  } catch (const UnitError& e) {
    const std::string m = e.what();
    EXPECT_TRUE(contains(m, "'30 deg'")) << m;
    EXPECT_TRUE(contains(m, "'30 rad' is 1718.87 deg")) << m;
  }
  EXPECT_THROW(parse_angle("0"), UnitError);  // any bare angle, even where both readings agree
  EXPECT_THROW(parse_angle("30 %"), UnitError);
  EXPECT_THROW(parse_angle("30 m"), UnitError);
}

// Every angle key of the reader, in 2D and 3D: the bare number is an error at its key.
TEST(Angles, EveryAngleKeyRefusesABareNumber) {
  const fs::path tutorial3d = test::source_dir() / "configs" / "tutorial-3d.yaml";
  const std::string pulse2d =
      std::string(kBuilding2d) + "ground_motion:\n  pulse: {amplitude: 1 m/s, phase: 30}\n";
  EXPECT_EQ(error_of(pulse2d).key(), "ground_motion.pulse.phase");
  EXPECT_TRUE(contains(error_of(pulse2d).detail(), "did you mean '30 deg'?"));

  // 3D: the tutorial writes every angle key with its unit; each made bare in turn is refused.
  const YAML::Node root = YAML::LoadFile(tutorial3d.string());
  int refused = 0;
  std::function<void(YAML::Node, const std::string&)> walk = [&](YAML::Node node,
                                                                 const std::string& path) {
    if (node.IsMap()) {
      for (auto entry : node) {
        const std::string key = entry.first.Scalar();
        const std::string child = path.empty() ? key : path + "." + key;
        if (entry.second.IsScalar() &&
            (key == "angle" || key == "rotation" || key == "orientation" || key == "phase")) {
          const std::string written = entry.second.Scalar();
          entry.second = "30";
          try {
            load_model(root, tutorial3d.string(), tutorial3d.parent_path().string());
            ADD_FAILURE() << child << ": a bare 30 was accepted";
          } catch (const InputError& e) {
            EXPECT_EQ(e.key(), child) << e.what();
            EXPECT_TRUE(contains(e.detail(), "30 deg") && contains(e.detail(), "30 rad"))
                << e.what();
            ++refused;
          }
          entry.second = written;
        } else {
          walk(entry.second, child);
        }
      }
    } else if (node.IsSequence()) {
      for (std::size_t i = 0; i < node.size(); ++i)
        walk(node[i], path + "[" + std::to_string(i) + "]");
    }
  };
  walk(root, "");
  EXPECT_GE(refused, 3);  // ground_motion.angle, structures[].rotation, columns' orientation
}

// --- the table ---

TEST(Plausibility, TableRowsAreConsistent) {
  std::set<std::string> seen;
  for (const PlausibleRange& r : plausible_ranges()) {
    const std::string id = std::string(r.key) + " " + r.dimension.to_string();
    EXPECT_TRUE(seen.insert(id).second) << "two rows for " << id;
    EXPECT_LE(r.hard_min, r.low) << r.key;
    EXPECT_LT(r.low, r.high) << r.key;
    EXPECT_LE(r.high, r.hard_max) << r.key;
    EXPECT_GT(r.unit_si, 0.0) << r.key;
    EXPECT_FALSE(r.what.empty()) << r.key;
  }
}

TEST(Plausibility, DocumentationListsEveryRow) {
  std::ifstream in(test::source_dir() / "docs" / "plausibility.md");
  ASSERT_TRUE(in) << "docs/plausibility.md";
  std::stringstream buffer;
  buffer << in.rdbuf();
  for (const PlausibleRange& r : plausible_ranges())
    EXPECT_TRUE(contains(buffer.str(), "| `" + std::string(r.key) + "` |"))
        << "docs/plausibility.md has no row for " << r.key;
}

TEST(Plausibility, VerdictsAtTheEdgesOfEachRow) {
  for (const PlausibleRange& r : plausible_ranges()) {
    const std::string path = "some.section." + std::string(r.key);
    const auto level = [&](double si) {
      return check_plausible(path, r.dimension, si, "x", false).level;
    };
    EXPECT_EQ(level(r.low), Plausibility::kOk) << r.key;
    EXPECT_EQ(level(r.high), Plausibility::kOk) << r.key;
    EXPECT_EQ(level(0.5 * (r.low + r.high)), Plausibility::kOk) << r.key;
    EXPECT_EQ(level(r.hard_max * 1.01 + 1e-9), Plausibility::kError) << r.key;
    if (r.hard_max > r.high) {
      EXPECT_EQ(level(0.5 * (r.high + r.hard_max)), Plausibility::kWarning) << r.key;
    }
    if (r.low > r.hard_min) {
      EXPECT_EQ(level(0.5 * (r.hard_min + r.low)), Plausibility::kWarning) << r.key;
    }
    EXPECT_EQ(level(r.hard_min - 1.0 - std::abs(r.hard_min)), Plausibility::kError) << r.key;
    // Another dimension is not this row (a row is key and dimension).
    EXPECT_EQ(check_plausible(path, Dimension{7, 7, 7}, 1e30, "x", false).level, Plausibility::kOk);
  }
}

// The issue's reproductions, through the reader.
TEST(Plausibility, IssueReproductions) {
  // gap: 15 is 15 m: impossible, with the hint.
  InputError e = error_of(std::string(kBuilding2d) + "  walls: {gap: 15}\n");
  EXPECT_EQ(e.key(), "building.walls.gap");
  EXPECT_TRUE(contains(e.detail(), "did you mean '15 cm'?")) << e.what();
  EXPECT_GT(e.line(), 0);
  // mu_fast: 8 (meant 8 %): impossible.
  e = error_of(std::string(kBuilding2d) +
               "  isolator: {model: friction_pendulum, R: 2.2 m, mu_slow: 4 %, mu_fast: 8, "
               "rate_parameter: 30 s/m, uy: 1 mm}\n");
  EXPECT_EQ(e.key(), "building.isolator.mu_fast") << e.what();
  EXPECT_TRUE(contains(e.detail(), "did you mean '8 %'?")) << e.what();
  // A floor mass of 340 (kg) under a 250 t roof: legal, implausible -> a warning with the hint.
  const ModelConfig m = load_text(
      "building:\n  base: {mass: 340 t}\n  floors:\n"
      "    - {mass: 340, stiffness: 600 MN/m, height: 3.2 m}\n"
      "    - {mass: 340 t, stiffness: 600 MN/m, height: 3.2 m}\n"
      "    - {mass: 250 t, stiffness: 600 MN/m, height: 3.2 m}\n");
  ASSERT_EQ(m.warnings.size(), 1u);
  EXPECT_TRUE(contains(m.warnings[0], "building.floors[0].mass")) << m.warnings[0];
  EXPECT_TRUE(contains(m.warnings[0], "did you mean '340 t'?")) << m.warnings[0];
  EXPECT_TRUE(contains(m.warnings[0], "model.yaml:")) << m.warnings[0];
  // The same value with its unit written is the same warning, without the hint.
  const ModelConfig m2 = load_text(
      "building:\n  base: {mass: 340 t}\n  floors:\n"
      "    - {mass: 340 kg, stiffness: 600 MN/m, height: 3.2 m}\n"
      "    - {mass: 340 t, stiffness: 600 MN/m, height: 3.2 m}\n");
  ASSERT_EQ(m2.warnings.size(), 1u);
  EXPECT_FALSE(contains(m2.warnings[0], "did you mean")) << m2.warnings[0];
}

// Table-driven over every numeric key the shipped models write: each bare number is replaced by
// one outside its possible range (refused at that key) and by one outside its plausible range
// (warned at that key, or refused by another rule at that key).
TEST(Plausibility, EveryNumericKeyOfTheShippedModels) {
  int refused = 0, refused_at_key = 0, warned = 0;
  std::set<std::string> keys_tried;
  for (const auto& entry : fs::directory_iterator(test::source_dir() / "configs")) {
    if (entry.path().extension() != ".yaml") continue;
    const std::string file = entry.path().string();
    const std::string dir = entry.path().parent_path().string();
    YAML::Node root;
    try {
      root = YAML::LoadFile(file);
      load_model(root, file, dir);
    } catch (const std::exception&) {
      continue;  // not a model (a polygon-pairs file)
    }
    std::function<void(YAML::Node, const std::string&, const std::string&)> walk =
        [&](YAML::Node node, const std::string& path, const std::string& key) {
          if (node.IsMap()) {
            for (auto e : node) {
              const std::string k = e.first.Scalar();
              walk(e.second, path.empty() ? k : path + "." + k, k);
            }
            return;
          }
          if (node.IsSequence()) {
            for (std::size_t i = 0; i < node.size(); ++i)
              walk(node[i], path + "[" + std::to_string(i) + "]", key);
            return;
          }
          if (!node.IsScalar()) return;
          Quantity q;
          try {
            q = parse_quantity(node.Scalar());
          } catch (const UnitError&) {
            return;  // not a number
          }
          const PlausibleRange* row = nullptr;
          for (const PlausibleRange& r : plausible_ranges())
            if (r.key == key && (!q.has_unit || r.dimension == q.dimension)) row = &r;
          if (row == nullptr) return;
          const std::string written = node.Scalar();
          const auto try_value = [&](double si, bool expect_error) {
            char text[40];
            std::snprintf(text, sizeof text, "%.6g", si);
            node = std::string(text);
            try {
              const ModelConfig m = load_model(root, file, dir);
              if (expect_error) {
                ADD_FAILURE() << file << ": " << path << ": " << text << " accepted";
              } else {
                bool found = false;
                for (const std::string& w : m.warnings) found = found || contains(w, path + ":");
                EXPECT_TRUE(found) << file << ": " << path << ": " << text << " not warned";
                warned += found;
              }
            } catch (const InputError& e) {
              // Refused: by the table at this key, or by a rule that reads it with others (a
              // step against steps_per_period, a storey height against a neighbour's).
              if (expect_error) refused_at_key += e.key() == path;
              refused += expect_error;
            }
          };
          keys_tried.insert(key);
          try_value(row->hard_max * 3 + 1, true);
          if (row->high < row->hard_max) try_value(0.5 * (row->high + row->hard_max), false);
          node = written;
        };
    walk(root, "", "");
  }
  EXPECT_GT(refused, 30);
  EXPECT_GT(refused_at_key, 0.9 * refused);
  EXPECT_GT(warned, 20);
  // The unit slips the issue names are among the keys tried.
  for (const char* key : {"gap", "mass", "stiffness", "uy", "QW", "Tb", "dt"})
    EXPECT_TRUE(keys_tried.count(key)) << key;
}

// Every numeric key the reader knows has a row or is a solver setting listed as unchecked.
TEST(Plausibility, EveryNumericKeyHasARowOrIsListedUnchecked) {
  for (const auto& entry : fs::directory_iterator(test::source_dir() / "configs"))
    if (entry.path().extension() == ".yaml") {
      try {
        load_model_file(entry.path().string());
      } catch (const std::exception&) {
      }
    }
  const auto keys = known_quantity_keys();
  ASSERT_GT(keys.size(), 40u);
  for (const auto& [path, dimension] : keys) {
    const std::string key = key_of(path);
    const bool unchecked = is_unchecked_key(key);
    EXPECT_TRUE(plausible_range_for(path, dimension) != nullptr || unchecked)
        << path << " (" << dimension.to_string()
        << ") has no plausibility row and is not listed as unchecked";
  }
}

// The shipped configs run unchanged: no warning from any of them.
TEST(Plausibility, ShippedConfigsGiveNoWarning) {
  for (const auto& entry : fs::directory_iterator(test::source_dir() / "configs")) {
    if (entry.path().extension() != ".yaml") continue;
    try {
      const ModelConfig m = load_model_file(entry.path().string());
      for (const std::string& w : m.warnings) ADD_FAILURE() << w;
    } catch (const InputError& e) {
      EXPECT_TRUE(contains(e.detail(), "pairs") || contains(e.what(), "overlap"))
          << entry.path() << ": " << e.what();
    }
  }
}

}  // namespace
}  // namespace isopound
