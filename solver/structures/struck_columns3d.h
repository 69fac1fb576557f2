// Floor-to-column pounding in 3D (issue 26, docs/floor-to-column.md): where a slab of one 3D
// structure faces a storey of another strictly between its floors, each of that storey's columns
// whose section lies within contact.search_distance of the slab at rest becomes a StruckColumn3D.
// The column's lateral stiffness (R diag(k_1, k_2) R^T, torsion stays) moves from the storey
// matrix into the element, so the storey is unchanged while nothing strikes.
#pragma once

#include <string>
#include <vector>

#include "solver/core/model.h"
#include "solver/structures/config.h"
#include "solver/structures/config3d.h"

namespace isopound {

// One struck column found at rest.
struct StruckColumnSite {
  int striker = -1, struck = -1;  // indices into ModelConfig::structures3d
  std::string striker_name, struck_name;
  std::string slab_level;               // "floor 2", "base"
  double slab_elevation = 0.0;          // m
  int storey = 0;                       // 1-based storey of the struck structure
  double z_lower = 0.0, z_upper = 0.0;  // m, the storey's floors
  int column = -1;                      // index in that storey's columns
  std::string column_label;
  std::vector<Vec2> section_W;  // the column's section at rest (site_plan.h column_rectangle), m
  double separation = 0.0;      // m, slab to section at rest
  // "<striker>/<level> on <struck> story <k> column <label>"
  std::string label() const;
};

// The storey (1-based) of b whose floors z lies strictly between, by more than `tolerance`;
// 0 if none (at a floor, in an isolation gap, below the ground or above the roof).
int storey_between_floors(const Building3DConfig& b, double z, double tolerance);

// Every slab facing a storey between its floors, and the storey's columns within reach
// (struck structures with or without struck_columns given: the site checks refuse the latter).
std::vector<StruckColumnSite> struck_column_sites(const ModelConfig& config);

// Adds a StruckColumn3D per site of a structure with struck_columns given (the model holds the
// structures' DOFs already); nothing when pounding is off.
void add_struck_columns3d(Model& model, const ModelConfig& config);

}  // namespace isopound
