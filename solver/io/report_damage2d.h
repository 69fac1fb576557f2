// Damage measures of the storeys of 2D buildings (issue 23): for a yielding storey its peak
// ductility mu = peak |drift| / d_y, residual drift at the end of the analysis (the record plus
// extra_time: give extra_time to let the building come to rest), dissipated hysteretic energy and
// time of first yield (|drift| >= d_y); for an elastic storey, whether its peak drift ratio is
// beyond the elastic model's range (StructureInfo::elastic_limit_drift_ratio).
#pragma once

#include <cstddef>
#include <nlohmann/json.hpp>
#include <ostream>

#include "solver/core/analysis.h"
#include "solver/core/model.h"

namespace isopound {

class StoryLink;

// The hysteretic law of story k of structure s, or null (an elastic story).
const StoryLink* story_link(const Model& model, const StructureInfo& s, std::size_t k);

// Keys added to story k's entry of summary.json (story_index: its index in r.stories); nothing
// for an elastic story within its limit, so elastic results stay as they were.
void add_story_damage_json(nlohmann::json& story, const Model& model, const AnalysisResult& r,
                           const StructureInfo& s, std::size_t k, std::size_t story_index);

// Console: after story k's line, its damage measures or the elastic-range warning (if any).
void print_story_damage(std::ostream& out, const Model& model, const AnalysisResult& r,
                        const StructureInfo& s, std::size_t k, std::size_t story_index);

// Energy dissipated by every yielding story of the model, J (0 without any).
double story_hysteretic_energy(const Model& model);
bool has_yielding_stories(const Model& model);

}  // namespace isopound
