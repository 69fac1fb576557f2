// "Defaults used" with the values the run computed: a key whose default is a rule rather than a
// number (carried_mass 0 = the building's mass, polar_moment 0 = from the plan, a wall's
// stiffness 0 = rigid, analysis.dt 0 = from T_min, output.interval 0 = the record interval) is
// listed with the rule and the value it gave, never as a bare 0.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "solver/core/analysis.h"
#include "solver/structures/config.h"

namespace isopound {

// config.defaults with every computed default stated: `record_dt` is the ground motion's
// interval, s; `stats` the run's statistics (analysis interval, T_min), or null before a run.
std::vector<std::pair<std::string, std::string>> defaults_with_values(const ModelConfig& config,
                                                                      double record_dt,
                                                                      const RunStatistics* stats);

}  // namespace isopound
