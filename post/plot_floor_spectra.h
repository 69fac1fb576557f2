// The floor-spectra figure: one panel per level (top floor first), its PSA against period (to 4 s)
// with the ground's for comparison; 2D the level's one direction; 3D x, y and RotD100 at the centre
// of mass, the largest RotD100 of the plan corners (wide and light, under the centre's), and the
// ground's RotD100. Axes (docs/floor-spectra.md): the period axis is logarithmic when the drawn
// periods span more than a decade; a panel's PSA axis is logarithmic when its peak is more than
// kLogPsaRatio times its largest value at periods of 1 s and longer (a base slab's impacts); each
// panel's title names its peak floor acceleration (the T = 0 value, off a log period axis).
#pragma once

#include <vector>

#include "post/figure.h"
#include "post/floor_spectra.h"
#include "post/xy_plot.h"

namespace isopound::post {

// Period axis logarithmic above this ratio of the longest to the shortest nonzero period drawn.
inline constexpr double kLogPeriodSpan = 10.0;
// PSA axis logarithmic above this ratio of a panel's peak to its largest value at T >= 1 s.
inline constexpr double kLogPsaRatio = 8.0;
// 3D: the corners' envelope wide and light under the centre of mass's RotD100, dark and narrow,
// so that both read where they coincide (a diaphragm that hardly rotates).
inline constexpr Rgb kCornersColour{244, 160, 160};
inline constexpr Rgb kCentreRotDColour{0, 100, 0};

// `frames` (optional): where each panel's data lands (PSA in g, period in s).
Figure floor_spectra_figure(const FloorSpectra& spectra, std::vector<PanelFrame>* frames = nullptr);

}  // namespace isopound::post
