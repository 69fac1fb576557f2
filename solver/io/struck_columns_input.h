// Reading a 2D building's facing column line (`columns:`, docs/floor-to-column.md), struck by
// another structure's slab between its floors. Errors name file, line and key (InputError).
#pragma once

#include "solver/io/yaml_reader.h"
#include "solver/structures/config.h"
#include "solver/structures/config3d.h"

namespace isopound {

// {count, E, I, M_y, hardening_ratio, shear_check, V_n}: M_y > 0; V_n required with
// shear_check: true; count x 12 E I / h^3 must not exceed any storey's stiffness (b's floors
// read before).
StruckColumnsConfig read_struck_columns(const InputNode& node, const BuildingConfig& b);

// A 3D building's `struck_columns: {M_y, hardening_ratio, shear_check, V_n}` (E, I11, I22 and
// the orientation come from the storey's columns): M_y > 0, one for both axes or [axis 1, axis
// 2]; V_n required with shear_check: true.
StruckColumns3DConfig read_struck_columns3d(const InputNode& node);

}  // namespace isopound
