// The 3D frames' geometry of a building isolated above a storey (issue 27 item 2,
// docs/isolation-level.md, "3D buildings"): the base slab at its elevation, the bearings between
// floor k and the slab, storey k + 1's columns on the slab, the substructure's on the ground.
#include <gtest/gtest.h>

#include "post/site3d.h"
#include "post_test_support.h"
#include "solver/io/model_input.h"

namespace isopound::post {
namespace {

TEST(PostSite3D, MidStoreyIsolationBearingsJoinFloorOneToTheRaisedSlab) {
  const ModelConfig config =
      load_model_file((test::source_dir() / "configs/3d-mid-storey-isolation.yaml").string());
  const Site3D site = site_geometry(config);
  const int base = site.find("building/base"), floor1 = site.find("building/floor 1");
  const int floor2 = site.find("building/floor 2");
  ASSERT_GE(base, 0);
  ASSERT_GE(floor1, 0);
  ASSERT_GE(floor2, 0);
  EXPECT_NEAR(site.bodies[static_cast<std::size_t>(floor1)].elevation, 4.0, 1e-12);
  EXPECT_NEAR(site.bodies[static_cast<std::size_t>(base)].elevation, 5.5, 1e-12);
  EXPECT_NEAR(site.bodies[static_cast<std::size_t>(floor2)].elevation, 8.7, 1e-12);
  ASSERT_EQ(site.bearings.size(), 16u);
  for (const PlanBearing& b : site.bearings) {
    EXPECT_EQ(b.base, base) << b.label;
    EXPECT_EQ(b.lower, floor1) << b.label;
  }
  int on_ground = 0, on_slab = 0;
  for (const PlanColumn& c : site.columns) {
    if (c.label.rfind("building/story 1/", 0) == 0) {
      EXPECT_EQ(c.lower, -1) << c.label;
      EXPECT_EQ(c.upper, floor1) << c.label;
      ++on_ground;
    }
    if (c.label.rfind("building/story 2/", 0) == 0) {
      EXPECT_EQ(c.lower, base) << c.label;
      EXPECT_EQ(c.upper, floor2) << c.label;
      ++on_slab;
    }
  }
  EXPECT_EQ(on_ground, 16);
  EXPECT_EQ(on_slab, 16);
}

}  // namespace
}  // namespace isopound::post
