// One hysteresis law, one definition (issue 37 item 6): the same law keys are read, defaulted,
// accepted and refused identically wherever a member yields: a 2D storey, a 3D column, a 2D
// isolator, a 3D bearing (and the friction pendulum's smooth z). Before the table, n: 0.5 was
// accepted for a storey and refused for a column, post_yield_ratio defaulted to 0 for a storey and
// was required for a column, and the pendulum's smooth z refused its own shape keys.
#include <gtest/gtest.h>

#include <yaml-cpp/yaml.h>

#include <functional>
#include <map>
#include <string>
#include <vector>

#include "solver/io/model_input.h"
#include "solver/structures/config3d.h"

namespace isopound {
namespace {

constexpr const char* kBuilding2d = R"(building:
  base: {mass: 340 t}
  floors: {count: 3, mass: 340 t, roof_mass: 250 t, stiffness: 600 MN/m, height: 3.2 m@STOREY}
@ISOLATOR)";

constexpr const char* kBuilding3d = R"(structures:
  - name: b
    grid: {bays_x: [5.5 m], bays_y: [5.5 m]}
    columns: {section: [45 cm, 45 cm], E: 30 GPa, nu: 0.2@COLUMN}
    storeys: {count: 2, height: 3 m, mass: 100 t}
    base: {mass: 100 t}
    bearing: {model: @BEARING}
)";

// A member that yields: a model with `law` ("bouc_wen" or "bilinear": for the pendulum, its
// smooth or plastic z) and `keys` written into its law's map.
struct Member {
  std::string name;
  std::string section;  // key path of the law's map
  bool alpha_is_key;    // post_yield_ratio is its key (storeys, columns), else derived (Tb, QW, uy)
  std::function<std::string(const std::string& law, const std::string& keys)> text;
  std::function<BoucWenShape(const ModelConfig&)> shape;
};

std::string replace(std::string text, const std::string& mark, const std::string& by) {
  const auto at = text.find(mark);
  return at == std::string::npos ? text : text.replace(at, mark.size(), by);
}

std::string tail(const std::string& keys) {
  return keys.empty() ? "" : ", " + keys;
}

std::string model_2d(const std::string& storey, const std::string& isolator) {
  return replace(replace(kBuilding2d, "@STOREY", storey), "@ISOLATOR", isolator);
}

std::string model_3d(const std::string& column, const std::string& bearing) {
  return replace(replace(kBuilding3d, "@COLUMN", column), "@BEARING", bearing);
}

std::vector<Member> members() {
  return {
      {"2D storey", "building.floors.hysteresis", true,
       [](const std::string& law, const std::string& keys) {
         return model_2d(
             ", hysteresis: {model: " + law + ", yield_drift_ratio: 0.5 %" + tail(keys) + "}", "");
       },
       [](const ModelConfig& m) { return m.building.floors.at(0).hysteresis.law.bouc_wen; }},
      {"3D column", "structures[0].columns.hysteresis", true,
       [](const std::string& law, const std::string& keys) {
         return model_3d(",\n              hysteresis: {model: " + law +
                             ", yield_drift_ratio: 0.5 %" + tail(keys) + "}",
                         "bouc_wen");
       },
       [](const ModelConfig& m) {
         return m.structures3d.at(0).storeys.at(0).columns.at(0).hysteresis.law.bouc_wen;
       }},
      {"2D isolator", "building.isolator", false,
       [](const std::string& law, const std::string& keys) {
         return model_2d("", "  isolator: {model: " + law + tail(keys) + "}\n");
       },
       [](const ModelConfig& m) { return m.building.isolator.bouc_wen; }},
      {"3D bearing", "structures[0].bearing", false,
       [](const std::string& law, const std::string& keys) {
         return model_3d("", law + tail(keys));
       },
       [](const ModelConfig& m) { return m.structures3d.at(0).bearing.bouc_wen; }},
      {"2D friction pendulum", "building.isolator", false,
       [](const std::string& law, const std::string& keys) {
         return model_2d("",
                         "  isolator: {model: friction_pendulum, R: 2.2 m, mu_slow: 5 %, "
                         "mu_fast: 5 %, friction_hysteresis: " +
                             std::string(law == "bouc_wen" ? "bouc_wen" : "plastic") + tail(keys) +
                             "}\n");
       },
       [](const ModelConfig& m) { return m.building.isolator.bouc_wen; }},
  };
}

ModelConfig load(const std::string& text) {
  return load_model(YAML::Load(text), "model.yaml", "");
}

struct Case {
  std::string law;
  std::string keys;
  std::string refused_at;  // empty: accepted
  std::string what;        // part of the message, or the shape read when accepted
  BoucWenShape shape{};    // accepted: the shape the member holds
};

std::vector<Case> cases() {
  return {
      {"bouc_wen", "", "", "", {2.0, 1.0, 0.5, 0.5}},
      {"bouc_wen", "n: 1", "", "", {1.0, 1.0, 0.5, 0.5}},
      {"bouc_wen", "n: 3, A: 2, beta: 0.25, gamma: 75 %", "", "", {3.0, 2.0, 0.25, 0.75}},
      {"bouc_wen", "n: ~, beta: -0.25", "", "", {2.0, 1.0, -0.25, 0.5}},
      {"bouc_wen", "n: 0.5", "n", "must be >= 1"},
      {"bouc_wen", "n: 0", "n", "must be >= 1"},
      {"bouc_wen", "A: 0", "A", "must be > 0"},
      {"bouc_wen", "beta: -0.5", "beta", "beta + gamma must be > 0 (got 0)"},
      {"bouc_wen", "beta: -0.6, gamma: 0.6", "gamma", "beta + gamma must be > 0"},
      {"bouc_wen", "deterioration: 20", "deterioration", "is not used with model: "},
      {"bouc_wen", "capping_drift_ratio: 2 %", "capping_drift_ratio", "is not used with model: "},
      {"bilinear", "", "", "", {2.0, 1.0, 0.5, 0.5}},
      {"bilinear", "n: 2", "n", "is not used with model: "},
      {"bilinear", "gamma: 0.5", "gamma", "is not used with model: "},
  };
}

TEST(HysteresisInput, TheSameLawKeysAreReadAlikeInEveryMember) {
  for (const Member& member : members())
    for (const Case& c : cases()) {
      const std::string text = member.text(c.law, c.keys);
      SCOPED_TRACE(member.name + ", " + c.law + " {" + c.keys + "}\n" + text);
      try {
        const ModelConfig m = load(text);
        EXPECT_TRUE(c.refused_at.empty()) << "accepted";
        const BoucWenShape s = member.shape(m);
        EXPECT_EQ(s.n, c.shape.n);
        EXPECT_EQ(s.A, c.shape.A);
        EXPECT_EQ(s.beta, c.shape.beta);
        EXPECT_EQ(s.gamma, c.shape.gamma);
      } catch (const InputError& e) {
        EXPECT_EQ(e.key(), member.section + "." + c.refused_at) << e.what();
        EXPECT_NE(e.detail().find(c.what), std::string::npos) << e.what();
        EXPECT_GT(e.line(), 0) << e.what();
      }
    }
}

// The Bouc-Wen shape's defaults are listed as used, under the member's own key path.
TEST(HysteresisInput, TheShapeDefaultsAreListedInEveryMember) {
  for (const Member& member : members()) {
    SCOPED_TRACE(member.name);
    const ModelConfig m = load(member.text("bouc_wen", ""));
    const std::map<std::string, std::string> defaults(m.defaults.begin(), m.defaults.end());
    for (const auto& [key, value] :
         {std::pair{"n", "2"}, {"A", "1"}, {"beta", "0.5"}, {"gamma", "0.5"}}) {
      const auto it = defaults.find(member.section + "." + key);
      ASSERT_NE(it, defaults.end()) << key;
      EXPECT_EQ(it->second, value) << key;
    }
  }
}

// alpha: a key of storeys and columns, [0, 1), default 0 listed as used; isolators and bearings
// derive it from Tb, QW and uy and do not take it.
TEST(HysteresisInput, PostYieldRatioIsOneRuleWhereItIsAKey) {
  for (const Member& member : members()) {
    SCOPED_TRACE(member.name);
    for (const char* law : {"bilinear", "bouc_wen"}) {
      try {
        load(member.text(law, "post_yield_ratio: 5 %"));
        EXPECT_TRUE(member.alpha_is_key) << "accepted";
      } catch (const InputError& e) {
        EXPECT_FALSE(member.alpha_is_key) << e.what();
        EXPECT_EQ(e.key(), member.section + ".post_yield_ratio") << e.what();
      }
      if (!member.alpha_is_key) continue;
      // Absent: 0, listed under "Defaults used".
      const ModelConfig plain = load(member.text(law, ""));
      const std::map<std::string, std::string> defaults(plain.defaults.begin(),
                                                        plain.defaults.end());
      EXPECT_EQ(defaults.count(member.section + ".post_yield_ratio"), 1u);
      EXPECT_EQ(defaults.at(member.section + ".post_yield_ratio"), "0");
      for (const char* bad : {"post_yield_ratio: 1", "post_yield_ratio: 120 %"}) {
        try {
          load(member.text(law, bad));
          ADD_FAILURE() << bad << " accepted";
        } catch (const InputError& e) {
          EXPECT_EQ(e.key(), member.section + ".post_yield_ratio") << e.what();
        }
      }
    }
  }
  // The value read is the same in both members.
  const std::vector<Member> all = members();
  const ModelConfig storey = load(all[0].text("bouc_wen", "post_yield_ratio: 5 %"));
  const ModelConfig column = load(all[1].text("bouc_wen", "post_yield_ratio: 5 %"));
  EXPECT_EQ(storey.building.floors[0].hysteresis.post_yield_ratio, 0.05);
  EXPECT_EQ(column.structures3d[0].storeys[0].columns[0].hysteresis.post_yield_ratio, 0.05);
}

// peak_oriented has no biaxial form: a column, isolator or bearing refuses it at `model`.
TEST(HysteresisInput, PeakOrientedOnlyWhereItHasAForm) {
  const std::string keys = "capping_drift_ratio: 2 %, post_capping_ratio: 10 %";
  const std::vector<Member> all = members();
  EXPECT_NO_THROW(load(all[0].text("peak_oriented", keys)));
  for (std::size_t i = 1; i < 4; ++i) {
    const Member& member = all[i];
    try {
      load(member.text("peak_oriented", keys));
      ADD_FAILURE() << member.name << " accepted peak_oriented";
    } catch (const InputError& e) {
      EXPECT_EQ(e.key(), member.section + ".model") << e.what();
      EXPECT_NE(e.detail().find("unknown model 'peak_oriented'"), std::string::npos) << e.what();
    }
  }
}

}  // namespace
}  // namespace isopound
