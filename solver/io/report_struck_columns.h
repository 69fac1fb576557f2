// Struck columns of 2D floor-to-column pounding (issue 26, docs/floor-to-column.md) in the run's
// summary and console: per struck storey, its peak shear against V_n (brittle shear failure:
// flag and first time), peak hinge moments against M_y, hinge ductilities, local drift (node
// minus the chord between the floors) and peak contact force.
#pragma once

#include <nlohmann/json.hpp>
#include <ostream>

#include "solver/core/analysis.h"
#include "solver/core/model.h"

namespace isopound {

// summary.json's "struck_columns" list; empty for a model without struck columns.
nlohmann::json struck_columns_json(const Model& model, const AnalysisResult& r);

// Console lines, one block per struck storey (nothing without struck columns).
void print_struck_columns(std::ostream& out, const Model& model, const AnalysisResult& r);

// The hinges' dissipated energy of every struck column, J; nullopt without any.
std::optional<double> struck_column_energy(const Model& model);

}  // namespace isopound
