// The one place where a model file becomes a ModelConfig (format: model_input.h and the report).
// Unknown keys, wrong types, units of the wrong dimension and out-of-range values are InputErrors.
#include "solver/io/model_input.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <optional>
#include <set>
#include <vector>

#include "solver/io/bumper_input.h"
#include "solver/io/contact3d_input.h"
#include "solver/io/ground_motion_input.h"
#include "solver/io/hysteresis_input.h"
#include "solver/io/isolator_input.h"
#include "solver/io/model_input3d.h"
#include "solver/io/site_checks.h"
#include "solver/io/struck_columns_input.h"
#include "solver/structures/building2d.h"
#include "solver/structures/config3d.h"
#include "solver/structures/rayleigh_modes.h"
#include "solver/structures/site_plan.h"
#include "solver/structures/story_hysteresis.h"

namespace isopound {
namespace {

namespace fs = std::filesystem;

constexpr int kIntMax = std::numeric_limits<int>::max();
// Limits of what a model may ask the reader to build (docs/input-limits.md, "What a model asks
// for"): the tallest buildings have ~160 storeys; a model assembles dense n x n matrices and
// solves their eigenproblem, so n is kept where that is milliseconds, as for 3D (kMaxStoreys).
constexpr int kMaxFloors = 200;
constexpr int kMaxHalvings = 60;  // dt / 2^60 is already far below any physical time scale
constexpr const char* kFixedBaseOnly = "not allowed for a fixed-base building (isolated: false)";

// A storey's `hysteresis:` map: the model, the storey's yield point (one of three keys) and
// alpha, and the law's shape (hysteresis_input.h). Keys the model does not use are refused.
StoryHysteresisConfig read_story_hysteresis(const InputNode& node) {
  using By = StoryHysteresisConfig::YieldBy;
  using M = HysteresisModel;
  node.expect_keys(with_hysteresis_keys({"model", "yield_drift_ratio", "yield_shear",
                                         "yield_shear_coefficient", "post_yield_ratio"}));
  StoryHysteresisConfig h;
  h.law.model =
      read_hysteresis_model(node, {M::kElastic, M::kBilinear, M::kBoucWen, M::kPeakOriented});
  if (!h.yields()) return h;
  int given = 0;
  if (const auto r = node.find("yield_drift_ratio")) {
    h.yield_by = By::kDriftRatio;
    h.yield_value = r->number(Bound::kPositive);
    ++given;
  }
  if (const auto v = node.find("yield_shear")) {
    h.yield_by = By::kShear;
    h.yield_value = v->quantity(dim::kForce, Bound::kPositive);
    if (given++) v->fail("give one of yield_drift_ratio, yield_shear, yield_shear_coefficient");
  }
  if (const auto c = node.find("yield_shear_coefficient")) {
    h.yield_by = By::kShearCoefficient;
    h.yield_value = c->number(Bound::kPositive);
    if (given++) c->fail("give one of yield_drift_ratio, yield_shear, yield_shear_coefficient");
  }
  if (!given)
    node.fail_at_key("yield_drift_ratio",
                     "missing: give yield_drift_ratio (d_y / h), yield_shear (a force) or "
                     "yield_shear_coefficient (V_y / weight above)");
  h.post_yield_ratio = read_post_yield_ratio(node);
  read_hysteresis_shape(node, h.law);
  return h;
}

// The capping drift of a peak_oriented storey must lie beyond its yield drift (known only once
// every floor, hence the weight above, is read).
void check_story_hysteresis(const BuildingConfig& b, const std::vector<InputNode>& nodes) {
  for (std::size_t i = 0; i < b.floors.size(); ++i) {
    const HysteresisLawConfig& law = b.floors[i].hysteresis.law;
    if (law.model != HysteresisModel::kPeakOriented) continue;
    const double d_y = story_yield_drift(b, static_cast<int>(i));
    const double d_c = law.peak_oriented.capping_drift_ratio * b.floors[i].height;
    if (!(d_c > d_y)) {
      char what[160];
      std::snprintf(what, sizeof what,
                    "the capping drift (%.4g m) must be beyond the yield drift (%.4g m)", d_c, d_y);
      nodes[i].required("capping_drift_ratio").fail(what);
    }
  }
}

std::vector<FloorConfig> read_floors(const InputNode& node,
                                     std::vector<InputNode>& hysteresis_nodes) {
  std::vector<FloorConfig> floors;
  if (node.is_sequence()) {
    for (const InputNode& item : node.elements()) {
      item.expect_keys({"mass", "stiffness", "height", "hysteresis"});
      if (!item.is_map()) item.fail("expected {mass, stiffness, height} of a floor");
      FloorConfig floor;
      floor.mass = item.required("mass").quantity(dim::kMass, Bound::kPositive);
      floor.stiffness = item.required("stiffness").quantity(dim::kStiffness, Bound::kPositive);
      floor.height = item.required("height").quantity(dim::kLength, Bound::kPositive);
      if (const auto h = item.find("hysteresis")) {
        floor.hysteresis = read_story_hysteresis(*h);
        hysteresis_nodes.push_back(*h);
      } else {
        hysteresis_nodes.push_back(item);
      }
      floors.push_back(floor);
    }
    if (floors.empty()) node.fail("no floors: give at least one {mass, stiffness, height}");
    if (floors.size() > kMaxFloors)
      node.fail("more than " + std::to_string(kMaxFloors) + " floors");
    return floors;
  }
  if (!node.is_map())
    node.fail(
        "expected a list of floors [{mass, stiffness, height}, ...] or the short form "
        "{count, mass, roof_mass, stiffness, height}; got " +
        node.kind());
  // Short form: `count` equal floors, the top one (the roof) optionally lighter.
  node.expect_keys({"count", "mass", "roof_mass", "stiffness", "height", "hysteresis"});
  const int count = node.required("count").integer(1, kMaxFloors);
  FloorConfig floor;
  floor.mass = node.required("mass").quantity(dim::kMass, Bound::kPositive);
  floor.stiffness = node.required("stiffness").quantity(dim::kStiffness, Bound::kPositive);
  floor.height = node.required("height").quantity(dim::kLength, Bound::kPositive);
  const auto h = node.find("hysteresis");
  if (h) floor.hysteresis = read_story_hysteresis(*h);
  floors.assign(static_cast<std::size_t>(count), floor);
  hysteresis_nodes.assign(static_cast<std::size_t>(count), h ? *h : node);
  node.read_quantity("roof_mass", dim::kMass, Bound::kPositive, floors.back().mass);
  return floors;
}

IsolatorConfig read_isolator(const InputNode& node) {
  using Model = IsolatorConfig::Model;
  node.expect_keys(isolator_keys());
  IsolatorConfig iso;
  node.read_choice<Model>("model",
                          {{"linear", Model::kLinear},
                           {"bilinear", Model::kBilinear},
                           {"bouc_wen", Model::kBoucWen},
                           {"friction_pendulum", Model::kFrictionPendulum}},
                          iso.model);
  read_isolator_keys(
      node, iso.model == Model::kFrictionPendulum, isolator_hysteresis_law(iso).model, iso, [&] {
        node.read_quantity("carried_mass", dim::kMass, Bound::kNonNegative, iso.carried_mass);
      });
  return iso;
}

// The two Rayleigh modes: distinct integers among the fixed-base modes 1..floor_count.
void read_rayleigh_modes(const InputNode& node, int floor_count, SuperstructureDamping& damping) {
  const std::vector<InputNode> modes = node.elements();
  if (modes.size() != 2)
    node.fail("expected two mode numbers, e.g. [1, 2]; got " + std::to_string(modes.size()));
  int values[2] = {0, 0};
  for (int i = 0; i < 2; ++i) {
    values[i] = modes[i].integer(1, kIntMax);
    if (values[i] > floor_count)
      modes[i].fail("mode " + std::to_string(values[i]) +
                    " does not exist: the fixed-base building has " + std::to_string(floor_count) +
                    " modes (one per floor)");
  }
  if (values[0] == values[1])
    node.fail("the two Rayleigh modes must differ (got " + std::to_string(values[0]) + " twice)");
  damping.mode_a = values[0];
  damping.mode_b = values[1];
}

// building.damping.substructure of a building isolated above storey k: {type, ratio, modes} of
// the fixed-base floors 1..k; by default modal with the superstructure's ratio.
void read_substructure_damping(const InputNode& building, const std::optional<InputNode>& damping,
                               const std::optional<InputNode>& substructure, BuildingConfig& b) {
  using Type = SuperstructureDamping::Type;
  SuperstructureDamping& s = b.substructure_damping;
  s.type = Type::kModal;
  s.ratio = b.damping.type == Type::kNone ? 0.0 : b.damping.ratio;
  if (!substructure) {
    (damping ? *damping : building)
        .note_default(damping ? "substructure" : "damping.substructure",
                      "modal, ratio " + std::to_string(s.ratio) + " (the superstructure's)");
    return;
  }
  substructure->expect_keys({"type", "ratio", "modes"});
  const auto type = substructure->find("type");
  if (type)
    s.type = type->choice<Type>(
        {{"rayleigh", Type::kRayleigh}, {"modal", Type::kModal}, {"none", Type::kNone}});
  else
    substructure->note_default("type", "modal");
  if (s.type != Type::kNone) substructure->read_number("ratio", Bound::kFraction, s.ratio);
  if (s.type != Type::kRayleigh) return;
  if (b.isolation_level < 2)
    (type ? *type : *substructure)
        .fail(
            "Rayleigh damping needs two fixed-base modes but a 1-storey substructure has one; "
            "use type: modal");
  if (const auto modes = substructure->find("modes"))
    read_rayleigh_modes(*modes, b.isolation_level, s);
  else
    substructure->note_default("modes", "[1, 2]");
}

// building.damping: {superstructure: {type, ratio, modes}, isolation, substructure}.
void read_damping(const InputNode& building, BuildingConfig& b) {
  using Type = SuperstructureDamping::Type;
  const auto damping = building.find("damping");
  std::optional<InputNode> superstructure;
  std::optional<InputNode> substructure;
  if (damping) {
    damping->expect_keys({"superstructure", "isolation", "substructure"});
    if (const auto isolation = damping->find("isolation")) {
      if (!b.isolated) isolation->fail(kFixedBaseOnly);
      b.isolation_damping_ratio = isolation->number(Bound::kFraction);
    }
    superstructure = damping->find("superstructure");
    substructure = damping->find("substructure");
    if (substructure && b.isolation_level == 0)
      substructure->fail("only for a building isolated above a storey (isolation_level > 0)");
  }
  if (b.isolated && !(damping && damping->has("isolation")))
    (damping ? *damping : building)
        .note_default(damping ? "isolation" : "damping.isolation", "0.05");
  if (!superstructure)
    (damping ? *damping : building)
        .note_default(damping ? "superstructure" : "damping.superstructure",
                      "rayleigh, ratio 0.02 at modes 1 and 2");
  SuperstructureDamping& s = b.damping;
  std::optional<InputNode> type, modes;
  if (superstructure) {
    superstructure->expect_keys({"type", "ratio", "modes"});
    type = superstructure->find("type");
    if (type)
      s.type = type->choice<Type>(
          {{"rayleigh", Type::kRayleigh}, {"modal", Type::kModal}, {"none", Type::kNone}});
    else
      superstructure->note_default("type", "rayleigh");
    if (s.type != Type::kNone) superstructure->read_number("ratio", Bound::kFraction, s.ratio);
    if (s.type == Type::kRayleigh) {
      modes = superstructure->find("modes");
      if (!modes) superstructure->note_default("modes", "[1, 2]");
    }
  }
  if (b.isolation_level > 0) read_substructure_damping(building, damping, substructure, b);
  if (s.type != Type::kRayleigh) return;
  const int floor_count = static_cast<int>(b.floors.size()) - b.isolation_level;
  if (floor_count < 2) {
    // Point at what chose Rayleigh: the written type, else the section that defaulted it.
    const std::string what =
        "Rayleigh damping needs two fixed-base modes but a 1-storey building has one; "
        "use type: modal";
    if (type) type->fail(what);
    if (superstructure) superstructure->fail_at_key("type", what + " (rayleigh is the default)");
    if (damping) damping->fail_at_key("superstructure", what + " (rayleigh is the default)");
    building.fail_at_key("damping.superstructure", what + " (rayleigh is the default)");
  }
  if (modes) read_rayleigh_modes(*modes, floor_count, s);
}

// The impact-law keys shared by walls and neighbours (THEORY section 4).
const std::vector<std::string_view> kImpactKeys = {
    "law", "k", "k_h", "n", "e", "material", "xi_formula", "min_impact_velocity"};

// Reads the law and only the parameters it uses (impact_law_uses): the law and its stiffness are
// required, and so is e for a dissipative law without a material; the rest is noted as default.
// Returns what the law uses (e.g. whether the other body's mass enters).
ImpactLawUses read_impact(const InputNode& node, ImpactLawConfig& c) {
  const auto law = node.required("law");
  c.law = law.choice<std::string>({{"linear", "linear"},
                                   {"kelvin_voigt", "kelvin_voigt"},
                                   {"modified_kelvin_voigt", "modified_kelvin_voigt"},
                                   {"ye", "ye"},
                                   {"mahmoud_jankowski", "mahmoud_jankowski"},
                                   {"pant_wijeyewickrema", "pant_wijeyewickrema"},
                                   {"hertz", "hertz"},
                                   {"jankowski", "jankowski"},
                                   {"hertz_damp_muthukumar", "hertz_damp_muthukumar"},
                                   {"hertz_damp_ye", "hertz_damp_ye"}});
  const ImpactLawUses uses = impact_law_uses(c.law);
  const auto stiffness = [&](const char* key, const char* other, const char* family) {
    const auto given = node.find(key);
    if (given) return *given;
    // The other family's stiffness given instead: the classic slip (k for a Hertz law).
    if (node.written(other))
      node.fail_at_key(key, "law " + c.law + " is a " + family + " law: it uses '" + key +
                                "', not '" + other + "'");
    return node.required(key);
  };
  if (uses.e) {
    node.read_choice<ImpactMaterial>("material",
                                     {{"none", ImpactMaterial::kNone},
                                      {"concrete", ImpactMaterial::kConcrete},
                                      {"steel", ImpactMaterial::kSteel},
                                      {"timber", ImpactMaterial::kTimber},
                                      {"ceramic", ImpactMaterial::kCeramic}},
                                     c.material);
    if (c.material == ImpactMaterial::kNone) {
      const InputNode e = node.required("e");
      c.e = e.number(Bound::kPositive);
      if (c.e > 1.0) e.fail("the coefficient of restitution must be in (0, 1]");
    } else if (const auto e = node.find("e")) {
      e->fail("give either e (constant) or material (velocity-dependent e), not both");
    }
  }
  if (uses.n) node.read_number("n", Bound::kPositive, c.n);
  if (uses.k)
    c.k = stiffness("k", "k_h", "linear-type").quantity(dim::kStiffness, Bound::kPositive);
  if (uses.k_h) {
    // k_h is in N/m^n: its dimension follows the exponent (n = 1.5 for Jankowski's law).
    const double n_h = c.law == "jankowski" ? 1.5 : c.n;
    c.k_h = stiffness("k_h", "k", "Hertz-type")
                .quantity(Dimension{1.0 - n_h, 1.0, -2.0}, Bound::kPositive);
  }
  if (uses.xi_formula)
    node.read_choice<std::string>("xi_formula", {{"eq_3_12", "eq_3_12"}, {"eq_3_11", "eq_3_11"}},
                                  c.xi_formula);
  if (uses.min_impact_velocity || c.material != ImpactMaterial::kNone)
    node.read_quantity("min_impact_velocity", dim::kVelocity, Bound::kPositive,
                       c.min_impact_velocity);
  return uses;
}

WallConfig read_wall(const InputNode& node) {
  std::vector<std::string_view> keys = {"sides", "gap",       "gap_left", "gap_right", "level",
                                        "mass",  "stiffness", "damping",  "bumper"};
  keys.insert(keys.end(), kImpactKeys.begin(), kImpactKeys.end());
  node.expect_keys(keys);
  WallConfig w;
  int which = 0;
  node.read_choice<int>("sides", {{"both", 0}, {"left", 1}, {"right", 2}}, which);
  w.left = which != 2;
  w.right = which != 1;
  // The gap decides whether pounding happens at all: never a default.
  if (const auto gap = node.find("gap")) {
    w.gap_left = w.gap_right = gap->quantity(dim::kLength, Bound::kNonNegative);
    for (const char* key : {"gap_left", "gap_right"})
      if (node.written(key))
        node.find(key)->fail("give either gap (both sides) or gap_left/gap_right");
  } else {
    if (!node.written("gap_left") && !node.written("gap_right"))
      node.fail_at_key("gap", "missing required key 'gap' (or gap_left/gap_right)");
    if (w.left) w.gap_left = node.required("gap_left").quantity(dim::kLength, Bound::kNonNegative);
    if (w.right)
      w.gap_right = node.required("gap_right").quantity(dim::kLength, Bound::kNonNegative);
  }
  node.read_integer("level", 0, 1000, w.level);
  node.read_quantity("stiffness", dim::kStiffness, Bound::kNonNegative, w.stiffness);
  if (w.stiffness > 0) node.read_number("damping", Bound::kFraction, w.damping_ratio);
  const ImpactLawUses uses = read_impact(node, w.impact);
  // A rigid wall's mass enters only the impact damping of the laws that use m_eff.
  if (w.stiffness > 0 || uses.mass)
    node.read_quantity("mass", dim::kMass, Bound::kPositive, w.mass);
  if (const auto bumper = node.find("bumper")) {
    const double gap = std::min(w.left ? w.gap_left : 1e300, w.right ? w.gap_right : 1e300);
    w.bumper = read_bumper(*bumper, gap);
  }
  return w;
}

BuildingConfig read_building(const InputNode& node);

NeighbourConfig read_neighbour(const InputNode& node) {
  node.expect_keys({"building", "side", "gap", "impact", "bumper", "ground_level"});
  NeighbourConfig n;
  n.building = read_building(node.required("building"));
  node.read_choice<bool>("side", {{"left", false}, {"right", true}}, n.right);
  n.gap = node.required("gap").quantity(dim::kLength, Bound::kNonNegative);
  const InputNode impact = node.required("impact");
  impact.expect_keys(kImpactKeys);
  read_impact(impact, n.impact);
  if (const auto bumper = node.find("bumper")) n.bumper = read_bumper(*bumper, n.gap);
  // Not noted as a default when absent: the buildings stand on one ground, as before.
  if (const auto ground = node.find("ground_level"))
    n.ground_level = ground->quantity(dim::kLength);
  return n;
}

// isolation_level k (0: on the ground; none, not even a default note, when absent) and, for
// k > 0, isolation_height, the isolated slab's elevation above floor k.
void read_isolation_level(const InputNode& node, BuildingConfig& b) {
  const auto level = node.find("isolation_level");
  const auto height = node.find("isolation_height");
  if (level) {
    if (!b.isolated) level->fail(kFixedBaseOnly);
    const int floors = static_cast<int>(b.floors.size());
    b.isolation_level = level->integer(0, kMaxFloors);
    if (b.isolation_level >= floors)
      level->fail("isolation_level " + std::to_string(b.isolation_level) +
                  " leaves no floor above the isolators: the building has " +
                  std::to_string(floors) + " floors (isolation_level 0.." +
                  std::to_string(floors - 1) + ")");
  }
  if (b.isolation_level == 0) {
    if (height) height->fail("only for a building isolated above a storey (isolation_level > 0)");
    return;
  }
  if (!height)
    node.fail_at_key("isolation_height",
                     "missing required key 'isolation_height' (the isolated slab's height above "
                     "floor " +
                         std::to_string(b.isolation_level) + ")");
  b.isolation_height = height->quantity(dim::kLength, Bound::kPositive);
}

BuildingConfig read_building(const InputNode& node) {
  node.expect_keys({"name", "isolated", "base", "floors", "isolation_level", "isolation_height",
                    "isolator", "damping", "walls", "p_delta", "elastic_limit_drift_ratio",
                    "columns"});
  BuildingConfig b;
  if (const auto name = node.find("name")) {
    b.name = name->string();
    if (b.name.empty()) name->fail("must not be empty");
  }
  if (const auto isolated = node.find("isolated")) b.isolated = isolated->boolean();
  if (b.isolated) {
    const InputNode base = node.required("base");
    base.expect_keys({"mass"});
    b.base_mass = base.required("mass").quantity(dim::kMass, Bound::kPositive);
  } else {
    for (const char* key : {"base", "isolator"})
      if (const auto n = node.find(key)) n->fail(kFixedBaseOnly);
  }
  std::vector<InputNode> hysteresis_nodes;
  b.floors = read_floors(node.required("floors"), hysteresis_nodes);
  read_isolation_level(node, b);
  check_story_hysteresis(b, hysteresis_nodes);
  // Not noted as defaults when absent: an elastic model's settings stay as they were.
  if (const auto p = node.find("p_delta")) b.p_delta = p->boolean();
  if (const auto l = node.find("elastic_limit_drift_ratio"))
    b.elastic_limit_drift_ratio = l->number(Bound::kPositive);
  // Without an isolator section the thesis isolator is used, each value noted as a default.
  if (b.isolated) {
    const auto isolator = node.find("isolator");
    b.isolator = read_isolator(isolator ? *isolator : node.empty_child("isolator"));
  }
  read_damping(node, b);
  if (const auto columns = node.find("columns")) b.columns = read_struck_columns(*columns, b);
  if (const auto walls = node.find("walls")) {
    const int levels = static_cast<int>(b.floors.size()) + (b.isolated ? 1 : 0);
    const auto add = [&](const InputNode& w) {
      b.walls.push_back(read_wall(w));
      if (b.walls.back().level >= levels)
        w.required("level").fail("level " + std::to_string(b.walls.back().level) +
                                 " does not exist (levels 0.." + std::to_string(levels - 1) + ")");
    };
    if (walls->is_sequence())
      for (const InputNode& w : walls->elements()) add(w);
    else
      add(*walls);
  }
  return b;
}

// `three_d`: the model has 3D structures, whose largest step follows the participating modes by
// default (a 2D building keeps every mode: its steps and results are those of before).
AnalysisConfig read_analysis(const InputNode& node, bool three_d) {
  using Stepping = AnalysisConfig::Stepping;
  using Rule = AnalysisConfig::MaxStepRule;
  node.expect_keys({"stepping", "dt", "steps_per_period", "max_step_rule",
                    "participation_threshold", "tolerance", "max_halvings", "newton_tolerance",
                    "max_iterations", "steps_per_contact", "locate_events", "t_end"});
  AnalysisConfig a;
  node.read_choice<Stepping>(
      "stepping", {{"adaptive", Stepping::kAdaptive}, {"fixed", Stepping::kFixed}}, a.stepping);
  if (a.stepping == Stepping::kFixed) {
    a.dt = node.required("dt").quantity(dim::kTime, Bound::kPositive);
  } else {
    node.read_quantity("dt", dim::kTime, Bound::kNonNegative, a.dt);
    if (a.dt == 0.0) {  // 0: the step follows the shortest period
      node.read_number("steps_per_period", Bound::kPositive, a.steps_per_period);
      a.max_step_rule = three_d ? Rule::kParticipating : Rule::kAllModes;
      node.read_choice<Rule>(
          "max_step_rule",
          {{"participating", Rule::kParticipating}, {"all_modes", Rule::kAllModes}},
          a.max_step_rule);
      if (a.max_step_rule == Rule::kParticipating) {
        node.read_number("participation_threshold", Bound::kPositive, a.participation_threshold);
        if (const auto t = node.find("participation_threshold");
            t && !(a.participation_threshold < 1.0))
          t->fail("must be below 1 (a fraction of the total mass, e.g. 1e-5)");
      }
    }
    node.read_number("tolerance", Bound::kPositive, a.tolerance);
    node.read_number("steps_per_contact", Bound::kPositive, a.steps_per_contact);
  }
  node.read_integer("max_halvings", 0, kMaxHalvings, a.max_halvings);
  node.read_number("newton_tolerance", Bound::kPositive, a.newton_tolerance);
  node.read_integer("max_iterations", 1, kIntMax, a.max_iterations);
  node.read_boolean("locate_events", a.locate_events);
  // Absent: the whole record (not a default value, so not listed among the defaults).
  if (const auto t_end = node.find("t_end"))
    a.t_end = t_end->quantity(dim::kTime, Bound::kPositive);
  return a;
}

OutputConfig read_output(const InputNode& node) {
  node.expect_keys({"interval", "histories", "floor_spectra"});
  OutputConfig o;
  node.read_boolean("histories", o.histories);
  node.read_boolean("floor_spectra", o.floor_spectra);
  if (o.histories) node.read_quantity("interval", dim::kTime, Bound::kNonNegative, o.interval);
  return o;
}

int line_of(const YAML::Mark& mark) {
  return mark.is_null() ? 0 : mark.line + 1;
}
int column_of(const YAML::Mark& mark) {
  return mark.is_null() ? 0 : mark.column + 1;
}

}  // namespace

ImpactLawUses read_impact_law(const InputNode& node, ImpactLawConfig& config) {
  return read_impact(node, config);
}

namespace {

// Rayleigh damping at two fixed-base modes of (nearly) equal frequency is refused at its key
// (rayleigh_modes.h); any other inconsistency is reported when the model is built, as before.
void check_damping_modes2d(const InputNode& building, const BuildingConfig& b) {
  try {
    superstructure_damping(b);
  } catch (const RayleighModesError& e) {
    building.fail_at_key("damping.superstructure.modes", e.what());
  } catch (const std::invalid_argument&) {
  }
}

}  // namespace

ModelConfig load_model(const YAML::Node& root, const std::string& source_name,
                       const std::string& base_dir, std::vector<std::string>* used_keys,
                       ProblemList* site_problems) {
  try {
    const InputNode top = InputNode::tracked(root, source_name);
    top.expect_keys(
        {"building", "neighbours", "structures", "contact", "ground_motion", "analysis", "output"});
    ModelConfig model;
    model.source = source_name;
    ProblemList own_problems;
    ProblemList& problems = site_problems ? *site_problems : own_problems;
    if (const auto structures = top.find("structures")) {  // 3D: model_input3d.cpp
      for (const char* key : {"building", "neighbours"})
        if (const auto n = top.find(key))
          n->fail("a 2D building cannot be combined with 3D structures (structures:)");
      model.structures3d = read_structures3d(*structures);
      if (const auto c = top.find("contact")) model.contact3d = read_contact3d(*c);
      check_site3d(model, structure_marks(*structures), site_plan(model), site_limits(model),
                   problems);
      if (!site_problems) problems.throw_errors();
    } else {
      if (const auto c = top.find("contact"))
        c->fail(
            "contact: is the 3D pounding law (with structures:); 2D walls and neighbours "
            "take their impact law in their own section");
      model.building = read_building(top.required("building"));
    }
    if (model.structures3d.empty()) check_damping_modes2d(top.required("building"), model.building);
    if (const auto list = top.find("neighbours")) {
      if (!list->is_sequence()) list->fail("must be a list of neighbours");
      for (const InputNode& n : list->elements()) {
        model.neighbours.push_back(read_neighbour(n));
        check_damping_modes2d(n.required("building"), model.neighbours.back().building);
      }
      check_site2d(model, list->elements(), problems);
      if (!site_problems) problems.throw_errors();
    }
    if (const auto n = top.find("ground_motion"))
      model.ground_motion = read_ground_motion(*n, base_dir);
    else
      top.note_default("ground_motion",
                       "the built-in near-fault pulse (amplitude 1 m/s, period 2 s)");
    // An absent section reads as an empty one: its defaults are noted like any other.
    const auto section = [&](const char* key) {
      if (const auto n = top.find(key)) return *n;
      return top.empty_child(key);
    };
    model.analysis = read_analysis(section("analysis"), !model.structures3d.empty());
    model.output = read_output(section("output"));
    // Structure names label every output: two equal ones would mix their peaks.
    std::set<std::string> names{model.building.name};  // not a scan per name: n log n, not n^2
    for (std::size_t i = 0; i < model.neighbours.size(); ++i) {
      const std::string& name = model.neighbours[i].building.name;
      if (!names.insert(name).second)
        top.find("neighbours")
            ->elements()[i]
            .fail_at_key("building.name",
                         "duplicate structure name '" + name +
                             "': give each building its own name (default 'building')");
    }
    if (used_keys) *used_keys = top.used_keys();
    top.refuse_unused();
    for (const DefaultUsed& d : top.defaults_used()) model.defaults.emplace_back(d.key, d.value);
    model.warnings = top.warnings();
    return model;
  } catch (const YAML::Exception& e) {
    // Not expected (keys are found by iteration, never indexed), but keep the promise of
    // InputError.
    throw InputError(source_name, line_of(e.mark), column_of(e.mark), "", "YAML error: " + e.msg);
  }
}

ModelConfig load_model_file(const std::string& path) {
  const std::string text = read_input_file(path, "a YAML model file");
  const YAML::Node root = parse_single_document(text, path, "a model file");
  return load_model(root, path, fs::path(path).parent_path().string());
}

}  // namespace isopound
