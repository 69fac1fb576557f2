// pvpython as a child process (see paraview_run.h).
#include "post/paraview_run.h"

#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <fcntl.h>

#include <cstdlib>
#include <fstream>
#include <sstream>

extern char** environ;

namespace isopound::post {

std::string find_pvpython() {
  const char* path = std::getenv("PATH");
  std::stringstream dirs(path ? path : "");
  std::string dir;
  while (std::getline(dirs, dir, ':')) {
    const std::filesystem::path candidate = std::filesystem::path(dir) / "pvpython";
    if (!dir.empty() && access(candidate.c_str(), X_OK) == 0) return candidate.string();
  }
  return "";
}

void run_pvpython(const std::filesystem::path& script, const std::vector<std::string>& args) {
  const std::string pvpython = find_pvpython();
  if (pvpython.empty())
    throw ParaViewError(
        "pvpython (ParaView's Python) is not on PATH: install ParaView (Debian: apt install "
        "paraview python3-paraview), or open the animation in ParaView yourself");
  std::string config = (std::filesystem::temp_directory_path() / "isopound-pv-XXXXXX").string();
  if (!mkdtemp(config.data())) throw ParaViewError("cannot create a temporary folder for pvpython");
  std::vector<std::string> argv_text = {pvpython, "--force-offscreen-rendering", script.string()};
  argv_text.insert(argv_text.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (std::string& a : argv_text) argv.push_back(a.data());
  argv.push_back(nullptr);
  std::vector<std::string> env_text;
  for (char** e = environ; *e; ++e)
    if (std::string(*e).rfind("XDG_CONFIG_HOME=", 0) != 0) env_text.push_back(*e);
  env_text.push_back("XDG_CONFIG_HOME=" + config);
  std::vector<char*> env;
  for (std::string& e : env_text) env.push_back(e.data());
  env.push_back(nullptr);

  // ParaView and FFmpeg are chatty (warnings on empty frames, a line per video frame): their
  // output goes to a log, shown only when pvpython fails.
  const std::string log = config + "/pvpython.log";
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, log.c_str(),
                                   O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_adddup2(&actions, STDOUT_FILENO, STDERR_FILENO);
  pid_t pid = -1;
  const int spawned =
      posix_spawn(&pid, pvpython.c_str(), &actions, nullptr, argv.data(), env.data());
  posix_spawn_file_actions_destroy(&actions);
  int status = 0;
  if (spawned == 0) waitpid(pid, &status, 0);
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
  if (spawned != 0) throw ParaViewError("cannot start " + pvpython);
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
    throw ParaViewError("pvpython " + script.string() + " failed (exit status " +
                        std::to_string(WIFEXITED(status) ? WEXITSTATUS(status) : -1) +
                        "); its messages:\n" + messages);
}

}  // namespace isopound::post
