// Reading `ground_motion:` (README "Model files", "3D buildings"): one record, a PEER .AT2 file
// (its NPTS/DT and unit from the header) or a column file (format, column or time_column, dt,
// unit), the built-in near-fault pulse, or for 3D structures a record pair L, T at an angle.
// Every key is used or refused; errors are InputErrors "file:line:col: key.path: what".
#pragma once

#include <string>
#include <string_view>

#include "solver/io/yaml_reader.h"
#include "solver/structures/config.h"

namespace isopound {

// The keys of `ground_motion:` that select a record pair.
inline constexpr std::string_view kPairKeys[] = {"L", "T", "angle"};

// `ground_motion:`; a relative record path is taken from base_dir.
GroundMotionConfig read_ground_motion(const InputNode& node, const std::string& base_dir);

}  // namespace isopound
