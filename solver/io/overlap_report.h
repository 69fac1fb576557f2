// JSON for `isopound geometry overlap`: one object per polygon pair, SI with the unit in each key.
// Conventions are geometry/overlap.h's (n_AB from A into B; separation < 0 = penetration depth).
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "geometry/overlap.h"
#include "geometry/plan_overlap.h"

namespace isopound {

// {"pair", "name"?, "case", "area_m2", "centroid_m", "crossings_m", "normal", "tangent",
//  "indentation_m",
//  "mean_depth_m", "vertices", "polygon_m", "separation_m"}; the points and directions are null
// when the polygons are separated.
nlohmann::ordered_json overlap_json(int index, const std::string& name, const Overlap& overlap,
                                    const Separation& separation);

// A pair with a non-convex plan: {"pair", "name"?, "case": "contacts", "contacts": the number of
// connected overlap components, "area_m2": their sum, "components": [one object as above per
// component, without pair, name and separation], "separation_m"}.
nlohmann::ordered_json plan_overlap_json(int index, const std::string& name,
                                         const PlanOverlap& overlap,
                                         const Separation& separation);

// An array of such objects as text: one key per line, each value on one line.
std::string overlaps_text(const std::vector<nlohmann::ordered_json>& objects);

}  // namespace isopound
