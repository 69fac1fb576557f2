// The built-in demo models of `isopound demo`: what isopound is for, with no file to write first.
//   3D (the default): the thesis's 3-storey building on 16 Bouc-Wen bearings, yielding columns,
//     moat walls 15 cm away on all four sides, under the built-in pulse pair at 30°, fixed 2 ms
//     steps (fine enough for floor spectra): some 40 impacts in 8 s, a few seconds to run.
//   2D (--2d): the thesis's 3-storey shear building on Bouc-Wen isolators, T_b = 2 s, Q/W = 5 %,
//     u_y = 1 cm, under the built-in near-fault pulse, no walls.
#pragma once

#include <string>

#include "solver/structures/config.h"

namespace isopound {

// The 3D demo as a commented model file: the demo writes it beside its results (the post tools
// read the plan geometry from the model file summary.json names) and a user can start from it.
const std::string& demo_model_3d_yaml();

ModelConfig demo_model_2d();

}  // namespace isopound
