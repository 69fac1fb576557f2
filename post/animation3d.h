// Animation frames of 3D runs: every slab an extruded plan polygon at its elevation, moved by its
// DOFs (u, v, θ) × scale (a plan point p moves by (u − p_y θ, v + p_x θ)); columns as lines
// between levels, bearings as lines under the base slab, walls; contact blocks from the log.
#pragma once

#include "post/animation.h"
#include "post/figure.h"
#include "post/run_data.h"

namespace isopound::post {

// The frame at time t of a 3D run (histories interpolated linearly between rows). Drawn
// coordinates: x, y plan (W), z up; a slab occupies [elevation − thickness, elevation], a wall
// (the solver's site puts its base at 0) [−height, 0]: its top flush with the ground, the base
// slab's level, as a moat wall retaining the soil around the isolation level.
//   point data: displacement (3, m, true not scaled), absolute_acceleration (3, m/s2),
//               contact_depth_offset (3, m: overlap vertices' offset from the logged centroid
//               along n_AB, see animation.h)
//   cell data:  block (Block), structure (index in run.structures, -1 walls), drift_ratio
//               (columns: |relative displacement of the column's ends| / storey height),
//               bearing_force (bearings: resultant, N), contact_force (3, N, the force on B of
//               the pair "A|B": F_N n_AB − F_T t_AB), normal_force, tangential_force (N),
//               area (m2), penetration (indentation δ_N, m)
// Contact blocks (the overlap polygon of A and B recomputed at the frame's state, drawn on A's
// top, or a vertex at the logged centroid when the interpolated state does not overlap, plus the
// normal and tangential force as lines from the logged centroid) exist exactly in frames where
// contact_events.csv says the pair is in contact: its last row with time <= t has in_contact 1.
FrameMesh animation_frame3d(const RunData& run, double t, const AnimationOptions& options);

// A picture of a 3D frame: an axonometric view (from the south-west, 30° above), faces painted
// back to front and shaded, coloured by block, with the time and the scale.
Figure frame_figure3d(const FrameMesh& mesh, double scale, int width = 900, int height = 620);

}  // namespace isopound::post
