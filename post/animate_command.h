// `isopound-post animate RUN_DIR`: the frames of a run on the impact-aware timeline
// (frame_timeline.h), the .pvd, view.py (paraview_view.h), an optional preview picture and an
// optional rendering through pvpython (paraview_run.h).
#pragma once

#include <string>

#include "post/animation.h"
#include "post/frame_timeline.h"

namespace isopound::post {

struct AnimateArgs {
  AnimationOptions frame;
  TimelineOptions timeline;
  double preview = -1.0;      // s, < 0: none
  double exaggeration = 0.0;  // overlap depth drawn × this in view.py; 0: automatic
  double view_scale = 0.0;    // displacements drawn × this in view.py; 0: automatic
  std::string render;         // "", png, video or a .png / .avi / .ogv path
};

// Throws BadInput (command_support.h) on bad options or a bad run directory.
int run_animate(const std::string& dir, const std::string& out, const std::string& model,
                const AnimateArgs& args);

}  // namespace isopound::post
