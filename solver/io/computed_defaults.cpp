// Computed defaults stated with their values (computed_defaults.h). The rules are those of the
// model builders: building2d.cpp (isolator carried mass), building3d.cpp (bearing share, polar
// moment, THEORY eq. 5.9), pounding2d.cpp (a wall of stiffness 0 is rigid), analysis.cpp (the
// largest step from T_min, the output interval).
#include "solver/io/computed_defaults.h"

#include <cstdio>
#include <string_view>

#include "solver/structures/building2d.h"
#include "solver/structures/building3d.h"
#include "solver/structures/config3d.h"

namespace isopound {

namespace {

bool ends_with(std::string_view s, std::string_view tail) {
  return s.size() >= tail.size() && s.substr(s.size() - tail.size()) == tail;
}

// The index after `name[` in `key` (e.g. "structures[1].base" -> 1); -1 if absent.
int index_after(const std::string& key, const std::string& name) {
  const std::size_t at = key.find(name + "[");
  if (at == std::string::npos) return -1;
  return std::stoi(key.substr(at + name.size() + 1));
}

std::string number(double value, const char* unit) {
  char text[64];
  std::snprintf(text, sizeof text, "%.6g %s", value, unit);
  return text;
}

// The mass the bearings carry: the base slab and the floors above it (levels3d.h).
double isolated_mass3d(const Building3DConfig& b) {
  double m = b.isolated ? b.base.mass : 0.0;
  for (std::size_t s = static_cast<std::size_t>(b.isolation_level); s < b.storeys.size(); ++s)
    m += b.storeys[s].floor.mass;
  return m;
}

std::size_t bearing_count(const Building3DConfig& b) {
  return b.bearings.empty()
             ? b.storeys.at(static_cast<std::size_t>(b.isolation_level)).columns.size()
             : b.bearings.size();
}

// The computed value of one default with its rule, or "" when the default is a plain value.
std::string computed(const ModelConfig& config, const std::string& key, double record_dt,
                     const RunStatistics* stats) {
  const bool three_d = !config.structures3d.empty();
  const int b3 = index_after(key, "structures");
  const Building3DConfig* b =
      three_d && b3 >= 0 && b3 < static_cast<int>(config.structures3d.size())
          ? &config.structures3d[static_cast<std::size_t>(b3)]
          : nullptr;
  if (key == "output.interval") return number(record_dt, "s") + " (computed: every record sample)";
  if (key == "analysis.dt") {
    if (config.analysis.stepping == AnalysisConfig::Stepping::kFixed) return "";
    if (!stats)
      return "0 (the largest step from T_min / steps_per_period, set when the run starts)";
    if (stats->step_period > 0)
      return number(stats->interval, "s") +
             " (computed: the record interval divided to be <= T_min " +
             number(stats->step_period, "s") + " / " +
             number(config.analysis.steps_per_period, "steps per period)");
    return number(stats->interval, "s") + " (computed: the record interval)";
  }
  if (!three_d && ends_with(key, "isolator.carried_mass")) {
    const int n = index_after(key, "neighbours");
    const BuildingConfig& building = n >= 0 && n < static_cast<int>(config.neighbours.size())
                                         ? config.neighbours[static_cast<std::size_t>(n)].building
                                         : config.building;
    if (building.isolation_level > 0)
      return number(isolated_mass(building), "kg") +
             " (computed: the base slab and the floors above it)";
    return number(building_mass(building), "kg") +
           " (computed: the whole building incl. the base slab)";
  }
  if (!three_d && ends_with(key, "stiffness") && key.find("walls") != std::string::npos)
    return "rigid (0: an immovable wall; its mass enters only the impact damping)";
  if (b && ends_with(key, "carried_mass")) {
    const std::size_t n = bearing_count(*b);
    const double share = isolated_mass3d(*b) / static_cast<double>(n);
    if (key.find("bearings[") != std::string::npos && b->bearing.carried_mass > 0)
      return number(b->bearing.carried_mass, "kg") + " (computed: bearing.carried_mass)";
    return number(share, "kg") +
           (b->isolation_level > 0 ? " (computed: the mass above the bearings / "
                                   : " (computed: the building's mass / ") +
           std::to_string(n) + " bearings)";
  }
  if (b && ends_with(key, "polar_moment")) {
    const char* rule = b->polar_moment_rule == EccentricPolarMoment::kThesis
                           ? " (computed from the plan: m r_g^2 + m e^2, eq. 5.9)"
                           : " (computed from the plan: m r_g^2, polar_moment_rule: centroid)";
    std::vector<const Diaphragm3DConfig*> diaphragms;
    if (key.find(".base.") != std::string::npos) {
      diaphragms.push_back(&b->base);
    } else if (const int s = index_after(key, "storeys");
               s >= 0 && s < static_cast<int>(b->storeys.size())) {
      diaphragms.push_back(&b->storeys[static_cast<std::size_t>(s)].floor);
    } else {
      for (const Storey3DConfig& s : b->storeys) diaphragms.push_back(&s.floor);
    }
    std::string values;
    for (const Diaphragm3DConfig* d : diaphragms) {
      if (!values.empty()) values += ", ";
      values += number(polar_moment_about_cm(*d, b->polar_moment_rule), "kg m2");
    }
    return values + rule;
  }
  return "";
}

}  // namespace

std::vector<std::pair<std::string, std::string>> defaults_with_values(const ModelConfig& config,
                                                                      double record_dt,
                                                                      const RunStatistics* stats) {
  std::vector<std::pair<std::string, std::string>> out = config.defaults;
  for (auto& [key, value] : out) {
    const std::string value_and_rule = computed(config, key, record_dt, stats);
    if (!value_and_rule.empty()) value = value_and_rule;
  }
  return out;
}

}  // namespace isopound
