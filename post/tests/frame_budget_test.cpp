// The frame budget of `animate` (frame_timeline.h, fit rule): with defaults the animation always
// fits, thinning the regular frames first (every k-th, k <= 5), then the frames per episode (down
// to 8), then leaving the regular frames only, with one note; options given are kept or refused.
// Expected strides and counts are computed here from the rule and the run's length, independently
// of frame_timeline.cpp; the episodes are contact_episodes()' (tested in paraview_test.cpp).
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <regex>
#include <string>
#include <vector>

#include "post/frame_timeline.h"
#include "post/run_data.h"
#include "post_test_support.h"

namespace isopound::post {
namespace {

namespace fs = std::filesystem;

// A building rattling between rigid walls 2 cm away (linear isolator, no isolation damping,
// elastic impacts) under a 1 m/s pulse: tens of contact episodes (2D: from the force histories).
std::string rattling_model(const std::string& seconds) {
  return "building:\n"
         "  name: building\n"
         "  base: {mass: 340 t}\n"
         "  floors: {count: 3, mass: 340 t, roof_mass: 250 t, stiffness: 600 MN/m, height: 3.2 m}\n"
         "  isolator: {model: linear, Tb: 2.0 s}\n"
         "  damping:\n"
         "    superstructure: {type: rayleigh, ratio: 2 %, modes: [1, 2]}\n"
         "    isolation: 0 %\n"
         "  walls: {sides: both, level: 0, gap: 2 cm, law: linear, k: 2500 kN/mm}\n"
         "ground_motion:\n"
         "  pulse: {amplitude: 1 m/s, period: 1 s, t_peak: 2 s, duration: " +
         seconds + ", dt: 0.005 s}\n" + "analysis: {t_end: " + seconds + "}\n";
}

// 44 s of rattling (the length of the shipped runs on RSN1084): more than the default budget.
const fs::path& long_run() {
  static const fs::path dir = [] {
    const fs::path d = test::scratch_dir("budget-long");
    std::ofstream(d / "model.yaml") << rattling_model("44 s");
    const auto r =
        test::run_solver("run -q " + (d / "model.yaml").string() + " -o " + (d / "run").string());
    EXPECT_EQ(r.exit_code, 0) << r.output;
    return d / "run";
  }();
  return dir;
}

// Regular frames every k-th of 25 per second over [0, t_end]: j k / 25 <= t_end.
std::size_t regular_count(double t_end, int k) {
  return static_cast<std::size_t>(std::floor(t_end * 25.0 / k + 1e-9)) + 1;
}

std::size_t frames_within(const std::vector<double>& times, double a, double b) {
  std::size_t n = 0;
  for (double t : times) n += t >= a - 1e-9 && t <= b + 1e-9;
  return n;
}

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

// Every k-th regular frame is there.
void expect_regular_frames(const std::vector<double>& times, double t_end, int k) {
  for (std::size_t j = 0; j < regular_count(t_end, k); ++j)
    EXPECT_EQ(frames_within(times, j * k / 25.0, j * k / 25.0), 1u) << "regular frame " << j;
}

TEST(PostFrameBudget, DefaultsThinTheRegularFramesFirst) {
  const RunData run = read_run(long_run());
  const double t_end = run.time().back();
  const std::size_t episodes = contact_episodes(run).size();
  ASSERT_GT(regular_count(t_end, 1) + 12 * episodes, 1500u) << "the run must exceed the budget";
  int k = 1;
  while (regular_count(t_end, k) + 12 * episodes > 1500) ++k;
  ASSERT_LE(k, kMaxRegularStride) << "the run is chosen to need only thinner regular frames";

  const Timeline line = frame_timeline(run, TimelineOptions{});
  EXPECT_EQ(line.regular_stride, k);
  EXPECT_DOUBLE_EQ(line.fps, 25.0 / k);
  EXPECT_EQ(line.frames_per_episode, 12);
  EXPECT_FALSE(line.uniform);
  EXPECT_LE(line.times.size(), 1500u);
  expect_regular_frames(line.times, t_end, k);
  for (const ContactEpisode& e : contact_episodes(run))
    EXPECT_GE(frames_within(line.times, e.start, e.end), 12u) << e.pair << " at " << e.start;
  // One note: what was thinned and the budget that keeps everything.
  EXPECT_TRUE(contains(line.note, "one in " + std::to_string(k))) << line.note;
  EXPECT_TRUE(contains(line.note,
                       "--max-frames " + std::to_string(regular_count(t_end, 1) + 12 * episodes)))
      << line.note;
  std::printf("[ budget ] %zu episodes in %.0f s: regular frames one in %d, %zu frames\n", episodes,
              t_end, k, line.times.size());
}

TEST(PostFrameBudget, TighterBudgetsThinTheEpisodesThenLeaveTheRegularFramesOnly) {
  const RunData run = read_run(long_run());
  const double t_end = run.time().back();
  const auto episodes = contact_episodes(run);
  const std::size_t count = episodes.size();
  const std::size_t thinnest = regular_count(t_end, kMaxRegularStride);

  // Room for 9 frames per episode beside every 5th regular frame.
  TimelineOptions o;
  o.max_frames = static_cast<int>(thinnest + 9 * count);
  Timeline line = frame_timeline(run, o);
  EXPECT_EQ(line.regular_stride, kMaxRegularStride);
  EXPECT_EQ(line.frames_per_episode, 9);
  EXPECT_LE(line.times.size(), static_cast<std::size_t>(o.max_frames));
  expect_regular_frames(line.times, t_end, kMaxRegularStride);
  for (const ContactEpisode& e : episodes) EXPECT_GE(frames_within(line.times, e.start, e.end), 9u);
  EXPECT_TRUE(contains(line.note, "9 frames in each episode")) << line.note;

  // Not even 8 per episode: the regular frames only, every k-th with the smallest k that fits.
  o.max_frames = static_cast<int>(thinnest + 8 * count - 1);
  int k = 1;
  while (regular_count(t_end, k) > static_cast<std::size_t>(o.max_frames)) ++k;
  line = frame_timeline(run, o);
  EXPECT_TRUE(line.uniform);
  EXPECT_EQ(line.frames_per_episode, 0);
  EXPECT_EQ(line.regular_stride, k);
  EXPECT_EQ(line.times.size(), regular_count(t_end, k));
  EXPECT_TRUE(contains(line.note, "no frames added in the contact episodes")) << line.note;
}

TEST(PostFrameBudget, OptionsGivenAreKeptOrRefused) {
  const RunData run = read_run(long_run());
  const double t_end = run.time().back();
  const std::size_t count = contact_episodes(run).size(), all = regular_count(t_end, 1);

  // --fps given: every regular frame stays; the default frames per episode are thinned.
  TimelineOptions o;
  o.fps_given = true;
  const std::size_t per = (1500 - all) / count;
  ASSERT_GE(per, 8u) << "the run is chosen to leave room for 8 per episode";
  Timeline line = frame_timeline(run, o);
  EXPECT_EQ(line.regular_stride, 1);
  EXPECT_EQ(line.frames_per_episode, static_cast<int>(per));

  // --impact-frames given and no room for it even at every 5th regular frame: refused.
  o = TimelineOptions{};
  o.frames_per_episode_given = true;
  o.max_frames = static_cast<int>(regular_count(t_end, kMaxRegularStride) + 12 * count - 1);
  try {
    frame_timeline(run, o);
    ADD_FAILURE() << "accepted";
  } catch (const TimelineError& e) {
    EXPECT_TRUE(contains(e.what(), "--max-frames")) << e.what();
  }
  // --uniform: the default rate thinned to fit, a rate given refused.
  o = TimelineOptions{};
  o.uniform = true;
  o.max_frames = static_cast<int>(all - 1);
  line = frame_timeline(run, o);
  EXPECT_EQ(line.regular_stride, 2);
  EXPECT_EQ(line.times.size(), regular_count(t_end, 2));
  o.fps_given = true;
  EXPECT_THROW(frame_timeline(run, o), TimelineError);
}

// The command: one note on the console, the frames within the budget, exit 0; the same budget with
// --impact-frames given is refused (exit 2). A budget is given so that the test writes few frames;
// the default budget takes the same path (DefaultsThinTheRegularFramesFirst).
TEST(PostFrameBudget, AnimateFitsTheBudgetWithOneNote) {
  const fs::path dir = test::scratch_dir("budget-cli-anim");
  std::ofstream(dir / "model.yaml") << rattling_model("4 s");
  auto r =
      test::run_solver("run -q " + (dir / "model.yaml").string() + " -o " + (dir / "run").string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const RunData run = read_run(dir / "run");
  const std::size_t count = contact_episodes(run).size();
  ASSERT_GE(count, 5u) << "the run must pound";
  const std::size_t budget = regular_count(run.time().back(), kMaxRegularStride) + 9 * count;
  r = test::run_post("animate " + (dir / "run").string() + " --max-frames " +
                     std::to_string(budget) + " -o " + (dir / "anim").string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const std::regex note("isopound-post: note: [^\n]*--max-frames [0-9]+ keeps [^\n]*\n");
  EXPECT_EQ(std::distance(std::sregex_iterator(r.output.begin(), r.output.end(), note),
                          std::sregex_iterator()),
            1)
      << r.output;
  EXPECT_TRUE(contains(r.output, "9 frames each")) << r.output;
  EXPECT_LE(test::read_pvd(dir / "anim" / "animation.pvd").size(), budget);

  r = test::run_post("animate " + (dir / "run").string() + " --impact-frames 12 --max-frames " +
                     std::to_string(budget) + " -o " + (dir / "anim-given").string());
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_TRUE(contains(r.output, "--max-frames")) << r.output;
  fs::remove_all(dir);
}

}  // namespace
}  // namespace isopound::post
