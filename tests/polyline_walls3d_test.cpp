// Walls along a polyline of their own (issue 40 item 3; geometry/moat.h polyline_walls,
// walls: {follow: polyline}): the mitred bands against hand-computed areas and corners, the side
// away from the slab however the line is drawn, a polyline along three faces of a square slab
// struck head-on as its box walls are, a slanted wall's clearance against its closed form and
// its impacts passive, rubber on a polyline face, and bad input refused at its key.
#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "geometry/moat.h"
#include "geometry/overlap.h"
#include "solver/core/analysis.h"
#include "solver/elements/polygon_contact.h"
#include "solver/excitation/ground_motion.h"
#include "solver/io/model_input.h"
#include "solver/io/yaml_reader.h"
#include "solver/structures/job.h"
#include "solver/structures/pounding3d.h"
#include "tests/wall_run_support.h"

namespace isopound {
namespace {

double area_of(const MoatWall& w) {
  return area_properties(w.outline).area;
}

// Three runs around the square [-10, 10]² (counter-clockwise, walls to the right, outside it):
// south from x = -12, east, north back to x = -12; thickness 1. A run's wall is its face times t
// plus, at each mitred 90° corner, the t × t / 2 triangle beyond the face's end.
TEST(PolylineWalls, MitredBandsOnTheRightMeetWithoutOverlapOrGap) {
  const std::vector<Vec2> line = {{-12, -10}, {10, -10}, {10, 10}, {-12, 10}};
  const std::vector<MoatWall> walls = polyline_walls(line, 1.0);
  ASSERT_EQ(walls.size(), 3u);
  EXPECT_NEAR(area_of(walls[0]), 22.0 + 0.5, 1e-12);
  EXPECT_NEAR(area_of(walls[1]), 20.0 + 0.5 + 0.5, 1e-12);
  EXPECT_NEAR(area_of(walls[2]), 22.0 + 0.5, 1e-12);
  // The east wall: its face on x = 10 from y = -10 to 10, its back on x = 11 from -11 to 11.
  const Vec2 lo = walls[1].outline.box_min(), hi = walls[1].outline.box_max();
  EXPECT_NEAR(lo.x, 10.0, 1e-12);
  EXPECT_NEAR(hi.x, 11.0, 1e-12);
  EXPECT_NEAR(lo.y, -11.0, 1e-12);
  EXPECT_NEAR(hi.y, 11.0, 1e-12);
  // Neighbours share the mitre and no area; the three fill the band with no hole (areas add up
  // to the band's: 22 + 20 + 22 faces times 1 plus the two corner squares).
  EXPECT_LT(overlap_of(walls[0].outline, walls[1].outline).area, 1e-12);
  EXPECT_LT(overlap_of(walls[1].outline, walls[2].outline).area, 1e-12);
  EXPECT_NEAR(area_of(walls[0]) + area_of(walls[1]) + area_of(walls[2]), 64.0 + 2.0, 1e-12);
  // Each wall faces its run: the wall to the right of (p_WS -> p_WE).
  EXPECT_EQ(walls[1].p_WS.x, 10.0);
  EXPECT_EQ(walls[1].p_WS.y, -10.0);
  EXPECT_EQ(walls[1].p_WE.y, 10.0);
}

// The same line drawn the other way with the walls on its left gives the same walls, listed in
// the order drawn; a re-entrant joint (the walls on the inside of the turn) is mitred too; a
// collinear point does not split a wall.
TEST(PolylineWalls, EitherSideAndCollinearPoints) {
  const std::vector<Vec2> line = {{-12, -10}, {10, -10}, {10, 10}, {-12, 10}};
  std::vector<Vec2> back(line.rbegin(), line.rend());
  const std::vector<MoatWall> right = polyline_walls(line, 1.0);
  const std::vector<MoatWall> left = polyline_walls(back, 1.0, true);
  ASSERT_EQ(left.size(), 3u);
  for (int k = 0; k < 3; ++k) {
    const MoatWall& a = right[static_cast<std::size_t>(k)];
    const MoatWall& b = left[static_cast<std::size_t>(2 - k)];
    EXPECT_NEAR(area_of(a), area_of(b), 1e-12);
    EXPECT_NEAR(overlap_of(a.outline, b.outline).area, area_of(a), 1e-9) << k;
    EXPECT_EQ(a.p_WS.x, b.p_WS.x);
    EXPECT_EQ(a.p_WS.y, b.p_WS.y);
  }
  // Walls inside the turns (on the line's left here, the square's inside): faces 22, 20, 22,
  // each corner takes t × t / 2 off the band.
  const std::vector<MoatWall> inside = polyline_walls(line, 1.0, true);
  EXPECT_NEAR(area_of(inside[1]), 20.0 - 1.0, 1e-12);
  EXPECT_NEAR(area_of(inside[0]), 22.0 - 0.5, 1e-12);
  EXPECT_LT(overlap_of(inside[0].outline, inside[1].outline).area, 1e-12);
  const std::vector<Vec2> straight = {{0, 0}, {4, 0}, {10, 0}};
  const std::vector<MoatWall> one = polyline_walls(straight, 0.5);
  ASSERT_EQ(one.size(), 1u);
  EXPECT_NEAR(area_of(one[0]), 5.0, 1e-12);
}

// Each run its own thickness: where two runs meet, their backs' offsets cross (a right-angle
// turn: the corner of the two back lines), so the walls still share only the mitre.
TEST(PolylineWalls, EachRunItsOwnThickness) {
  const std::vector<Vec2> line = {{-12, -10}, {10, -10}, {10, 10}};
  const std::vector<MoatWall> walls = polyline_walls(line, std::vector<double>{1.0, 2.0}, false);
  ASSERT_EQ(walls.size(), 2u);
  // South: face 22 (y = -10), back 24 (y = -11, to x = 12), 1 deep; east: face 20 (x = 10),
  // back 21 (x = 12, from y = -11), 2 deep.
  EXPECT_NEAR(area_of(walls[0]), (22.0 + 24.0) / 2 * 1.0, 1e-12);
  EXPECT_NEAR(area_of(walls[1]), (20.0 + 21.0) / 2 * 2.0, 1e-12);
  EXPECT_NEAR(walls[1].outline.box_max().x, 12.0, 1e-12);
  EXPECT_NEAR(walls[1].outline.box_min().y, -11.0, 1e-12);
  EXPECT_LT(overlap_of(walls[0].outline, walls[1].outline).area, 1e-12);
  // The same thickness for every run is the one-thickness walls, bit for bit.
  const std::vector<MoatWall> one = polyline_walls(line, 1.5);
  const std::vector<MoatWall> each = polyline_walls(line, std::vector<double>{1.5, 1.5}, false);
  for (std::size_t k = 0; k < one.size(); ++k)
    for (std::size_t i = 0; i < one[k].outline.vertices().size(); ++i) {
      EXPECT_EQ(one[k].outline.vertices()[i].x, each[k].outline.vertices()[i].x);
      EXPECT_EQ(one[k].outline.vertices()[i].y, each[k].outline.vertices()[i].y);
    }
}

TEST(PolylineWalls, RefusesWhatCannotBeAWallNamingTheVertex) {
  const auto vertex_of = [](std::vector<Vec2> line, double t) {
    try {
      polyline_walls(line, t);
    } catch (const InvalidPolygon& e) {
      return e.vertex();
    }
    return -2;  // accepted
  };
  EXPECT_EQ(vertex_of({{0, 0}, {5, 0}, {5, 0}, {5, 5}}, 1.0), 2);  // repeated
  EXPECT_EQ(vertex_of({{0, 0}, {5, 0}, {2, 0}}, 1.0), 1);          // turns back
  EXPECT_EQ(vertex_of({{0, 0}}, 1.0), -1);                         // one point
  // A 0.5 m jog with walls 1 m thick is a wall; a 0.5 m hairpin with them inside both turns is
  // not: the mitres of the short run's ends cross before its back (it would run backwards).
  EXPECT_EQ(vertex_of({{0, 0}, {10, 0}, {10, -0.5}, {20, -0.5}}, 1.0), -2);
  EXPECT_EQ(vertex_of({{0, 0}, {10, 0}, {10, -0.5}, {0, -0.5}}, 1.0), 1);
}

// The clearance along a slanted wall's normal: the slab corner that reaches furthest towards it,
// in closed form.
TEST(PolylineWalls, NormalClearanceOfASlantedWall) {
  const std::vector<Vec2> square = {{-8.25, -8.25}, {8.25, -8.25}, {8.25, 8.25}, {-8.25, 8.25}};
  const Vec2 a{-8.45, 8.65}, b{11.0, 9.65};
  const std::vector<Vec2> line = {a, b};
  const std::vector<MoatWall> walls = polyline_walls(line, 1.0, true);  // north of the line
  const double L = std::hypot(b.x - a.x, b.y - a.y);
  const Vec2 n{-(b.y - a.y) / L, (b.x - a.x) / L};
  const NormalClearance c = normal_clearance(square, walls[0].outline.vertices(), n);
  // The north-west corner: n·(a − corner).
  EXPECT_NEAR(c.clearance, n.x * (a.x + 8.25) + n.y * (a.y - 8.25), 1e-12);
  EXPECT_EQ(c.p_WA.x, -8.25);
  EXPECT_EQ(c.p_WA.y, 8.25);
}

// --- in a model -----------------------------------------------------------------------------

ModelConfig load_text(const std::string& text) {
  return load_model(YAML::Load(text), "inline.yaml", "/models");
}

// The thesis building (configs/3d-xy5.yaml: a 16.5 m square base) with `walls` as given.
std::string building(const std::string& walls) {
  return test::moat_building("{mass: 340 t}", walls);
}

std::string refused_key(const std::string& walls) {
  try {
    load_text(building(walls));
  } catch (const InputError& e) {
    return e.key();
  }
  return "(accepted)";
}

using test::Outcome;
using test::pulse_at;
constexpr auto run = &test::run_until;
constexpr auto contact = &test::polygon_contact;

// Three box walls at 20 cm (1 m thick, 1.2 m beyond the slab: the mitred walls' length, so the
// same mass) against a polyline along the same three faces. Head-on (x, then y), the slab's
// face meets each struck wall inside its face's extent, so the overlaps, and the runs, are the
// same up to the order the overlap's vertices come in: peaks to 1e-7 of the largest (measured:
// 2e-8; the located onsets move by round-off and the adaptive steps with them).
TEST(PolylineWalls3D, APolylineAlongThreeFacesIsStruckHeadOnAsTheBoxWalls) {
  const std::string common = "thickness: 1 m, height: 1 m, mass_per_length: 5 t/m}";
  const ModelConfig box =
      load_text(building("{sides: [east, north, south], gap: 20 cm, extension: 1.2 m, " + common));
  const ModelConfig line = load_text(building(
      "{follow: polyline, polyline: [[-9.45 m, -8.45 m], [8.45 m, -8.45 m], [8.45 m, 8.45 m], "
      "[-9.45 m, 8.45 m]], " +
      common));
  for (const SiteBody& w : site_bodies(line)) {
    if (w.role == "wall") {
      EXPECT_NEAR(w.wall_gap, 0.2, 1e-12) << w.wall_face;
    }
  }
  for (const double angle : {0.0, std::numbers::pi / 2}) {
    const GroundMotion g = pulse_at(angle);
    const Outcome a = run(box, g, 6.0), b = run(line, g, 6.0);
    const std::string struck =
        angle == 0.0 ? "building/base|wall east" : "building/base|wall north";
    const PolygonContact* pa = contact(a.model, struck);
    const PolygonContact* pb = contact(b.model, struck);
    ASSERT_NE(pa, nullptr);
    ASSERT_NE(pb, nullptr);
    EXPECT_GT(pa->impacts(), 0) << "the pulse must reach the wall for the comparison to mean much";
    EXPECT_EQ(pa->impacts(), pb->impacts());
    EXPECT_NEAR(pb->max_impact_velocity(), pa->max_impact_velocity(),
                1e-7 * pa->max_impact_velocity());
    ASSERT_EQ(a.result.displacement.size(), b.result.displacement.size());
    double largest_u = 0.0, largest_a = 0.0;  // the peaks' scales (off-axis ones are round-off)
    for (std::size_t i = 0; i < a.result.displacement.size(); ++i) {
      largest_u = std::max(largest_u, std::abs(a.result.displacement[i].value));
      largest_a = std::max(largest_a, std::abs(a.result.absolute_acceleration[i].value));
    }
    for (std::size_t i = 0; i < a.result.displacement.size(); ++i) {
      const std::string& dof = a.model.dofs[i].label;
      if (dof.find("(theta)") != std::string::npos) {
        // Head-on there is no torsion but what round-off seeds through friction's stick spring
        // (both runs: below 1e-3 of the peaks at the slab's corner, 11.7 m out).
        for (const AnalysisResult* r : {&a.result, &b.result}) {
          EXPECT_LT(11.7 * r->displacement[i].value, 1e-3 * largest_u) << dof;
          EXPECT_LT(11.7 * r->absolute_acceleration[i].value, 1e-3 * largest_a) << dof;
        }
        continue;
      }
      EXPECT_NEAR(b.result.displacement[i].value, a.result.displacement[i].value, 1e-7 * largest_u)
          << dof;
      EXPECT_NEAR(b.result.absolute_acceleration[i].value, a.result.absolute_acceleration[i].value,
                  1e-7 * largest_a)
          << dof;
    }
  }
}

// configs/3d-retaining-wall.yaml's wall (west at 20 cm, then a north wall rising 1 m over its
// 19.45 m): drawn clockwise around the slab or the other way, the walls stand on the side away
// from it, each at its clearance; a pulse at 120° strikes both, every episode of
// every contact passive, the energy balance closing with the step tolerance.
constexpr const char* kRetaining =
    "{follow: polyline, polyline: [[-8.45 m, -11 m], [-8.45 m, 8.65 m], [11 m, 9.65 m]], "
    "thickness: 1 m, height: 1.5 m, mass_per_length: 8 t/m";

TEST(PolylineWalls3D, ASlantedRetainingWallIsStruckPassively) {
  const ModelConfig c = load_text(building(std::string(kRetaining) + "}"));
  const ModelConfig reversed = load_text(building(
      "{follow: polyline, polyline: [[11 m, 9.65 m], [-8.45 m, 8.65 m], [-8.45 m, -11 m]], "
      "thickness: 1 m, height: 1.5 m, mass_per_length: 8 t/m}"));
  std::vector<std::string> faces;
  for (const SiteBody& w : site_bodies(c)) {
    if (w.role != "wall") continue;
    faces.push_back(w.wall_face);
    if (w.wall_face == "north") {
      const double L = std::hypot(19.45, 1.0);
      EXPECT_NEAR(w.wall_gap, (0.2 + 19.45 * 0.4) / L, 1e-12);  // n·(a − north-west corner)
    } else {
      EXPECT_NEAR(w.wall_gap, 0.2, 1e-12);
    }
    bool found = false;
    for (const SiteBody& v : site_bodies(reversed))
      if (v.role == "wall" && v.wall_face == w.wall_face) {
        found = true;
        EXPECT_NEAR(overlap_of(v.plan_W, w.plan_W).area, area_properties(w.plan_W).area, 1e-9);
      }
    EXPECT_TRUE(found) << w.wall_face;
  }
  EXPECT_EQ(faces, (std::vector<std::string>{"west", "north"}));
  const Outcome r = run(c, pulse_at(2 * std::numbers::pi / 3), 8.0);
  for (const char* wall : {"building/base|wall west", "building/base|wall north"}) {
    const PolygonContact* p = contact(r.model, wall);
    ASSERT_NE(p, nullptr) << wall;
    EXPECT_GT(p->impacts(), 0) << wall;
  }
  test::expect_every_episode_passive(r.model);
  EXPECT_LT(std::abs(r.result.energy.relative_error), 1e-3);
  ModelConfig tight = c;
  tight.analysis.tolerance = 1e-5;
  EXPECT_LT(
      std::abs(run(tight, pulse_at(2 * std::numbers::pi / 3), 8.0).result.energy.relative_error),
      2e-4);
}

// Rubber on the west face of the retaining wall (by face name, as on an outline wall): struck
// before the concrete, every episode passive; flexible walls take the polyline's too.
TEST(PolylineWalls3D, RubberAndFlexibleWallsAlongAPolyline) {
  const ModelConfig c = load_text(
      building(std::string(kRetaining) +
               ", bumper: {sides: [west], thickness: 10 cm, E: 10 MPa, height: 30 cm, e: 0.7}}"));
  const Outcome r = run(c, pulse_at(std::numbers::pi), 8.0);
  const PolygonContact* rubber = contact(r.model, "building/base|wall west bumper");
  ASSERT_NE(rubber, nullptr);
  EXPECT_GT(rubber->impacts(), 0);
  test::expect_every_episode_passive(r.model);
  EXPECT_LT(std::abs(r.result.energy.relative_error), 1e-3);
  const ModelConfig flexible = load_text(building(std::string(kRetaining) + ", model: flexible}"));
  const Outcome f = run(flexible, pulse_at(std::numbers::pi), 8.0);
  const PolygonContact* west = contact(f.model, "building/base|wall west");
  ASSERT_NE(west, nullptr);
  EXPECT_GT(west->impacts(), 0);
  EXPECT_LT(std::abs(f.result.energy.relative_error), 1e-3);
}

// Segments with their own thickness and model: the retaining wall's west wall rigid and 1 m
// thick, its north wall flexible and 60 cm thick (its own 3 DOFs, its section from that
// thickness); struck by the pulse, every episode passive. A map by face gives every wall's face.
TEST(PolylineWalls3D, EachWallItsOwnThicknessAndModel) {
  const ModelConfig c = load_text(building(
      "{follow: polyline, polyline: [[-8.45 m, -11 m], [-8.45 m, 8.65 m], [11 m, 9.65 m]], "
      "height: 1.5 m, mass_per_length: 8 t/m, thickness: {west: 1 m, north: 60 cm}, "
      "model: {west: rigid, north: flexible}}"));
  for (const SiteBody& w : site_bodies(c)) {
    if (w.role != "wall") continue;
    const bool north = w.wall_face == "north";
    EXPECT_EQ(w.dof_label_u.empty(), !north) << w.wall_face;
    // Its depth along its normal: the thickness.
    const WallExtent e = wall_extent(w.plan_W.vertices(), w.wall_normal_W);
    double back = -1e9;
    for (const Vec2& p : w.plan_W.vertices()) back = std::max(back, dot(w.wall_normal_W, p));
    EXPECT_NEAR(back - e.face, north ? 0.6 : 1.0, 1e-12) << w.wall_face;
  }
  const Outcome r = run(c, pulse_at(2 * std::numbers::pi / 3), 8.0);
  const PolygonContact* north = contact(r.model, "building/base|wall north");
  ASSERT_NE(north, nullptr);
  EXPECT_GT(north->impacts(), 0);
  test::expect_every_episode_passive(r.model);
  EXPECT_LT(std::abs(r.result.energy.relative_error), 1e-3);
  const std::string line =
      "{follow: polyline, polyline: [[-8.45 m, -11 m], [-8.45 m, 8.65 m], [11 m, 9.65 m]], ";
  EXPECT_EQ(refused_key(line + "thickness: {west: 1 m}}"), "structures[0].walls.thickness");
  EXPECT_EQ(refused_key(line + "thickness: {west: 1 m, north: 1 m, east: 1 m}}"),
            "structures[0].walls.thickness.east");
  EXPECT_EQ(refused_key(line + "model: {west: rigid, north: bendy}}"),
            "structures[0].walls.model.north");
  // Box walls by side: the east wall 2 m thick.
  const ModelConfig box = load_text(
      building("{sides: [east, west], gap: 20 cm, thickness: {east: 2 m, west: 1 m}, model: {east: "
               "flexible, west: rigid}}"));
  for (const SiteBody& w : site_bodies(box)) {
    if (w.role != "wall") continue;
    const bool east = w.wall_face == "east";
    EXPECT_NEAR(w.plan_W.box_max().x - w.plan_W.box_min().x, east ? 2.0 : 1.0, 1e-12);
    EXPECT_EQ(w.dof_label_u.empty(), !east);
  }
  EXPECT_EQ(refused_key("{sides: [east, west], gap: 20 cm, thickness: {east: 2 m}}"),
            "structures[0].walls.thickness");
  EXPECT_EQ(refused_key("{sides: [east], gap: 20 cm, thickness: {east: 2 m, west: 1 m}}"),
            "structures[0].walls.thickness.west");
}

TEST(PolylineWalls3D, BadPolylinesAreRefusedAtTheirKey) {
  // Through the slab.
  EXPECT_EQ(refused_key("{follow: polyline, polyline: [[-9 m, -11 m], [-8 m, 11 m]]}"),
            "structures[0].walls.polyline");
  // Touching it.
  EXPECT_EQ(refused_key("{follow: polyline, polyline: [[-8.25 m, -11 m], [-8.25 m, 11 m]]}"),
            "structures[0].walls.polyline");
  EXPECT_EQ(
      refused_key("{follow: polyline, polyline: [[-9 m, -11 m], [-9 m, -11 m], [-9 m, 11 m]]}"),
      "structures[0].walls.polyline[1]");
  EXPECT_EQ(refused_key("{follow: polyline, polyline: [[-9 m, -11 m]]}"),
            "structures[0].walls.polyline");
  EXPECT_EQ(refused_key("{follow: polyline}"), "structures[0].walls.polyline");
  EXPECT_EQ(refused_key("{follow: polyline, gap: 20 cm, polyline: [[-9 m, -11 m], [-9 m, 11 m]]}"),
            "structures[0].walls.gap");
  EXPECT_EQ(refused_key("{follow: outline, gap: 20 cm, polyline: [[-9 m, -11 m], [-9 m, 11 m]]}"),
            "structures[0].walls.polyline");
  EXPECT_EQ(refused_key("{polyline: [[-9 m, -11 m], [-9 m, 11 m]], sides: [east]}"),
            "structures[0].walls.sides[0]");
  EXPECT_EQ(
      refused_key(std::string(kRetaining) +
                  ", bumper: {sides: [west], thickness: 20 cm, E: 10 MPa, height: 30 cm, e: 0.7}}"),
      "structures[0].walls.bumper.thickness");
  // Without `follow`, a polyline is followed (a default that adapts).
  EXPECT_EQ(refused_key("{polyline: [[-9 m, -11 m], [-9 m, 11 m]]}"), "(accepted)");
}

}  // namespace
}  // namespace isopound
