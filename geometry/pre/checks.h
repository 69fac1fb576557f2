// isopound-pre's warnings on a model (issue 12 item 1): storey stiffness jumps > 3x, very
// eccentric mass (EC8 4.2.3.2(6): e > 0.30 r) and bearings fewer than 3 or collinear. The site
// errors (overlaps, clearances against declared gaps, floors at equal levels, placements) are the
// reader's own checks, solver/io/site_checks.h, which isopound-pre runs through the reader.
#pragma once

#include <string>
#include <vector>

#include "geometry/pre/model_scan.h"
#include "geometry/pre/properties.h"
#include "solver/io/problems.h"
#include "solver/structures/site_plan.h"

namespace isopound::pre {

// Thresholds of the warnings.
struct CheckLimits {
  double stiffness_jump = 3.0;       // adjacent storeys' K ratio
  double eccentricity_ratio = 0.30;  // e / r (EC8 4.2.3.2(6))
};

// 3D models: per structure, stiffness jumps, eccentric mass, bearings.
void check_structures(const ScannedModel& model, const Site& site,
                      const std::vector<StructureProperties>& properties, const CheckLimits& limits,
                      ProblemList& problems);
// 2D models: stiffness jumps of the building's storeys.
void check_model2d(const ScannedModel& model, const CheckLimits& limits, ProblemList& problems);

}  // namespace isopound::pre
