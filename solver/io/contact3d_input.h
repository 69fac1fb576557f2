// Reading `contact:`, the 3D pounding law of every polygon contact pair (THEORY section 6): its
// stiffness (k_normal and k_tangential, or the materials' E and nu), friction, restitution,
// indentation and overlap rules, or a 2D impact law along the normal (law:, the walls' keys).
#pragma once

#include "solver/io/yaml_reader.h"
#include "solver/structures/config.h"

namespace isopound {

ModelConfig::Contact3D read_contact3d(const InputNode& node);

}  // namespace isopound
