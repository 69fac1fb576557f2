// The figure of `isopound-post spectra`: PSA [g] and SD [cm] against period, one curve per record
// (each named in the legend), for a set the log-space median exp(mean ln) and the band
// exp(mean ln ± σ_ln) (spectra.h), and RotD50/RotD100 of horizontal pairs. Log-log axes: the
// zero period (PGA) is in spectra.csv only.
#pragma once

#include <string>
#include <vector>

#include "post/figure.h"
#include "post/spectra.h"
#include "post/xy_plot.h"

namespace isopound::post {

// `damping_percent` only names the damping in the panel titles. frames: xy_figure's.
Figure spectra_figure(const std::vector<Spectrum>& spectra, const SpectrumStatistics& stats,
                      const std::vector<RotDSpectrum>& rotd, double damping_percent,
                      std::vector<PanelFrame>* frames = nullptr);

}  // namespace isopound::post
