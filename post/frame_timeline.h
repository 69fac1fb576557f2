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
// at the ends), at least 1, fps the regular rate as laid (Timeline::fps): how many times slower
// than the regular rate the frame's stretch of analysis time is shown when every frame is shown
// for 1/fps.
#pragma once

#include <stdexcept>
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
  int frames_per_episode = 12;  // frames inside each episode
  int max_frames = 1500;        // budget: the timeline never has more frames
  // Given on the command line: kept as given or refused (TimelineError). A default is thinned to
  // fit the budget (fit rule below).
  bool fps_given = false;
  bool frames_per_episode_given = false;
};

// Fit rule, when the regular frames plus frames_per_episode in every episode exceed max_frames:
//   1. a default fps: every k-th regular frame (fps / k), k = 2 .. kMaxRegularStride, the smallest
//      that fits;
//   2. a default frames_per_episode: then fewer per episode, down to kMinFramesPerEpisode;
//   3. a default frames_per_episode and still too many: the regular frames only (as --uniform),
//      every k-th with the smallest k that fits (k = 1 when fps was given).
// Regular frames only (asked, or no episode) are thinned as in 3 when fps is a default.
// Whatever else does not fit is a TimelineError that says what to change.
inline constexpr int kMinFramesPerEpisode = 8;
inline constexpr int kMaxRegularStride = 5;  // a default 25 frames/s down to 5 frames/s

struct Timeline {
  std::vector<double> times;        // s, strictly increasing
  std::vector<double> slow_motion;  // per frame, >= 1, against `fps`
  double fps = 0.0;                 // regular frames per second as laid: options.fps / stride
  int regular_stride = 1;           // every k-th regular frame of options.fps
  bool uniform = false;             // regular frames only (asked, or the fit rule's step 3)
  std::size_t episodes = 0;         // episodes inside [start, end]
  int frames_per_episode = 0;       // frames each episode got (0 when uniform or none)
  std::string note;                 // what the fit rule thinned and how to keep it; "" if nothing
};

// Thrown when options given on the command line cannot fit the budget; the message says what to
// change.
class TimelineError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

Timeline frame_timeline(const RunData& run, const TimelineOptions& options);

// The regular frames only: start, start + 1/fps, ... up to `end` or the last history row.
std::vector<double> frame_times(const RunData& run, double fps, double start = 0.0,
                                double end = -1.0);

}  // namespace isopound::post
