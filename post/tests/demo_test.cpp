// `isopound demo`, the README's first command: a 3D pounding run of the built-in model, then its
// pictures and its impact-aware animation with view.py through isopound-post, headless.
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "post_test_support.h"

namespace fs = std::filesystem;
namespace isopound::post {
namespace {

TEST(PostDemo, DemoLeavesTheRunItsPicturesAndTheAnimationWithItsViewScript) {
  const fs::path dir = test::scratch_dir("demo") / "out";
  const auto r = test::run_solver("demo -o " + dir.string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  for (const char* file : {"model.yaml", "summary.json", "histories.csv", "contact_events.csv",
                           "time_histories.png", "trajectory.png", "contacts.png", "hysteresis.png",
                           "floor-spectra.png", "floor-spectra.csv", "animation/animation.pvd",
                           "animation/view.py", "animation/frame_000000.vtu"})
    EXPECT_TRUE(fs::exists(dir / file)) << file;
  // It pounds: every wall is struck, and the animation slows down at the impacts.
  std::ifstream sj(dir / "summary.json");
  const auto summary = nlohmann::json::parse(sj);
  ASSERT_EQ(summary["contacts_3d"].size(), 4u);
  int impacts = 0;
  for (const auto& c : summary["contacts_3d"]) {
    EXPECT_GT(c["impacts"].get<int>(), 0);
    impacts += c["impacts"].get<int>();
  }
  EXPECT_GT(impacts, 20);
  // The closing lines say where each file is and how to open the animation.
  EXPECT_NE(r.output.find("paraview --script=" + (dir / "animation" / "view.py").string()),
            std::string::npos)
      << r.output;
  for (const char* line : {"Results:", "Pictures:", "Animation:"})
    EXPECT_NE(r.output.find(line), std::string::npos) << line;

  // --no-pictures: the run only.
  const fs::path bare = test::scratch_dir("demo-bare");
  const auto b = test::run_solver("demo -q --no-pictures -o " + bare.string());
  ASSERT_EQ(b.exit_code, 0) << b.output;
  EXPECT_TRUE(b.output.empty()) << b.output;
  EXPECT_TRUE(fs::exists(bare / "summary.json"));
  EXPECT_FALSE(fs::exists(bare / "trajectory.png"));
  EXPECT_FALSE(fs::exists(bare / "animation"));
}

}  // namespace
}  // namespace isopound::post
