// Rubber on a non-convex slab's own faces (issue 40; docs/non-convex-plans.md, "Rubber on the
// slab's own faces"): the strips line the outline's faces by name and the re-entrant corner once;
// head-on, the rubber on a U-shaped building's face and the same rubber on its neighbour's face
// give the same motion (the strips against the non-convex slab go through its contact slots);
// a building striking both prongs of a U-shaped neighbour lined with rubber does no net work in
// any contact episode; bad faces and spans are refused at their keys.
#include <gtest/gtest.h>

#include <algorithm>
#include <limits>

#include "peak_comparison.h"
#include "solver/core/analysis.h"
#include "solver/elements/polygon_contact.h"
#include "solver/excitation/ground_motion.h"
#include "solver/io/model_input.h"
#include "solver/structures/bumper_layer3d.h"
#include "solver/structures/job.h"
#include "solver/structures/pounding3d.h"
#include "test_support.h"
#include "tests/bumper3d_support.h"
#include "tests/model_test_support.h"

namespace isopound {
namespace {

// Net work of an episode relative to its gross work: round-off (tests/bumper3d_test.cpp).
constexpr double kRoundOff = 1e-9;

Bumper3DConfig rubber(double thickness) {
  Bumper3DConfig b;
  b.on = {true, true, true, true};
  b.thickness = thickness;
  b.modulus = 10e6;
  b.height = 0.5;
  return b;
}

// [x_min, x_max, y_min, y_max] of a polygon.
std::array<double, 4> box(const std::vector<Vec2>& p) {
  std::array<double, 4> b{p[0].x, p[0].x, p[0].y, p[0].y};
  for (const Vec2& q : p) {
    b[0] = std::min(b[0], q.x), b[1] = std::max(b[1], q.x);
    b[2] = std::min(b[2], q.y), b[3] = std::max(b[3], q.y);
  }
  return b;
}

void expect_box(const std::vector<Vec2>& p, std::array<double, 4> want, const std::string& what) {
  const std::array<double, 4> got = box(p);
  for (int k = 0; k < 4; ++k) EXPECT_NEAR(got[k], want[k], 1e-12) << what << " " << k;
}

const FaceStrips* find_face(const std::vector<FaceStrips>& faces, const std::string& name) {
  for (const FaceStrips& f : faces)
    if (f.face == name) return &f;
  return nullptr;
}

// An L (10 x 10 with the 6 x 6 north-east quarter cut away, notch corner at (4, 4)): every face
// gets its strips outside the slab, the rubber outermost (t = 10 cm, max_strain 0.6: rubber
// 6 cm in front of 4 cm of bottomed rubber). At the notch the face that starts there (east 2,
// counter-clockwise after north) begins t from the corner, where north's strip ends: the corner
// is lined once. With rubber on east 2 alone it runs into the corner. A convex plan keeps its
// box sides.
TEST(Bumper3DOutline, LFaceStripsLineTheOutlineAndTheNotchOnce) {
  const std::vector<Vec2> l = {{0, 0}, {10, 0}, {10, 4}, {4, 4}, {4, 10}, {0, 10}};
  std::vector<std::string> names;
  for (const OutlineFace& f : outline_faces(SimplePolygon(std::span<const Vec2>(l))))
    names.push_back(f.name);
  std::sort(names.begin(), names.end());
  EXPECT_EQ(names,
            (std::vector<std::string>{"east", "east 2", "north", "north 2", "south", "west"}));
  const Bumper3DConfig all = rubber(0.1);
  const std::vector<FaceStrips> faces = slab_face_strips(l, all);
  ASSERT_EQ(faces.size(), 6u);
  const auto strips = [&](const std::string& name) {
    const FaceStrips* f = find_face(faces, name);
    EXPECT_NE(f, nullptr) << name;
    return f ? f->strips : BumperStrips{};
  };
  expect_box(strips("south").rubber, {0, 10, -0.1, -0.04}, "south rubber");
  expect_box(strips("south").bottomed, {0, 10, -0.04, 0}, "south bottomed");
  expect_box(strips("east").rubber, {10.04, 10.1, 0, 4}, "east rubber");
  expect_box(strips("north").rubber, {4, 10, 4.04, 4.1}, "north rubber");
  expect_box(strips("north").bottomed, {4, 10, 4, 4.04}, "north bottomed");
  expect_box(strips("east 2").rubber, {4.04, 4.1, 4.1, 10}, "east 2 rubber (after the corner)");
  expect_box(strips("east 2").bottomed, {4, 4.04, 4.1, 10}, "east 2 bottomed");
  expect_box(strips("north 2").rubber, {0, 4, 10.04, 10.1}, "north 2 rubber");
  expect_box(strips("west").bottomed, {-0.04, 0, 0, 10}, "west bottomed");

  Bumper3DConfig notch = all;
  notch.faces = {"east 2"};
  const std::vector<FaceStrips> one = slab_face_strips(l, notch);
  ASSERT_EQ(one.size(), 1u);
  expect_box(one[0].strips.rubber, {4.04, 4.1, 4, 10}, "east 2 alone");
  notch.from = 1.0, notch.to = 3.0;  // from its end of least y, (4, 4)
  expect_box(slab_face_strips(l, notch)[0].strips.rubber, {4.04, 4.1, 5, 7}, "east 2 span");
  notch.to = 6.5;  // beyond the 6 m face
  EXPECT_THROW(slab_face_strips(l, notch), std::invalid_argument);

  const std::vector<Vec2> rectangle = {{-5, -3}, {5, -3}, {5, 3}, {-5, 3}};
  Bumper3DConfig east = rubber(0.1);
  east.on = {true, false, false, false};
  const std::vector<FaceStrips> box_faces = slab_face_strips(rectangle, east);
  ASSERT_EQ(box_faces.size(), 1u);
  EXPECT_EQ(box_faces[0].face, "east");
  const BumperStrips want = slab_bumper_strips(rectangle, 0, east);
  EXPECT_EQ(box(box_faces[0].strips.rubber), box(want.rubber));
}

// A strip that ends inside the face striking it (a span's end, a re-entrant corner, a notch) and
// is pressed through its whole depth: the overlap is the strip's piece beside the slab, whose
// two boundary crossings lie on the slab's side face, across the strip; that chord's normal
// would run along the face, with δ_N = A/w metres deep. The strip's own compression direction
// keeps the normal on the face normal and δ_N at the strip's depth s (A = s L, w = L).
TEST(Bumper3DOutline, AStripPressedThroughItsDepthKeepsItsFaceNormal) {
  const double s = 0.03;                                         // strip depth, m
  const ConvexPolygon slab{{-5, -5}, {5, -5}, {5, 5}, {-5, 5}};  // a 10 m square
  // The strip lies in front of x = 5.01 over y in [-2, 12]: its end y = -2 inside the slab's face.
  const ConvexPolygon strip{{5.01, -2}, {5.01 + s, -2}, {5.01 + s, 12}, {5.01, 12}};
  PolygonContactConfig cfg;
  cfg.friction = false;
  Bumper3DConfig b = rubber(0.05);
  cfg.length_law = bumper_rubber_law(b, 2.58e10);
  const PolygonBody a{0, 1, -1, {0, 0}, slab, 340e3};
  const PolygonBody fixed{-1, -1, -1, {0, 0}, strip, std::numeric_limits<double>::infinity()};
  const double through = 0.01 + s + 0.005;  // the slab's face 5 mm beyond the strip's back
  const auto pressed = [&](const PolygonContactConfig& c) {
    PolygonContact contact("c", a, fixed, c);
    contact.begin_step(1e-4, false);
    contact.set_trial(Eigen::Vector2d(through, 0), Eigen::Vector2d(0, 0));
    return contact.snapshot();
  };
  const ContactSnapshot chord = pressed(cfg);  // without the direction: the chord's normal
  EXPECT_LT(std::abs(chord.n_AB.x), 1e-9);
  EXPECT_GT(chord.indentation, 1.0);  // metres: A/w with w the strip's depth
  cfg.strip_compression_W = {1, 0};
  const ContactSnapshot held = pressed(cfg);
  EXPECT_EQ(held.n_AB.x, 1.0);
  EXPECT_EQ(held.n_AB.y, 0.0);
  EXPECT_NEAR(held.indentation, s, 1e-12);
  EXPECT_NEAR(held.area, s * 7.0, 1e-12);  // y from -2 to 5
  // Below full depth the two agree: the chord runs along the strip's front.
  PolygonContactConfig plain = cfg;
  plain.strip_compression_W = {};
  const auto partly = [&](const PolygonContactConfig& c) {
    PolygonContact contact("c", a, fixed, c);
    contact.begin_step(1e-4, false);
    contact.set_trial(Eigen::Vector2d(0.01 + 0.5 * s, 0), Eigen::Vector2d(0, 0));
    return contact.snapshot();
  };
  EXPECT_NEAR(partly(cfg).normal_force, partly(plain).normal_force,
              1e-12 * partly(plain).normal_force);
  EXPECT_NEAR(partly(cfg).indentation, 0.5 * s, 1e-12);
}

// A U-shaped building (24 m square, a 3 m x 6 m notch in its west face, symmetric about the x
// axis: the x pulse moves it along x only) and a fixed-base neighbour 4 cm east of its straight
// east face. `building_extra` / `neighbour_extra` are keys added to each (indented 4).
constexpr const char* kUPlan =
    "{polygon: [[-12 m, -12 m], [12 m, -12 m], [12 m, 12 m], [-12 m, 12 m], [-12 m, 3 m], "
    "[-9 m, 3 m], [-9 m, -3 m], [-12 m, -3 m]]}";

std::string u_and_neighbour(const std::string& building_extra, const std::string& neighbour_extra) {
  return test::building_beside_neighbour(kUPlan, building_extra, neighbour_extra);
}

using Outcome = test::BumperOutcome;

int impacts_of(const Model& m, const std::string& label) {
  int n = 0;
  bool found = false;
  for (const auto& e : m.elements)
    if (e->label() == label || without_slot(e->label()) == label) {
      n += static_cast<const PolygonContact&>(*e).impacts();
      found = true;
    }
  EXPECT_TRUE(found) << "no contact " << label;
  return n;
}

const std::string kRubber = "{thickness: 2 cm, E: 5 MPa, height: 30 cm, e: 0.7";

// Head-on, the rubber on the U's east face (strips on the non-convex slab's DOFs, convex
// contacts with the neighbour) and the same rubber on the neighbour's west face (strips against
// the U through its contact slots) press the same overlap: the same motion along x, to the
// differences' round-off (1e-6 as for two rectangles, tests/bumper3d_test.cpp).
TEST(Bumper3DOutline, RubberOnTheUOrOnItsNeighbourIsTheSameHeadOn) {
  const GroundMotion pulse = make_pulse(PulseParameters{});  // along x
  const Outcome on_u = test::run_bumper_model(
      test::load_model_text(u_and_neighbour("    bumper: " + kRubber + ", sides: [east]}\n", "")),
      pulse, 3.3);
  const Outcome on_neighbour = test::run_bumper_model(
      test::load_model_text(u_and_neighbour("", "    bumper: " + kRubber + "}\n")), pulse, 3.3);
  const int rubber_u = impacts_of(on_u.model, "neighbour/floor 1|building/floor 1 east bumper");
  EXPECT_GE(rubber_u, 1);
  EXPECT_EQ(rubber_u,
            impacts_of(on_neighbour.model, "building/floor 1|neighbour/floor 1 west bumper"));
  EXPECT_EQ(impacts_of(on_u.model, "building/floor 1|neighbour/floor 1"), 0);  // no concrete
  const test::Comparison c = test::compare(test::x_peaks(on_u), test::x_peaks(on_neighbour));
  EXPECT_LE(c.worst, 1e-6) << c.where;
}

// The U as the neighbour, its notch towards an eccentric building, soft rubber (it bottoms out)
// on both prongs' tips, the notch's back and its two sides; the pulse at 30 degrees: every
// episode of every contact does net work <= 0 and the energy balance closes.
TEST(Bumper3DOutline, EveryEpisodeIsPassiveAgainstARubberLinedU) {
  const std::string text = test::building_beside_neighbour(
      "{rectangle: [16.95 m, 16.95 m]}", "    eccentricity: [1.5 m, 1 m]\n",
      "    bumper: {thickness: 2 cm, E: 0.5 MPa, height: 30 cm, e: 0.6, mu_static: 0.9, "
      "mu_kinetic: 0.7, sides: [west, west 2, west 3, south 2, north 2]}\n",
      kUPlan);
  GroundMotion g = make_pulse(PulseParameters{});
  g.acceleration_y = g.acceleration;
  for (std::size_t k = 0; k < g.acceleration.size(); ++k) {
    g.acceleration_y[k] *= 0.5;
    g.acceleration[k] *= std::sqrt(3.0) / 2;
  }
  const Outcome r = test::run_bumper_model(test::load_model_text(text), g, 4.0);
  int rubber = 0, bottomed = 0, episodes = 0;
  for (const auto& e : r.model.elements) {
    const auto* c = dynamic_cast<const PolygonContact*>(e.get());
    if (!c) continue;
    SCOPED_TRACE(c->label());
    const std::string_view label = without_slot(c->label());
    if (label.ends_with(kBottomedLabel))
      bottomed += c->impacts();
    else if (label.ends_with(kBumperLabel))
      rubber += c->impacts();
    episodes += c->episodes();
    if (c->episodes() > 0) {
      EXPECT_LE(c->max_episode_net_work_relative(), kRoundOff);
    }
    EXPECT_GE(c->friction_dissipated(), 0.0);
  }
  EXPECT_GE(rubber, 2);  // both prongs' tips
  EXPECT_GE(bottomed, 1);
  EXPECT_GE(episodes, 3);
  EXPECT_LT(r.result.energy.relative_error, 1e-3);
}

// Bad faces and spans on a non-convex slab, at their keys.
TEST(Bumper3DOutline, BadFacesAndSpansNameTheirKeys) {
  const auto key_of = [](const std::string& bumper) {
    try {
      test::load_model_text(u_and_neighbour("    bumper: " + bumper + "\n", ""));
    } catch (const InputError& e) {
      return e.key() + ": " + e.what();
    }
    return std::string("(accepted)");
  };
  const std::string rubber = "{thickness: 2 cm, E: 5 MPa, height: 30 cm, e: 0.7, ";
  EXPECT_EQ(key_of(rubber + "sides: [east]}"), "(accepted)");
  EXPECT_EQ(key_of(rubber + "sides: [west, west 2, west 3, north 2, south 2]}"), "(accepted)");
  std::string k = key_of(rubber + "sides: [east, east 2]}");
  EXPECT_EQ(k.substr(0, k.find(':')), "structures[0].bumper.sides[1]") << k;
  EXPECT_NE(k.find("west 2"), std::string::npos) << k;  // lists the faces there are
  k = key_of(rubber + "sides: [west 2], to: 7 m}");     // the notch's back is 6 m
  EXPECT_EQ(k.substr(0, k.find(':')), "structures[0].bumper.to") << k;
  k = key_of("{thickness: 5 cm, E: 5 MPa, height: 30 cm, e: 0.7, sides: [east]}");  // gap 4 cm
  EXPECT_EQ(k.substr(0, k.find(':')), "structures[0].bumper.thickness") << k;
}

}  // namespace
}  // namespace isopound
