// Reading rubber bumpers (issue 27; docs/impact-laws.md, "Bumpers"): `bumper:` under a 2D
// wall or neighbour, under 3D moat walls and on a 3D building's slab faces. Errors name file, line
// and key (InputError).
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "solver/io/problems.h"
#include "solver/io/site_checks.h"
#include "solver/io/yaml_reader.h"
#include "solver/materials/bumper_law.h"
#include "solver/structures/config3d.h"

namespace isopound {

// 2D: {thickness, law, k | (E, area), e, max_strain, min_impact_velocity, bottoming}; the
// thickness below `gap`, the smallest gap the rubber faces.
BumperConfig read_bumper(const InputNode& node, double gap);

// A list of the faces of walls that follow the outline ("east", "north-east 2"), each once:
// `sides: [...]` of the walls and of their bumper (the names are checked against the outline
// with the plan). An empty list fails with `when_empty`.
std::vector<std::string> read_face_names(const InputNode& list, const std::string& when_empty);

// 3D walls: {sides, thickness, law, E, height, e, max_strain, mu_static, mu_kinetic, from, to};
// side_of reads a side name into MoatWalls3DConfig::Side.
Bumper3DConfig read_bumper3d(const InputNode& node, const MoatWalls3DConfig& walls,
                             const std::function<int(const InputNode&)>& side_of);

// 3D buildings: the same keys, rubber on the faces of every slab; `sides` (building frame)
// defaults to the face towards adjacent.to. Needs the building placed (adjacent read).
Bumper3DConfig read_slab_bumper3d(const InputNode& node, const Building3DConfig& building,
                                  const std::function<int(const InputNode&)>& side_of);

// Site check of the slab bumpers: no rubber touching or entering another structure's slab at its
// level at rest (the bumper thicker than the gap), blamed on the building's bumper.thickness.
void check_slab_bumpers(const ModelConfig& config, const std::vector<StructureMarks>& marks,
                        const Site& site, double level_tolerance, ProblemList& problems);

// from/to inside every bumpered face of the building's moat walls (read after the building).
void check_bumper_span(const InputNode& walls_node, const Building3DConfig& b);

}  // namespace isopound
