// Running ParaView's pvpython on a view.py (paraview_view.h): to render an animation to PNG
// frames or a video headless, and in the tests that check the animation in the real client.
#pragma once

#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

namespace isopound::post {

class ParaViewError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// The pvpython on PATH ("" when there is none).
std::string find_pvpython();

// Runs `pvpython --force-offscreen-rendering SCRIPT ARGS...` and waits. ParaView keeps settings
// under the user's configuration folder: XDG_CONFIG_HOME points at a private temporary folder
// for the run, so neither a user's settings change the picture nor the run the user's settings.
// Needs an X display (PrivateDisplay). pvpython's output is kept in a log, not shown. Throws
// ParaViewError when pvpython is missing or exits non-zero (the message ends with the log).
void run_pvpython(const std::filesystem::path& script, const std::vector<std::string>& args);

}  // namespace isopound::post
