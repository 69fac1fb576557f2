// view.py: a ParaView Python state written beside an animation so that it opens ready to watch
// (`paraview --script=view.py`, or `pvpython view.py` headless).
//
// What the script sets up (ParaView 5.11's paraview.simple):
//   - the .pvd, played one frame per tick ("Snap To TimeSteps"): the impact-aware timeline is
//     slow motion exactly where its frames are dense;
//   - a 3D camera on the building (from the south-west, 30° above); 2D runs from the side,
//     upright (x right, z up);
//   - the structure coloured by block (categorical: slab, column, bearing, wall; a 3D building
//     see-through so that contacts under its floors stay in sight), the contact cells by normal
//     force in MN (kN when the run's peak is under 1 MN) with one fixed range, [0, the run's peak],
//     for the whole run, in warm colours only (yellow to dark red) and outlined, so that a contact
//     never looks like a wall;
//   - contact forces as arrows at the contact, on the building, the run's peak force
//     `force_length` long;
//   - displacements drawn × `scale` (by default the largest drawn 4 to 10 % of the site's size,
//     a WarpByVector of the frames' displacement plus their gap_offset, so that gaps are drawn
//     × scale too and bodies touch exactly when in contact), stated on screen; SCALE at the top
//     of view.py changes it;
//   - the overlap drawn `exaggeration` times deeper along the contact normal (a WarpByVector of
//     the frames' contact_depth_offset by exaggeration − 1), stated on screen;
//   - the time and the frame's slow-motion factor on screen.
// Options of the script: --png DIR (every frame as PNG), --video FILE (.avi or .ogv),
// --time T --screenshot FILE (one frame), --report FILE (JSON for tests: time steps, and per
// --time the contact cells and where their centroid lands on the screenshot), --size W H.
#pragma once

#include <string>

#include "post/run_data.h"

namespace isopound::post {

struct ContactPeaks {
  double normal_force = 0.0;  // N, the run's largest contact (normal) force
  double penetration = 0.0;   // m, its largest penetration (3D: indentation δ_N)
};

// From the contact-event log (3D) or the contact histories (2D).
ContactPeaks contact_peaks(const RunData& run);

struct ViewScriptOptions {
  std::string pvd_file = "animation.pvd";  // beside the script
  std::string absolute_dir;                // where the script was written (fallback)
  bool three_d = false;
  double frame_scale = 1.0;        // the frames' own displacement magnification (animate --scale)
  bool frame_gaps_scaled = false;  // the frames draw gaps × frame_scale too (2D)
  double scale = 1.0;              // view.py's displacement magnification
  double fps = 25.0;               // regular frames per second of analysis time
  double exaggeration = 1.0;       // overlap depth drawn × this
  double force_length = 3.0;       // m, drawn length of the peak contact force
  ContactPeaks peaks;
};

// The largest factor 1, 2 or 5 × 10^k at most `wanted` (1 when wanted <= 1): a factor a reader
// takes in at a glance.
double nice_factor_below(double wanted);

// The displacement scale that draws the run's largest displacement `largest` (m) 10 % of the site's
// size `extent`, rounded down by nice_factor_below (so 4 to 10 %); 1 when nothing moves.
double automatic_scale(double largest, double extent);

// The exaggeration that draws the run's deepest overlap about 5 % of the drawing's size
// `extent` deep, rounded down to 1, 2 or 5 × 10^k; 1 without contacts.
double automatic_exaggeration(const ContactPeaks& peaks, double drawn_depth_per_metre,
                              double extent);

// The unit view.py shows contact forces in: MN where the run's peak reaches 1 MN, else kN (the
// colour bar's numbers stay short).
struct ForceUnit {
  const char* name;
  double newtons;
};
ForceUnit force_unit(const ContactPeaks& peaks);

std::string view_script(const ViewScriptOptions& options);

}  // namespace isopound::post
