// pvpython as a child process (see paraview_run.h).
#include "post/paraview_run.h"

#include <unistd.h>

#include <cstdlib>
#include <fstream>
#include <sstream>

#include "solver/io/child_process.h"

namespace isopound::post {

std::string find_pvpython() {
  return find_on_path("pvpython");
}

void run_pvpython(const std::filesystem::path& script, const std::vector<std::string>& args) {
  const std::string pvpython = find_pvpython();
  if (pvpython.empty())
    throw ParaViewError(
        "pvpython (ParaView's Python) is not on PATH: install ParaView (Debian: apt install "
        "paraview python3-paraview), or open the animation in ParaView yourself");
  std::string config = (std::filesystem::temp_directory_path() / "isopound-pv-XXXXXX").string();
  if (!mkdtemp(config.data())) throw ParaViewError("cannot create a temporary folder for pvpython");
  std::vector<std::string> pv_args = {"--force-offscreen-rendering", script.string()};
  pv_args.insert(pv_args.end(), args.begin(), args.end());
  ChildOptions options;
  for (char** e = environ; *e; ++e)
    if (std::string(*e).rfind("XDG_CONFIG_HOME=", 0) != 0) options.environment.push_back(*e);
  options.environment.push_back("XDG_CONFIG_HOME=" + config);
  // ParaView and FFmpeg are chatty (warnings on empty frames, a line per video frame): their
  // output goes to a log, shown only when pvpython fails.
  const std::string log = config + "/pvpython.log";
  options.output_file = log;
  options.stderr_to_output = true;
  const ChildResult child = run_child(pvpython, pv_args, options);
  std::string messages;
  {
    std::ifstream in(log);
    std::stringstream text;
    text << in.rdbuf();
    messages = text.str();
    if (messages.size() > 4000) messages = "..." + messages.substr(messages.size() - 4000);
  }
  std::error_code ignored;
  std::filesystem::remove_all(config, ignored);
  if (!child.started) throw ParaViewError("cannot start " + pvpython);
  if (child.exit_code != 0)
    throw ParaViewError("pvpython " + script.string() + " failed (exit status " +
                        std::to_string(child.exit_code) + "); its messages:\n" + messages);
}

}  // namespace isopound::post
