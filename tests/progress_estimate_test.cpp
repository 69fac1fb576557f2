// The progress line's time left (solver/io/progress_estimate.h): at the pace of the last ~10 s.
// Its ring read the slot it had just overwritten once full (after 10 s of lines), and printed
// "no step for 0 s" from then on for every long run.
#include <gtest/gtest.h>

#include <cstdio>
#include <string>

#include "solver/io/progress_estimate.h"

namespace isopound {
namespace {

double seconds_left(const std::string& text) {
  double s = -1.0;
  EXPECT_EQ(std::sscanf(text.c_str(), "about %lf s left", &s), 1) << text;
  return s;
}

TEST(ProgressEstimate, TimeLeftAtThePaceOfTheLastTenSecondsLongAfterTheRingIsFull) {
  ProgressEstimate e;
  const double total = 100.0;
  double t = 0.0, wall = 0.0;
  // 60 s at 1 s of analysis per wall second (120 lines, the ring of 20 full six times over)...
  for (int i = 0; i < 120; ++i) {
    wall += 0.5;
    t += 0.5;
    EXPECT_NEAR(seconds_left(e.sample(wall, t, total)), total - t, 0.5) << wall;
  }
  // ... then ten times slower: after the window has passed, the estimate is at the new pace.
  std::string text;
  for (int i = 0; i < 40; ++i) {
    wall += 0.5;
    t += 0.05;
    text = e.sample(wall, t, total);
  }
  EXPECT_NEAR(seconds_left(text), (total - t) / 0.1, 1.0) << text;
  // A stall: no progress over the window, said with its length.
  for (int i = 0; i < 20; ++i) {
    wall += 0.5;
    text = e.sample(wall, t, total);
  }
  EXPECT_EQ(text, "no progress for 10 s");
}

}  // namespace
}  // namespace isopound
