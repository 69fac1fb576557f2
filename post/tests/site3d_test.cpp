// The 3D frames' geometry of a building isolated above a storey (issue 27 item 2,
// docs/isolation-level.md, "3D buildings"): the base slab at its elevation, the bearings between
// floor k and the slab, storey k + 1's columns on the slab, the substructure's on the ground.
// Rubber bumpers (issue 27 item 1): the strips of a wall and of a neighbour's face, named as the
// solver's contacts name them, drawn where the solver puts them and moving with their owner.
#include <gtest/gtest.h>

#include <yaml-cpp/yaml.h>

#include "post/animation3d.h"
#include "post/contact_log.h"
#include "post/run_data.h"
#include "post/site3d.h"
#include "post_test_support.h"
#include "solver/io/model_input.h"
#include "solver/structures/job.h"

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

// An isolated 12 x 12 m building with a bumpered east wall (4 cm of rubber at an 8 cm gap) and a
// fixed-base neighbour 10 cm to its west with 5 cm of rubber on its east face (slabs reaching the
// columns' outer faces, as the site checks require).
constexpr const char* kBumpered = R"(structures:
  - name: building
    grid: {bays_x: [6 m, 6 m], bays_y: [6 m, 6 m]}
    plan: {rectangle: [12.45 m, 12.45 m]}
    columns: {section: [45 cm, 45 cm], E: 30 GPa, nu: 0.2}
    storeys: {count: 2, height: 3.2 m, mass: 300 t}
    base: {mass: 300 t}
    bearing: {model: bouc_wen, Tb: 2.0 s, QW: 5 %, uy: 1 cm}
    walls: {sides: [east], gap: 8 cm, bumper: {thickness: 4 cm, E: 10 MPa, height: 50 cm, e: 0.8}}
  - name: west
    isolated: false
    adjacent: {to: building, side: west, gap: 10 cm}
    grid: {bays_x: [6 m], bays_y: [6 m, 6 m]}
    plan: {rectangle: [6.35 m, 12.35 m]}
    columns: {section: [35 cm, 35 cm], E: 30 GPa, nu: 0.2}
    storeys: {count: 2, height: 3.2 m, mass: 150 t}
    bumper: {thickness: 5 cm, E: 10 MPa, height: 30 cm, e: 0.7}
ground_motion:
  L: {pulse: {amplitude: 0.8 m/s, period: 1 s}}
  T: {pulse: {amplitude: 0.4 m/s, period: 1 s}}
  angle: 20 deg
)";

TEST(PostSite3D, BumperStripsAreTheSolversAndMoveWithTheirOwner) {
  const ModelConfig config = load_model(YAML::Load(kBumpered), "inline.yaml", "");
  const Site3D site = site_geometry(config);
  // Every contact of the solver's model names two bodies of the drawn site.
  const Model model = build_model(config);
  int strips = 0;
  for (const auto& e : model.elements) {
    const std::string& label = e->label();
    if (label.find('|') == std::string::npos || label.find("/bearing") != std::string::npos)
      continue;
    std::string a, b;
    ASSERT_TRUE(split_pair(label, a, b)) << label;
    EXPECT_GE(site.find(a), 0) << label;
    EXPECT_GE(site.find(b), 0) << label;
    strips += label.ends_with("bumper") || label.ends_with("bumper bottomed") ? 1 : 0;
  }
  EXPECT_EQ(strips, 2 + 2 * 2);  // the wall's two; the neighbour's two at each pounding floor
  // The wall's rubber: x in [6 + 0.08 - 0.04, 6 + 0.08 - 0.04 + 0.6 x 0.04] (the slab's east face
  // at 6 m: the base slab spans the grid), glued to the wall.
  const int wall = site.find("wall east"), rubber = site.find("wall east bumper");
  ASSERT_GE(wall, 0);
  ASSERT_GE(rubber, 0);
  const PlanBody& r = site.bodies[static_cast<std::size_t>(rubber)];
  EXPECT_EQ(r.follows, wall);
  EXPECT_EQ(r.role, "rubber");
  double x0 = 1e9, x1 = -1e9;
  for (Vec2 p : r.plan_W) x0 = std::min(x0, p.x), x1 = std::max(x1, p.x);
  const Vec2 hi =
      site.bodies[static_cast<std::size_t>(site.find("building/base"))].polygon().box_max();
  EXPECT_NEAR(x0, hi.x + 0.04, 1e-9);
  EXPECT_NEAR(x1, hi.x + 0.04 + 0.024, 1e-9);
  // The neighbour's east-face rubber on floor 1: x from its face out by 5 cm, following it.
  const int floor1 = site.find("west/floor 1");
  const int face = site.find("west/floor 1 east bumper");
  ASSERT_GE(face, 0);
  EXPECT_EQ(site.bodies[static_cast<std::size_t>(face)].follows, floor1);
  const double face_x = site.bodies[static_cast<std::size_t>(floor1)].polygon().box_max().x;
  double far_x = -1e9;
  for (Vec2 p : site.bodies[static_cast<std::size_t>(face)].plan_W) far_x = std::max(far_x, p.x);
  EXPECT_NEAR(far_x, face_x + 0.05, 1e-9);
  const double building_x =
      site.bodies[static_cast<std::size_t>(site.find("building/floor 1"))].polygon().box_min().x;
  EXPECT_NEAR(building_x - face_x, 0.10, 1e-9);  // the declared gap

  // Drawn: the strip moves with the floor it is glued to (no DOFs of its own).
  RunData run;
  run.three_d = true;
  run.site = site;
  run.columns = {"time [s]", "west/floor 1 (x) u [m]", "west/floor 1 (y) u [m]",
                 "west/floor 1 (theta) u [rad]"};
  run.values = {{0.0, 1.0}, {0.0, 0.03}, {0.0, 0.0}, {0.0, 0.0}};
  Level l;
  l.label = "west/floor 1";
  l.u = 1, l.u_y = 2, l.theta = 3, l.body = floor1;
  run.structures.push_back({"west", {l}});
  AnimationOptions o;
  o.scale = 1.0;
  const FrameMesh m = animation_frame3d(run, 1.0, o);
  const MeshArray& block = m.cell_data[0];
  double rubber_x1 = -1e9;
  int rubber_cells = 0;
  for (std::size_t c = 0; c < m.cells.size(); ++c) {
    if (block.values[c] != static_cast<double>(Block::kRubber)) continue;
    ++rubber_cells;
    for (int p : m.cells[c].points) {
      const auto& q = m.points[static_cast<std::size_t>(p)];
      if (q[2] > 2.0 && q[2] < 4.0)  // floor 1's strips (3.2 m), not floor 2's nor the wall's
        rubber_x1 = std::max(rubber_x1, q[0]);
    }
  }
  EXPECT_GT(rubber_cells, 0);
  EXPECT_NEAR(rubber_x1, face_x + 0.05 + 0.03, 1e-9);  // moved 3 cm east with floor 1
}

}  // namespace
}  // namespace isopound::post
