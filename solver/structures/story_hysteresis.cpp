// A yielding storey's law from its configuration (the equations are in the header).
#include "solver/structures/story_hysteresis.h"

#include <stdexcept>

#include "solver/core/constants.h"

namespace isopound {

double weight_above_story(const BuildingConfig& b, int story) {
  double mass = 0.0;
  for (std::size_t i = static_cast<std::size_t>(story); i < b.floors.size(); ++i)
    mass += b.floors[i].mass;
  // A storey of the substructure under isolators also carries the isolated slab.
  if (b.isolated && story < b.isolation_level) mass += b.base_mass;
  return kGravity * mass;
}

double story_yield_drift(const BuildingConfig& b, int story) {
  const FloorConfig& f = b.floors[static_cast<std::size_t>(story)];
  const StoryHysteresisConfig& h = f.hysteresis;
  using By = StoryHysteresisConfig::YieldBy;
  switch (h.yield_by) {
    case By::kDriftRatio:
      return h.yield_value * f.height;
    case By::kShear:
      return h.yield_value / f.stiffness;
    case By::kShearCoefficient:
      return h.yield_value * weight_above_story(b, story) / f.stiffness;
  }
  return 0.0;
}

YieldPoint story_yield_point(const BuildingConfig& b, int story) {
  const FloorConfig& f = b.floors[static_cast<std::size_t>(story)];
  const double d_y = story_yield_drift(b, story);
  return {f.stiffness, f.stiffness * d_y, d_y, f.hysteresis.post_yield_ratio, f.height};
}

std::unique_ptr<UniaxialMaterial> make_story_material(const BuildingConfig& b, int story) {
  const StoryHysteresisConfig& h = b.floors[static_cast<std::size_t>(story)].hysteresis;
  if (!h.yields())
    throw std::invalid_argument("storey " + std::to_string(story + 1) + " of '" + b.name +
                                "' is elastic: it has no hysteretic law");
  return make_uniaxial_hysteresis(h.law, story_yield_point(b, story));
}

}  // namespace isopound
