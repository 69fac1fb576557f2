// Headless rendering: a private Xvfb started when there is no DISPLAY (Debian's VTK is GLX only).
// The server picks its own free display number (-displayfd), dies with us (PR_SET_PDEATHSIG).
#pragma once

#include <sys/types.h>
#include <stdexcept>
#include <string>

namespace isopound::post {

class HeadlessError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Owns a private X server for the lifetime of the object. If DISPLAY is set and can be opened it
// does nothing (a DISPLAY that cannot be opened is replaced, with a line on stderr). Otherwise it
// starts `Xvfb -displayfd`, waits until the server has written its display number (it is then
// accepting connections), sets DISPLAY=:N and says so in one line on stderr. The server is stopped
// (SIGTERM, then reaped) by the destructor, by std::exit and on SIGINT / SIGTERM / SIGHUP; if this
// process dies any other way the kernel sends it SIGTERM. Throws HeadlessError when Xvfb is missing
// or does not come up within `timeout_seconds`.
class PrivateDisplay {
 public:
  explicit PrivateDisplay(bool announce = true, double timeout_seconds = 20.0);
  ~PrivateDisplay();
  PrivateDisplay(const PrivateDisplay&) = delete;
  PrivateDisplay& operator=(const PrivateDisplay&) = delete;

  bool started() const { return pid_ > 0; }
  const std::string& display() const { return display_; }  // ":N" or the inherited DISPLAY
  pid_t pid() const { return pid_; }
  void stop();

 private:
  pid_t pid_ = -1;
  std::string display_;
  std::string previous_display_;  // an unusable DISPLAY we replaced, restored by stop()
};

// True when DISPLAY is set and non-empty.
bool has_display();
// True when DISPLAY is set and an X connection to it opens.
bool display_reachable();

}  // namespace isopound::post
