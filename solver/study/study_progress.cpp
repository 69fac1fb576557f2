// Sweep progress on stderr (see study_progress.h): '\r'-redrawn bar on a terminal, throttled
// plain lines elsewhere; both show done/total, percent, runs per second and the ETA.
#include "solver/study/study_progress.h"

#include <unistd.h>

#include <cmath>

namespace isopound {
namespace {

constexpr double kBarInterval = 0.2;   // s between redraws of the bar
constexpr double kLineInterval = 5.0;  // s between plain lines
constexpr int kBarWidth = 30;

}  // namespace

std::string format_duration(double seconds) {
  if (!std::isfinite(seconds) || seconds < 0) return "--:--";
  const long total = std::lround(seconds);
  char buffer[32];
  if (total >= 3600)
    std::snprintf(buffer, sizeof buffer, "%ld:%02ld:%02ld", total / 3600, (total / 60) % 60,
                  total % 60);
  else
    std::snprintf(buffer, sizeof buffer, "%ld:%02ld", total / 60, total % 60);
  return buffer;
}

Progress::Mode Progress::mode_for(std::FILE* out, bool quiet) {
  if (quiet) return Mode::kQuiet;
  return isatty(fileno(out)) ? Mode::kBar : Mode::kLines;
}

Progress::Progress(Mode mode, std::int64_t total, std::int64_t already, std::FILE* out)
    : mode_(mode),
      total_(total),
      already_(already),
      out_(out),
      start_(std::chrono::steady_clock::now()),
      last_draw_(start_) {}

double Progress::elapsed_seconds() const {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
}

void Progress::update(std::int64_t finished, std::int64_t failed) {
  if (mode_ == Mode::kQuiet) return;
  const auto now = std::chrono::steady_clock::now();
  const double since = std::chrono::duration<double>(now - last_draw_).count();
  if (since < (mode_ == Mode::kBar ? kBarInterval : kLineInterval)) return;
  last_draw_ = now;
  draw(finished, failed, false);
}

void Progress::finish(std::int64_t finished, std::int64_t failed) {
  if (mode_ == Mode::kQuiet) return;
  draw(finished, failed, true);
}

void Progress::draw(std::int64_t finished, std::int64_t failed, bool final) {
  const double elapsed = elapsed_seconds();
  const double rate = elapsed > 0 ? static_cast<double>(finished) / elapsed : 0.0;
  const std::int64_t done = already_ + finished;
  const std::int64_t all = already_ + total_;
  const double fraction = all > 0 ? static_cast<double>(done) / static_cast<double>(all) : 1.0;
  const double eta = rate > 0 ? static_cast<double>(total_ - finished) / rate : NAN;
  const std::string failures = failed > 0 ? ", " + std::to_string(failed) + " failed" : "";
  if (mode_ == Mode::kBar) {
    const int filled = static_cast<int>(fraction * kBarWidth);
    std::string bar(static_cast<std::size_t>(filled), '#');
    bar.append(static_cast<std::size_t>(kBarWidth - filled), '.');
    std::fprintf(out_, "\r[%s] %lld/%lld %5.1f%%  %.1f runs/s  %s %s%s\x1b[K", bar.c_str(),
                 static_cast<long long>(done), static_cast<long long>(all), 100.0 * fraction, rate,
                 final ? "took" : "ETA", format_duration(final ? elapsed : eta).c_str(),
                 failures.c_str());
    if (final) std::fputc('\n', out_);
  } else {
    std::fprintf(out_, "sweep: %lld/%lld runs (%.1f %%), %.1f runs/s, %s %s%s\n",
                 static_cast<long long>(done), static_cast<long long>(all), 100.0 * fraction, rate,
                 final ? "took" : "ETA", format_duration(final ? elapsed : eta).c_str(),
                 failures.c_str());
  }
  std::fflush(out_);
}

}  // namespace isopound
