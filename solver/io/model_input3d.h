// Reading the 3D parts of a model file: `structures:` (buildings with rigid-diaphragm floors,
// columns, bearings) and the record pair of `ground_motion:` (L, T, angle). Every key is used or
// refused; errors are InputErrors "file:line:col: key.path: what".
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "solver/io/yaml_reader.h"
#include "solver/structures/config.h"
#include "solver/structures/config3d.h"

namespace isopound {

// `structures:`, a list of 3D buildings.
std::vector<Building3DConfig> read_structures3d(const InputNode& node);

// `contact:`, the 3D pounding law of every polygon contact pair (THEORY §6).
ModelConfig::Contact3D read_contact3d(const InputNode& node);

// The keys of `ground_motion:` that select a record pair.
inline constexpr std::string_view kPairKeys[] = {"L", "T", "angle"};

// `ground_motion:` with L, T (each read by `read_component`, the one-component reader) and angle.
GroundMotionConfig read_ground_motion_pair(
    const InputNode& node,
    const std::function<GroundMotionConfig(const InputNode&)>& read_component);

}  // namespace isopound
