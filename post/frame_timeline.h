// The frame times of an animation that slows down at every impact.
//
// An impact lasts a few milliseconds: at a regular 25 frames/s most contacts fall between two
// frames and are never seen. The impact-aware timeline keeps the regular frames (start + k/fps)
// and adds, inside every contact episode, `frames_per_episode` frames spread evenly from the
// episode's first instant in contact to its end (both included), so every rise and fall of a
// contact force is drawn. Played one frame per tick (ParaView's "Snap To TimeSteps"), time runs
// slower exactly where the frames are denser.
//
// Contact episode (pair P, times in s):
//   3D: from contact_events.csv: [time of an onset row, time of the separation row that ends it]
//       (the run's last row when it ends in contact);
//   2D: from the force (or penetration) history of each contact: [the last row with zero force
//       before a run of positive rows, the first row with zero force after it] (the true onset and
//       end lie inside, between samples).
//
// Slow-motion factor of frame k: s_k = (1/fps) / h_k with h_k = (t_{k+1} − t_{k−1})/2 (one-sided
// at the ends), at least 1: how many times slower than the regular rate the frame's stretch of
// analysis time is shown when every frame is shown for 1/fps.
#pragma once

#include <string>
#include <vector>

#include "post/run_data.h"

namespace isopound::post {

struct ContactEpisode {
  std::string pair;    // the contact's label (2D) or the log's pair "A|B" (3D)
  double start = 0.0;  // s
  double end = 0.0;    // s, >= start
};

// Every contact episode of the run, ordered by start time.
std::vector<ContactEpisode> contact_episodes(const RunData& run);

struct TimelineOptions {
  double fps = 25.0;            // regular frames per second of analysis time
  double start = 0.0;           // s
  double end = -1.0;            // s, < 0: the end of the run
  bool uniform = false;         // true: only the regular frames
  int frames_per_episode = 12;  // wanted frames inside each episode (fewer, down to
                                // kMinFramesPerEpisode, when the budget asks for it)
  int max_frames = 1500;        // budget: the timeline never has more frames
};

inline constexpr int kMinFramesPerEpisode = 8;

struct Timeline {
  std::vector<double> times;        // s, strictly increasing
  std::vector<double> slow_motion;  // per frame, >= 1
  std::size_t episodes = 0;         // episodes inside [start, end]
  int frames_per_episode = 0;       // frames each episode got (0 when uniform or none)
};

// Thrown when the budget cannot hold the regular frames plus kMinFramesPerEpisode per episode;
// the message says what to change.
class TimelineError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

Timeline frame_timeline(const RunData& run, const TimelineOptions& options);

// The regular frames only: start, start + 1/fps, ... up to `end` or the last history row.
std::vector<double> frame_times(const RunData& run, double fps, double start = 0.0,
                                double end = -1.0);

}  // namespace isopound::post
