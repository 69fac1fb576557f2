// Progress of a sweep on stderr: a redrawn bar with rate and ETA on a terminal (isatty), plain
// lines every few seconds otherwise (logs, CI, Slurm). Rate = runs finished this session / elapsed.
#pragma once

#include <chrono>
#include <cstdint>
#include <cstdio>
#include <string>

namespace isopound {

class Progress {
 public:
  enum class Mode { kBar, kLines, kQuiet };
  // `total`: runs this session will finish; `already`: finished before it (resume).
  Progress(Mode mode, std::int64_t total, std::int64_t already, std::FILE* out = stderr);

  // Shows `finished` runs of this session (throttled: at most every 0.2 s bar, 5 s lines).
  void update(std::int64_t finished, std::int64_t failed);
  // Final state and a newline after the bar.
  void finish(std::int64_t finished, std::int64_t failed);

  double elapsed_seconds() const;

  // kBar on a terminal, kLines otherwise.
  static Mode mode_for(std::FILE* out, bool quiet);

 private:
  void draw(std::int64_t finished, std::int64_t failed, bool final);

  Mode mode_;
  std::int64_t total_;
  std::int64_t already_;
  std::FILE* out_;
  std::chrono::steady_clock::time_point start_;
  std::chrono::steady_clock::time_point last_draw_;
};

// "1:02:03" / "2:03" for a duration in seconds; "--:--" when unknown.
std::string format_duration(double seconds);

}  // namespace isopound
