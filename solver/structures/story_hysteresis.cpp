// A yielding storey's law from its configuration (the equations are in the header).
#include "solver/structures/story_hysteresis.h"

#include <stdexcept>

#include "solver/core/constants.h"
#include "solver/materials/bilinear.h"
#include "solver/materials/bouc_wen.h"
#include "solver/materials/peak_oriented.h"

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

std::unique_ptr<UniaxialMaterial> make_story_material(const BuildingConfig& b, int story) {
  const FloorConfig& f = b.floors[static_cast<std::size_t>(story)];
  const StoryHysteresisConfig& h = f.hysteresis;
  const double k = f.stiffness;
  const double d_y = story_yield_drift(b, story);
  using Model = StoryHysteresisConfig::Model;
  switch (h.model) {
    case Model::kElastic:
      break;
    case Model::kBilinear:
      return std::make_unique<BilinearMaterial>(k, h.post_yield_ratio, k * d_y);
    case Model::kBoucWen: {
      BoucWenParameters p;
      p.elastic_stiffness = k;
      p.alpha = h.post_yield_ratio;
      p.yield_force = k * d_y;
      p.yield_displacement = d_y;
      p.A = h.A;
      p.beta = h.beta;
      p.gamma = h.gamma;
      p.n = h.n;
      return std::make_unique<BoucWenMaterial>(p);
    }
    case Model::kPeakOriented: {
      PeakOrientedParameters p;
      p.elastic_stiffness = k;
      p.yield_deformation = d_y;
      p.post_yield_ratio = h.post_yield_ratio;
      p.capping_deformation = h.capping_drift_ratio * f.height;
      p.post_capping_ratio = h.post_capping_ratio;
      p.residual_strength_ratio = h.residual_strength_ratio;
      p.deterioration = h.deterioration;
      return std::make_unique<PeakOrientedMaterial>(p);
    }
  }
  throw std::invalid_argument("storey " + std::to_string(story + 1) + " of '" + b.name +
                              "' is elastic: it has no hysteretic law");
}

const char* story_hysteresis_name(StoryHysteresisConfig::Model model) {
  switch (model) {
    case StoryHysteresisConfig::Model::kElastic:
      return "elastic";
    case StoryHysteresisConfig::Model::kBilinear:
      return "bilinear";
    case StoryHysteresisConfig::Model::kBoucWen:
      return "bouc_wen";
    case StoryHysteresisConfig::Model::kPeakOriented:
      return "peak_oriented";
  }
  return "?";
}

}  // namespace isopound
