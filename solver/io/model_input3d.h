// Reading the 3D buildings of a model file, `structures:` (rigid-diaphragm floors, columns,
// bearings, walls; contact3d_input.h reads their `contact:`, ground_motion_input.h the record
// pair). Every key is used or refused; errors are InputErrors "file:line:col: key.path: what".
#pragma once

#include <string>
#include <vector>

#include "solver/io/yaml_reader.h"
#include "solver/structures/config.h"
#include "solver/structures/config3d.h"

namespace isopound {

// `structures:`, a list of 3D buildings.
std::vector<Building3DConfig> read_structures3d(const InputNode& node);

}  // namespace isopound
