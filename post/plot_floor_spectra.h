// The floor-spectra figure: one panel per level (top floor first), its PSA against period (to 4 s)
// with the ground's for comparison; 2D the level's one direction; 3D x, y and RotD100 at the centre
// of mass, the largest RotD100 of the plan corners, and the ground's RotD100.
#pragma once

#include "post/figure.h"
#include "post/floor_spectra.h"

namespace isopound::post {

Figure floor_spectra_figure(const FloorSpectra& spectra);

}  // namespace isopound::post
