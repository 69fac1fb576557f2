// summary.json and console lines of yielding 3D columns (issue 23): per column and enveloped per
// storey the shear, drift, ductility, time of first yield and hysteretic energy; per storey the
// shear in x, y and resultant, the residual drift ratio and the number of yielded columns; the
// elastic-validity flag of elastic storeys.
#pragma once

#include <nlohmann/json.hpp>
#include <ostream>

#include "solver/structures/job.h"

namespace isopound {

// Adds to building's json (summary3d_json's, with its "storeys"):
//  - always: "elastic_limit_drift_ratio" and "elastic_limit_exceeded" (an elastic storey, one
//    without yielding columns, whose peak drift ratio over its columns exceeds the limit; such a
//    storey also gets "elastic_limit_exceeded": true);
//  - for a building with yielding columns or P-Delta, per storey: "shear" (x, y, resultant, N,
//    V = -sum of M a_abs above), "residual_drift_ratio" (the largest column's at the end), and
//    with yielding columns "yielding": {"columns": [per column: shear, drift, ductility,
//    shear_x, shear_y, hysteretic_energy, first_yield_time_s or null], "peak_ductility",
//    "yielded_columns", "column_count", "first_yield_time_s", "hysteretic_energy_J"}; per
//    building "column_hysteretic_energy_J" (at the end; the part of the energy balance's hysteretic
//    term dissipated by the columns).
void add_column_yield_json(const JobResult& job, const StructureInfo& structure,
                           nlohmann::json& building);

// Console lines of one building of summary3d_json: yielding storeys and the elastic warning.
void print_column_yield(std::ostream& out, const nlohmann::json& building);

}  // namespace isopound
