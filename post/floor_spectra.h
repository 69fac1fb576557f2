// Floor response spectra of a run: the elastic SDOF spectra (spectra.h) of every level's absolute
// acceleration and of the run's own ground acceleration; in 3D at each diaphragm's centre of mass
// and plan corners, where a rigid diaphragm with DOFs (u, v, θ) at the plan origin accelerates
// point p by a_p = (a_x − p_y a_θ, a_y + p_x a_θ) (site3d.h), in x, y and RotD50/RotD100.
#pragma once

#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "geometry/convex_polygon.h"
#include "post/run_data.h"
#include "post/spectra.h"

namespace isopound::post {

// A run that cannot give the spectra asked (history too coarse, no acceleration columns, rows
// not uniform); the message says what to change. The CLI exits 2 on it.
class FloorSpectraError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct FloorSpectraOptions {
  std::vector<double> periods;  // s, ascending; empty: default_periods(); 0 = the peak itself
  SpectrumOptions spectrum;     // damping ratio (default 5 %), oversample
  // Sampling rule: the history's effective interval dt must satisfy dt <= T / samples_per_period
  // for every nonzero period T (the rows are joined by straight lines, a filter of gain
  // sinc^2(pi dt / T) at period T: 0.967 at 10 samples per period; docs/floor-spectra.md).
  double samples_per_period = 10.0;
  // Periods shorter than the rule allows: kRefuse (FloorSpectraError), kClip (dropped, one note
  // that says how to compute them), or kAuto: kClip for the default periods (a default never
  // refuses), kRefuse for periods given.
  enum class ShortPeriods { kAuto, kRefuse, kClip };
  ShortPeriods short_periods = ShortPeriods::kAuto;
  // What the oscillators integrate: the run's every analysis step (step-accelerations.csv, from
  // output.floor_spectra: true; exact, every period), or the rows of histories.csv (the sampling
  // rule above). kAuto: the steps when the run has them, else the rows, with a note.
  enum class Source { kAuto, kSteps, kRows };
  Source source = Source::kAuto;
};

// The interval the spectra see: histories.csv's row interval, or the solver's analysis interval
// when that is longer (rows between two steps are interpolated linearly, they add nothing).
struct HistorySampling {
  double row_interval = 0.0;       // s, from summary.json's output_interval_s or the time column
  double analysis_interval = 0.0;  // s, summary.json's analysis_interval_s (0: unknown)
  double effective() const {
    return row_interval > analysis_interval ? row_interval : analysis_interval;
  }
};
HistorySampling history_sampling(const RunData& run);

// The spectra of one place (ground, a 2D level, or a 3D diaphragm's point). 2D: x only.
struct PlaceSpectra {
  std::string label;          // "ground", "3-storey/floor 2", "building/floor 1/CM", ".../corner 3"
  std::string structure;      // "" for the ground
  std::string level;          // "base", "floor 2", "" for the ground
  double elevation = 0.0;     // m above the ground
  std::optional<Vec2> p_W;    // 3D: the point in the model's plan frame
  Spectrum x;                 // along x (2D: the level's one direction)
  std::optional<Spectrum> y;  // 3D
  std::optional<RotDSpectrum> rotd;  // 3D: of the (x, y) pair
};

struct FloorSpectra {
  std::vector<double> periods;  // s, as computed (after clipping)
  double damping = 0.05;
  HistorySampling sampling;
  std::size_t steps = 0;  // > 0: computed over this many analysis steps (not the rows)
  bool three_d = false;
  PlaceSpectra ground;               // from the run's ground_acceleration column(s)
  std::vector<PlaceSpectra> places;  // structure by structure, levels bottom to top
  std::vector<std::string> notes;    // what was clipped or assumed
};

// A history column as an accelerogram: samples every dt from the first row (the run's t = 0).
GroundMotion column_motion(const RunData& run, int column, double dt, const std::string& name);

// Throws FloorSpectraError (sampling, missing columns) and std::invalid_argument (options).
FloorSpectra floor_spectra(const RunData& run, const FloorSpectraOptions& options = {});

// CSV: period_s, damping_ratio, then per place "<label> PSA [g]" and "<label> SD [m]" (2D), or
// PSA_x, PSA_y, PSA_RotD50, PSA_RotD100 and the same SD columns (3D); the ground first.
std::string floor_spectra_csv(const FloorSpectra& spectra);
// Where each place is: label, structure, level, x_m, y_m (3D), elevation_m.
std::string floor_spectra_places_csv(const FloorSpectra& spectra);

}  // namespace isopound::post
