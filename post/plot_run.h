// The figures of one run: time histories (ground and base, story drift ratios, absolute floor
// accelerations, impact forces) and hysteresis loops (isolator force vs deformation, impact force
// vs penetration), axes in engineering units (cm, g, kN or MN, %).
#pragma once

#include <string>
#include <vector>

#include "post/figure.h"
#include "post/run_data.h"

namespace isopound::post {

struct NamedFigure {
  std::string file;  // e.g. "time_histories.png"
  Figure figure;
};

// time_histories.png and hysteresis.png (the latter only when the run has isolators or contacts);
// a 3D run's figures are run_figures3d's (plot_run3d.h).
std::vector<NamedFigure> run_figures(const RunData& run);

// Force unit for a peak |F| in N: kN below 10 MN, else MN. Returns the divisor and sets unit.
double force_scale(double peak_newton, std::string& unit);

}  // namespace isopound::post
