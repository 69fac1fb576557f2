// Private Xvfb for headless rendering (see headless.h).
#include "post/headless.h"

#include <X11/Xlib.h>
#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>

namespace isopound::post {
namespace {

// The server to kill from signal handlers and atexit (one private server per process).
std::atomic<pid_t> g_server{-1};

void kill_server_now() {
  const pid_t pid = g_server.exchange(-1);
  if (pid > 0) {
    kill(pid, SIGTERM);
    int status = 0;
    waitpid(pid, &status, 0);
  }
}

void on_signal(int sig) {
  kill_server_now();  // kill and waitpid are async-signal-safe
  signal(sig, SIG_DFL);
  raise(sig);
}

void install_cleanup_once() {
  static bool installed = false;
  if (installed) return;
  installed = true;
  std::atexit(kill_server_now);
  for (int sig : {SIGINT, SIGTERM, SIGHUP}) {
    struct sigaction sa {};
    sa.sa_handler = on_signal;
    sigemptyset(&sa.sa_mask);
    sigaction(sig, &sa, nullptr);
  }
}

}  // namespace

bool has_display() {
  const char* d = std::getenv("DISPLAY");
  return d != nullptr && *d != '\0';
}

bool display_reachable() {
  if (!has_display()) return false;
  Display* x = XOpenDisplay(nullptr);
  if (x == nullptr) return false;
  XCloseDisplay(x);
  return true;
}

PrivateDisplay::PrivateDisplay(bool announce, double timeout_seconds) {
  if (display_reachable()) {
    display_ = std::getenv("DISPLAY");
    return;
  }
  // A DISPLAY that cannot be opened (ssh without X forwarding, a stopped server) would make VTK
  // abort: render on a private server instead, and say why.
  const std::string reason =
      has_display() ? "DISPLAY=" + std::string(std::getenv("DISPLAY")) + " cannot be opened"
                    : std::string("no DISPLAY");
  if (has_display()) previous_display_ = std::getenv("DISPLAY");
  int fds[2];
  if (pipe(fds) != 0) throw HeadlessError(std::string("pipe: ") + std::strerror(errno));
  install_cleanup_once();
  char fd_text[16];  // formatted before fork: the child only calls async-signal-safe functions
  std::snprintf(fd_text, sizeof fd_text, "%d", fds[1]);
  const pid_t parent = getpid();
  const pid_t pid = fork();
  if (pid < 0) {
    close(fds[0]);
    close(fds[1]);
    throw HeadlessError(std::string("fork: ") + std::strerror(errno));
  }
  if (pid == 0) {
    // Child: die with the parent whatever the way it exits; quiet; exec the server.
    prctl(PR_SET_PDEATHSIG, SIGTERM);
    if (getppid() != parent) _exit(127);
    close(fds[0]);
    const int null_fd = open("/dev/null", O_RDWR);
    if (null_fd >= 0) {
      dup2(null_fd, STDIN_FILENO);
      dup2(null_fd, STDOUT_FILENO);
      dup2(null_fd, STDERR_FILENO);
    }
    execlp("Xvfb", "Xvfb", "-displayfd", fd_text, "-screen", "0", "1600x1200x24", "-nolisten",
           "tcp", "-noreset", static_cast<char*>(nullptr));
    _exit(127);
  }
  close(fds[1]);
  pid_ = pid;
  g_server = pid;

  // The server writes "N\n" once it accepts connections; EOF first means it failed.
  std::string text;
  const auto deadline =
      std::chrono::steady_clock::now() + std::chrono::duration<double>(timeout_seconds);
  for (;;) {
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(
        deadline - std::chrono::steady_clock::now());
    if (left.count() <= 0) break;
    pollfd p{fds[0], POLLIN, 0};
    const int r = poll(&p, 1, static_cast<int>(left.count()));
    if (r < 0 && errno == EINTR) continue;
    if (r <= 0) break;
    char buf[32];
    const ssize_t n = read(fds[0], buf, sizeof buf);
    if (n <= 0) break;
    text.append(buf, static_cast<std::size_t>(n));
    if (text.find('\n') != std::string::npos) break;
  }
  close(fds[0]);
  if (text.find('\n') == std::string::npos) {
    stop();
    throw HeadlessError(
        "no DISPLAY and could not start a private Xvfb (is the xvfb package installed?); "
        "set DISPLAY or run under xvfb-run");
  }
  text.erase(text.find('\n'));
  display_ = std::string(1, ':') + text;
  setenv("DISPLAY", display_.c_str(), 1);
  if (announce)
    std::fprintf(stderr, "isopound-post: %s, rendering on a private Xvfb %s (pid %d)\n",
                 reason.c_str(), display_.c_str(), static_cast<int>(pid_));
}

void PrivateDisplay::stop() {
  if (pid_ <= 0) return;
  if (g_server == pid_) g_server = -1;
  kill(pid_, SIGTERM);
  int status = 0;
  waitpid(pid_, &status, 0);
  pid_ = -1;
  if (previous_display_.empty())
    unsetenv("DISPLAY");
  else
    setenv("DISPLAY", previous_display_.c_str(), 1);
}

PrivateDisplay::~PrivateDisplay() {
  stop();
}

}  // namespace isopound::post
