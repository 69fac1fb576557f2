// Impact-aware frame times (see frame_timeline.h).
#include "post/frame_timeline.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>

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

struct BudgetFit {
  int stride = 1;        // every k-th regular frame
  int per_episode = 0;   // frames in each episode
  bool uniform = false;  // the regular frames only (step 3 of the fit rule)
  std::string note;      // what was thinned; "" when nothing
};

std::string fps_text(double fps) {
  char b[32];
  std::snprintf(b, sizeof b, "%.4g frames/s", fps);
  return b;
}

// The fit rule of frame_timeline.h. regular(k): how many regular frames every k-th gives.
BudgetFit fit_budget(const TimelineOptions& o, std::size_t episodes,
                     const std::function<std::size_t(int)>& regular) {
  const auto fits = [&](int stride, long per_episode) {
    return static_cast<long>(regular(stride)) + per_episode * static_cast<long>(episodes) <=
           o.max_frames;
  };
  // The smallest stride (up to `limit`) at which the regular frames and `per_episode` fit; 0: none.
  const auto stride_for = [&](long per_episode, long limit) {
    for (int k = 1; k <= limit; ++k) {
      if (fits(k, per_episode)) return k;
      if (regular(k) <= 1) break;  // one frame is as thin as it gets
    }
    return 0;
  };
  const bool slowed = episodes > 0;
  const long wanted_per_episode = slowed ? o.frames_per_episode : 0;
  const std::size_t regular_all = regular(1);
  BudgetFit fit;
  fit.per_episode = static_cast<int>(wanted_per_episode);
  if (fits(1, wanted_per_episode)) return fit;

  const long most_strides = o.fps_given ? 1 : std::numeric_limits<int>::max();
  if (slowed) {
    fit.stride = stride_for(wanted_per_episode, o.fps_given ? 1 : kMaxRegularStride);
    if (fit.stride == 0 && !o.frames_per_episode_given) {
      fit.stride = o.fps_given ? 1 : kMaxRegularStride;
      const long room = o.max_frames - static_cast<long>(regular(fit.stride));
      const long per = room / static_cast<long>(episodes);
      if (per >= kMinFramesPerEpisode) {
        fit.per_episode = static_cast<int>(per);
      } else {
        fit.stride = 0;
        fit.uniform = true;
      }
    }
    if (fit.stride == 0 && !fit.uniform) {
      char text[400];
      std::snprintf(
          text, sizeof text,
          "the frame budget (%d) holds %zu regular frames at %g frames/s but not %ld "
          "frames in each of the %zu contact episodes: raise --max-frames to at least "
          "%ld, lower --fps or --impact-frames, narrow --start/--end, or use --uniform",
          o.max_frames, regular_all, o.fps, wanted_per_episode, episodes,
          static_cast<long>(regular_all) + wanted_per_episode * static_cast<long>(episodes));
      throw TimelineError(text);
    }
  }
  if (!slowed || fit.uniform) {
    fit.per_episode = 0;
    fit.stride = stride_for(0, most_strides);
    if (fit.stride == 0) {
      char text[300];
      std::snprintf(text, sizeof text,
                    "the frame budget (%d) does not hold the %zu regular frames at %g frames/s "
                    "(--fps): raise --max-frames to at least %zu, lower --fps, or narrow "
                    "--start/--end",
                    o.max_frames, regular_all, o.fps, regular_all);
      throw TimelineError(text);
    }
  }

  // One line: what was asked, what was thinned, which option keeps it.
  std::string note = std::to_string(regular_all) + " regular frames at " + fps_text(o.fps);
  if (slowed)
    note += " and " + std::to_string(wanted_per_episode) + " frames in each of the " +
            std::to_string(episodes) + " contact episodes";
  note += " exceed the frame budget (" + std::to_string(o.max_frames) + "): ";
  std::vector<std::string> thinned, kept;
  if (fit.stride > 1) {
    thinned.push_back("regular frames at " + fps_text(o.fps / fit.stride) + " (one in " +
                      std::to_string(fit.stride) + ")");
    kept.push_back(fps_text(o.fps));
  }
  if (fit.uniform) {
    thinned.push_back("no frames added in the contact episodes (" +
                      std::to_string(kMinFramesPerEpisode) + " in each do not fit)");
    kept.push_back("the slow motion at the contacts");
  } else if (slowed && fit.per_episode < wanted_per_episode) {
    thinned.push_back(std::to_string(fit.per_episode) + " frames in each episode");
    kept.push_back(std::to_string(wanted_per_episode) + " per episode");
  }
  const auto joined = [](const std::vector<std::string>& parts) {
    std::string out;
    for (std::size_t i = 0; i < parts.size(); ++i)
      out += (i == 0 ? "" : i + 1 == parts.size() ? " and " : ", ") + parts[i];
    return out;
  };
  note += joined(thinned) + "; --max-frames " +
          std::to_string(static_cast<long>(regular_all) +
                         wanted_per_episode * static_cast<long>(episodes)) +
          " keeps " + joined(kept);
  fit.note = std::move(note);
  return fit;
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
  const std::vector<double> regular_all = frame_times(run, o.fps, o.start, o.end);
  const double t0 = regular_all.front(), t1 = window_end(run, o.end);
  std::vector<ContactEpisode> inside;
  if (!o.uniform)
    for (const ContactEpisode& e : contact_episodes(run))
      if (e.end >= t0 && e.start <= t1)
        inside.push_back({e.pair, std::max(e.start, t0), std::min(e.end, t1)});
  line.episodes = inside.size();

  const BudgetFit fit = fit_budget(o, inside.size(), [&](int stride) {
    return stride == 1 ? regular_all.size()
                       : frame_times(run, o.fps / stride, o.start, o.end).size();
  });
  line.regular_stride = fit.stride;
  line.fps = o.fps / fit.stride;
  line.uniform = o.uniform || fit.uniform;
  line.frames_per_episode = line.uniform ? 0 : fit.per_episode;
  line.note = fit.note;

  std::vector<double> times =
      fit.stride == 1 ? regular_all : frame_times(run, line.fps, o.start, o.end);
  const int per_episode = line.frames_per_episode;
  if (per_episode > 0)
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
    line.slow_motion[k] = std::max(1.0, h > 0.0 ? 1.0 / (line.fps * h) : 1.0);
  }
  return line;
}

}  // namespace isopound::post
