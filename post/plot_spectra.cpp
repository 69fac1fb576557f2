// Spectra figure (see plot_spectra.h).
#include "post/plot_spectra.h"

#include <cstdio>
#include <optional>

#include "solver/core/constants.h"

namespace isopound::post {

Figure spectra_figure(const std::vector<Spectrum>& spectra, const SpectrumStatistics& stats,
                      const std::vector<RotDSpectrum>& rotd, double damping_percent,
                      std::vector<PanelFrame>* frames) {
  char damping[32];
  std::snprintf(damping, sizeof damping, "%g %%", damping_percent);
  Panel psa{"Pseudo-acceleration, ξ = " + std::string(damping),
            "period T [s]",
            "PSA [g]",
            {},
            true,
            false,
            true};
  Panel sd{"Displacement, ξ = " + std::string(damping),
           "period T [s]",
           "SD [cm]",
           {},
           true,
           false,
           true};
  // Log-log, as spectra of a set are read (T = 0, the PGA, and SD(0) = 0 are not on it).
  for (Panel* p : {&psa, &sd}) {
    p->log_x = p->log_y = true;
    p->legend_at = Panel::LegendAt::kBest;
  }
  const auto add = [&](const std::string& label, const std::vector<double>& period,
                       const std::vector<double>& p, const std::vector<double>& d,
                       std::optional<Rgb> c, double w) {
    psa.series.push_back({label, period, scaled(p, kGravity), c, w});
    sd.series.push_back({label, period, scaled(d, 0.01), c, w});
  };
  const bool set = spectra.size() > 1;
  // Records thin in their own colours when the set's statistics are drawn over them.
  for (std::size_t k = 0; k < spectra.size(); ++k)
    add(spectra[k].name, spectra[k].period, spectra[k].psa, spectra[k].sd,
        series_colour(static_cast<int>(k)), set ? 1.0 : 1.8);
  if (set) {
    add("median exp(mean ln)", stats.period, stats.median_psa, stats.median_sd, Rgb{0, 0, 0}, 2.5);
    add("exp(mean ln ± σ_ln)", stats.period, stats.upper_psa, stats.upper_sd, Rgb{110, 110, 110},
        1.5);
    add("", stats.period, stats.lower_psa, stats.lower_sd, Rgb{110, 110, 110}, 1.5);
  }
  for (std::size_t k = 0; k < rotd.size(); ++k) {
    const std::string pre = rotd.size() > 1 ? rotd[k].name + " " : "";
    const int c = static_cast<int>(spectra.size() + 2 * k);
    add(pre + "RotD50", rotd[k].period, rotd[k].psa50, rotd[k].sd50, series_colour(c), 2.0);
    add(pre + "RotD100", rotd[k].period, rotd[k].psa100, rotd[k].sd100, series_colour(c + 1), 2.0);
  }
  const std::string what =
      set ? " of " + std::to_string(spectra.size()) + " records: median and ±σ in log space" : "";
  return xy_figure({psa, sd}, 2, 1200, 480, "Elastic response spectra" + what, frames);
}

}  // namespace isopound::post
