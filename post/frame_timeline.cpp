// Impact-aware frame times (see frame_timeline.h).
#include "post/frame_timeline.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace isopound::post {
namespace {

// Two frame times closer than this are one frame (well below any solver step).
constexpr double kSameTime = 1e-9;

double window_end(const RunData& run, double end) {
  return end < 0.0 ? run.time().back() : std::min(end, run.time().back());
}

// 2D: runs of rows with positive force (or penetration) in each contact's history.
void episodes_from_histories(const RunData& run, std::vector<ContactEpisode>& out) {
  const std::vector<double>& time = run.time();
  for (const ElementColumns& c : run.contacts) {
    if (c.force < 0) continue;
    const std::vector<double>& force = run.column(c.force);
    const std::vector<double>* pen = c.penetration >= 0 ? &run.column(c.penetration) : nullptr;
    const auto active = [&](std::size_t i) { return force[i] > 0.0 || (pen && (*pen)[i] > 0.0); };
    for (std::size_t i = 0; i < time.size();) {
      if (!active(i)) {
        ++i;
        continue;
      }
      std::size_t j = i;
      while (j < time.size() && active(j)) ++j;
      // The true onset lies after row i-1 and the true end before row j.
      out.push_back({c.label, time[i > 0 ? i - 1 : 0], time[std::min(j, time.size() - 1)]});
      i = j;
    }
  }
}

// 3D: onset .. separation in the contact-event log.
void episodes_from_log(const RunData& run, std::vector<ContactEpisode>& out) {
  for (const auto& [pair, rows] : run.contact_log.pairs) {
    for (std::size_t i = 0; i < rows.size();) {
      if (!rows[i].in_contact) {
        ++i;
        continue;
      }
      std::size_t j = i;
      while (j < rows.size() && rows[j].in_contact) ++j;
      const double end = j < rows.size() ? rows[j].time : run.time().back();
      out.push_back({pair, rows[i].time, std::max(end, rows[i].time)});
      i = j;
    }
  }
}

}  // namespace

std::vector<ContactEpisode> contact_episodes(const RunData& run) {
  std::vector<ContactEpisode> out;
  if (run.three_d)
    episodes_from_log(run, out);
  else
    episodes_from_histories(run, out);
  std::stable_sort(out.begin(), out.end(), [](const ContactEpisode& a, const ContactEpisode& b) {
    return a.start < b.start;
  });
  return out;
}

std::vector<double> frame_times(const RunData& run, double fps, double start, double end) {
  std::vector<double> times;
  const double t0 = std::max(run.time().front(), start);
  const double t1 = window_end(run, end);
  // Frame k at t0 + k/fps (integer k, no accumulated sum), up to t1 within round-off.
  for (long k = 0;; ++k) {
    const double t = t0 + static_cast<double>(k) / fps;
    if (t > t1 + 1e-9 * (1.0 + std::abs(t1))) break;
    times.push_back(std::min(t, t1));
  }
  return times;
}

Timeline frame_timeline(const RunData& run, const TimelineOptions& o) {
  Timeline line;
  std::vector<double> regular = frame_times(run, o.fps, o.start, o.end);
  const double t0 = regular.front(), t1 = window_end(run, o.end);
  std::vector<ContactEpisode> inside;
  if (!o.uniform)
    for (const ContactEpisode& e : contact_episodes(run))
      if (e.end >= t0 && e.start <= t1)
        inside.push_back({e.pair, std::max(e.start, t0), std::min(e.end, t1)});
  line.episodes = inside.size();

  int per_episode = 0;
  if (!inside.empty()) {
    const auto count = static_cast<long>(inside.size());
    const long room = static_cast<long>(o.max_frames) - static_cast<long>(regular.size());
    if (room < kMinFramesPerEpisode * count) {
      char text[320];
      std::snprintf(text, sizeof text,
                    "the frame budget (%d) holds %zu regular frames at %g frames/s but not %d "
                    "frames in each of the %ld contact episodes: raise --max-frames to at least "
                    "%ld, lower --fps, narrow --start/--end, or use --uniform",
                    o.max_frames, regular.size(), o.fps, kMinFramesPerEpisode, count,
                    static_cast<long>(regular.size()) + kMinFramesPerEpisode * count);
      throw TimelineError(text);
    }
    per_episode = static_cast<int>(std::clamp<long>(
        room / count, kMinFramesPerEpisode, std::max(o.frames_per_episode, kMinFramesPerEpisode)));
  }
  line.frames_per_episode = per_episode;

  std::vector<double> times = std::move(regular);
  for (const ContactEpisode& e : inside)
    for (int k = 0; k < per_episode; ++k)
      times.push_back(e.start + (e.end - e.start) * k / (per_episode - 1));
  std::sort(times.begin(), times.end());
  // Equal times (an episode on a regular frame, overlapping episodes) are one frame.
  for (double t : times)
    if (line.times.empty() || t > line.times.back() + kSameTime) line.times.push_back(t);

  const std::size_t n = line.times.size();
  line.slow_motion.assign(n, 1.0);
  for (std::size_t k = 0; k < n && n > 1; ++k) {
    const double lo = line.times[k > 0 ? k - 1 : 0], hi = line.times[k + 1 < n ? k + 1 : n - 1];
    const double h = (hi - lo) / ((k > 0 && k + 1 < n) ? 2.0 : 1.0);
    line.slow_motion[k] = std::max(1.0, h > 0.0 ? 1.0 / (o.fps * h) : 1.0);
  }
  return line;
}

}  // namespace isopound::post
