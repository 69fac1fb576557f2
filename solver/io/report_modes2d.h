// `isopound modes` for a 2D building as a reusable function (the same table main.cpp prints):
// fixed-base superstructure, then isolated with the isolators at K_post and K_el.
#pragma once

#include <ostream>

#include "solver/structures/config.h"

namespace isopound {

void print_modes2d(std::ostream& out, const BuildingConfig& building);

}  // namespace isopound
