// The private Xvfb is stopped on every way out of the process that owns it: normal return
// (destructor), std::exit (atexit), a terminating signal (handler) and SIGKILL (the kernel's
// parent-death signal). Each case runs in a forked child; the parent checks the server is gone.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <fstream>
#include <string>
#include <thread>

#include "post/headless.h"

namespace isopound::post {
namespace {

// Running and not a zombie.
bool xvfb_alive(pid_t pid) {
  std::ifstream stat("/proc/" + std::to_string(pid) + "/stat");
  std::string line;
  if (!std::getline(stat, line)) return false;
  const auto close = line.rfind(')');
  return line.find("(Xvfb)") != std::string::npos && close != std::string::npos &&
         line.size() > close + 2 && line[close + 2] != 'Z';
}

enum class Exit { kReturn, kStdExit, kSigterm, kSigkill };

// Forks a child that starts a private display, reports the server pid and leaves as told.
pid_t server_after(Exit how) {
  int fds[2];
  if (pipe(fds) != 0) return -1;
  const pid_t child = fork();
  if (child == 0) {
    close(fds[0]);
    unsetenv("DISPLAY");
    pid_t server = -1;
    {
      PrivateDisplay display(false);
      server = display.pid();
      if (write(fds[1], &server, sizeof server) != sizeof server) _exit(9);
      if (how == Exit::kStdExit) std::exit(0);  // skips the destructor
      if (how == Exit::kSigterm) raise(SIGTERM);
      if (how == Exit::kSigkill) raise(SIGKILL);
    }
    _exit(0);  // kReturn: the destructor ran at the end of the block
  }
  close(fds[1]);
  pid_t server = -1;
  if (read(fds[0], &server, sizeof server) != sizeof server) server = -1;
  close(fds[0]);
  int status = 0;
  waitpid(child, &status, 0);
  return server;
}

TEST(PostHeadless, ServerStopsOnEveryExitPath) {
  for (Exit how : {Exit::kReturn, Exit::kStdExit, Exit::kSigterm, Exit::kSigkill}) {
    SCOPED_TRACE("exit path " + std::to_string(static_cast<int>(how)));
    const pid_t server = server_after(how);
    ASSERT_GT(server, 0) << "the private Xvfb did not start";
    // SIGKILL: the kernel signals the server when its parent dies; allow it 5 s to go.
    bool alive = true;
    for (int i = 0; i < 100 && alive; ++i) {
      alive = xvfb_alive(server);
      if (alive) std::this_thread::sleep_for(std::chrono::milliseconds(50));
    }
    EXPECT_FALSE(alive) << "Xvfb " << server << " still running";
  }
}

}  // namespace
}  // namespace isopound::post
