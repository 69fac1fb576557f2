// Reading rubber bumpers (issue 27; docs/impact-laws.md, "Bumpers"): `bumper:` under a 2D
// wall or neighbour, and under 3D moat walls. Errors name file, line and key (InputError).
#pragma once

#include <functional>

#include "solver/io/yaml_reader.h"
#include "solver/materials/bumper_law.h"
#include "solver/structures/config3d.h"

namespace isopound {

// 2D: {thickness, law, k | (E, area), e, max_strain, min_impact_velocity, bottoming}; the
// thickness below `gap`, the smallest gap the rubber faces.
BumperConfig read_bumper(const InputNode& node, double gap);

// 3D walls: {sides, thickness, law, E, height, e, max_strain, mu_static, mu_kinetic, from, to};
// side_of reads a side name into MoatWalls3DConfig::Side.
MoatBumper3DConfig read_bumper3d(const InputNode& node, const MoatWalls3DConfig& walls,
                                 const std::function<int(const InputNode&)>& side_of);

// from/to inside every bumpered face of the building's moat walls (read after the building).
void check_bumper_span(const InputNode& walls_node, const Building3DConfig& b);

}  // namespace isopound
