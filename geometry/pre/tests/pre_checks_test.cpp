// Every check of isopound-pre with a model that fails it and the expected message (file:line and
// key), and a model with five problems that prints all five.
#include <gtest/gtest.h>

#include <string>

#include "pre_test_support.h"

namespace isopound::pre::test {
namespace {

struct PreRun {
  int exit_code;
  std::string output;
  std::string file;
};

PreRun check(const std::string& name, const std::string& yaml) {
  const auto dir = scratch_dir("checks-" + name);
  const std::string path = write_model(dir, yaml);
  const auto r = run_pre(path + " -o " + (dir / "out").string() + " --no-plan");
  std::filesystem::remove_all(dir);
  return {r.exit_code, r.output, path};
}

int count(const std::string& text, const std::string& what) {
  int n = 0;
  for (auto at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

TEST(PreChecks, ACleanModelPasses) {
  const PreRun r = check("clean", building_a());
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("0 errors, 0 warnings"), std::string::npos) << r.output;
}

// A plan whose outline crosses itself (a bow tie) is refused as the solver refuses it; an L, T or
// U plan is a plan (issue 40).
TEST(PreChecks, SlabOutlineCrossesItself) {
  const PreRun r =
      check("bowtie",
            building_a() + building_b("[20 m, 0 m]", "3 m",
                                      "{polygon: [[-3 m, -3 m], [3 m, 3 m], [3 m, -3 m], [-3 m, "
                                      "3 m]]}"));
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("structures[1].plan.polygon"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("not a simple polygon"), std::string::npos) << r.output;
  const PreRun l =
      check("l-plan", building_a() + building_b("[20 m, 0 m]", "3 m",
                                                "{polygon: [[-3 m, -3 m], [3 m, -3 m], [3 m, 0 m], "
                                                "[0 m, 0 m], [0 m, 3 m], [-3 m, 3 m]]}"));
  EXPECT_EQ(l.output.find("not a simple polygon"), std::string::npos) << l.output;
}

TEST(PreChecks, SlabDegenerate) {
  const PreRun r = check(
      "degenerate", building_a() + building_b("[20 m, 0 m]", "3 m",
                                              "{polygon: [[0 m, 0 m], [3 m, 0 m], [6 m, 0 m]]}"));
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("not a simple polygon"), std::string::npos) << r.output;
}

TEST(PreChecks, ColumnOutsideItsSlab) {
  std::string cols = kColumns;
  cols.replace(cols.find("[3 m, 3 m]"), 10, "[3 m, 3.5 m]");
  const PreRun r = check("column", building_a(cols));
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("error: " + r.file + ":11:"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("structures[0].storeys[0].columns[2].at: column C3 (and the bearing "
                          "under it) is outside the base slab's plan"),
            std::string::npos)
      << r.output;
}

TEST(PreChecks, BearingOutsideTheBaseSlab) {
  const PreRun r = check("bearing", building_a(kColumns, R"(    bearings:
      - {at: [-3 m, -3 m]}
      - {at: [3.2 m, -3 m]}
      - {at: [3 m, 3 m]}
)"));
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find(r.file + ":17:"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("structures[0].bearings[1].at: bearing B2 is outside the base slab's "
                          "plan"),
            std::string::npos)
      << r.output;
}

TEST(PreChecks, StructuresOverlapAtRest) {
  const PreRun r = check("overlap", building_a() + building_b("[5 m, 0 m]", "3 m"));
  EXPECT_EQ(r.exit_code, 2) << r.output;
  // a spans x in [-3, 3], b in [2, 8]: 1 m x 6 m in common, 1 m deep.
  EXPECT_NE(r.output.find(r.file + ":17:"), std::string::npos) << r.output;  // b's position
  EXPECT_NE(r.output.find("structures[1].position: structures 'a' and 'b' overlap at rest"),
            std::string::npos)
      << r.output;
  EXPECT_NE(r.output.find("share 6.000 m2 (1.000 m deep)"), std::string::npos) << r.output;
}

TEST(PreChecks, FloorsOfPoundingPairsAtDifferentLevels) {
  // b 0.5 m east of a, its floor at 3.5 m against a's at 3.0 m.
  const PreRun r = check("levels", building_a() + building_b("[6.5 m, 0 m]", "3.5 m"));
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find(r.file + ":6:"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("floor 1 of 'a' at 3.000 m has no floor of 'b' at its level (nearest: "
                          "floor 1 at 3.500 m), 0.500 m away"),
            std::string::npos)
      << r.output;
  // The clearance is measured and printed per side.
  EXPECT_NE(r.output.find("b/floor 1"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("east"), std::string::npos);
  // Farther apart than contact.search_distance (2 m), the same levels are no pounding pair.
  const PreRun far = check("levels-far", building_a() + building_b("[10 m, 0 m]", "3.5 m"));
  EXPECT_EQ(far.exit_code, 0) << far.output;
}

TEST(PreChecks, MassesStiffnessesHeightsPositive) {
  std::string yaml = building_a();
  yaml.replace(yaml.find("mass: 100 t"), 11, "mass: -100 t");
  const PreRun r = check("positive", yaml);
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find(r.file + ":7:"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("structures[0].storeys[0].mass: must be > 0"), std::string::npos)
      << r.output;
  std::string h = building_a();
  h.replace(h.find("height: 3 m"), 11, "height: 0 m");
  const PreRun rh = check("positive-h", h);
  EXPECT_NE(rh.output.find("structures[0].storeys[0].height: must be > 0"), std::string::npos)
      << rh.output;
}

TEST(PreChecks, StoreyStiffnessJumpWarns) {
  // Storey 2 with 80 cm columns: k ~ b^4, (80/40)^4 = 16 times storey 1.
  const std::string yaml = building_a() + R"(      - height: 3 m
        mass: 100 t
        columns:
          - {at: [-3 m, -3 m], section: [80 cm, 80 cm]}
          - {at: [3 m, -3 m], section: [80 cm, 80 cm]}
          - {at: [3 m, 3 m], section: [80 cm, 80 cm]}
          - {at: [-3 m, 3 m], section: [80 cm, 80 cm]}
)";
  // Insert storey 2 into the storeys list (before base:).
  std::string model = building_a();
  model.insert(model.find("    base:"), yaml.substr(building_a().size()));
  const PreRun r = check("jump", model);
  EXPECT_EQ(r.exit_code, 0) << r.output;  // a warning only
  EXPECT_NE(r.output.find("warning: " + r.file + ":13:"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("storey stiffness jumps 16.0x along x from storey 1"), std::string::npos)
      << r.output;
  // --strict: warnings count as problems.
  const auto dir = scratch_dir("strict");
  const auto strict =
      run_pre(write_model(dir, model) + " -o " + (dir / "out").string() + " --no-plan --strict");
  EXPECT_EQ(strict.exit_code, 2) << strict.output;
  std::filesystem::remove_all(dir);
}

TEST(PreChecks, VeryEccentricMassWarns) {
  std::string model = building_a();
  model.insert(model.find("    storeys:"), "    eccentricity: [2.5 m, 0 m]\n");
  const PreRun r = check("eccentric", model);
  EXPECT_EQ(r.exit_code, 0) << r.output;
  // Columns at the corners: r = sqrt(sum k (x^2 + y^2) / sum k + GJ/h terms) ~ 4.3 m; 2.5 m is
  // more than 0.30 r.
  EXPECT_NE(r.output.find("very eccentric mass in storey 1 of 'a': e = (2.500 m, 0.000 m)"),
            std::string::npos)
      << r.output;
  EXPECT_NE(r.output.find("very eccentric mass in isolation of 'a'"), std::string::npos);
}

TEST(PreChecks, FewOrCollinearBearingsWarn) {
  const PreRun two = check("two-bearings", building_a(kColumns, R"(    bearings:
      - {at: [-3 m, -3 m]}
      - {at: [3 m, 3 m]}
)"));
  EXPECT_EQ(two.exit_code, 0) << two.output;
  EXPECT_NE(two.output.find(two.file + ":15:"), std::string::npos) << two.output;
  EXPECT_NE(two.output.find("only 2 bearings under 'a'"), std::string::npos) << two.output;
  const PreRun line = check("collinear", building_a(kColumns, R"(    bearings:
      - {at: [-3 m, 0 m]}
      - {at: [0 m, 0 m]}
      - {at: [3 m, 0 m]}
)"));
  EXPECT_EQ(line.exit_code, 0) << line.output;
  EXPECT_NE(line.output.find("the bearings under 'a' stand on one line"), std::string::npos)
      << line.output;
}

// (Six since issue 24: b's columns also stand in a's base slab, a check of its own.)
TEST(PreChecks, FiveProblemsPrintAllFive) {
  std::string cols = kColumns;
  cols.replace(cols.find("[-3 m, 3 m]"), 11, "[-3.5 m, 3 m]");  // 1: column outside
  const std::string model =
      building_a(cols, R"(    bearings:
      - {at: [-3 m, -3 m]}
      - {at: [3 m, -3 m]}
      - {at: [3 m, 3 m]}
      - {at: [-3 m, 4 m]}
)") +  // 2: bearing outside
      // 3: b's plan crosses itself, 4: b overlaps a, 5: b's floor at 3.5 m against a's at 3 m,
      // 6: b's columns (at x = 3 and 7 m) stand in a's base slab (to x = 3 m).
      building_b("[5 m, 0 m]", "3.5 m",
                 "{polygon: [[-3 m, -3 m], [3 m, 3 m], [3 m, -3 m], [-3 m, 3 m]]}");
  const PreRun r = check("five", model);
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("6 errors"), std::string::npos) << r.output;
  EXPECT_EQ(count(r.output, "error: " + r.file + ":"), 6) << r.output;
  for (const char* what :
       {"column C4 of storey 1 is outside its slab's plan",
        "bearing B4 is outside the base slab's plan", "not a simple polygon", "overlap at rest",
        "has no floor of 'b' at its level", "column C1 of storey 1 of 'b' stands in base of 'a'"})
    EXPECT_EQ(count(r.output, what), 1) << what << "\n" << r.output;
}

// Walls (issue 16): measured and printed per side against the declared gaps; a wall may not stand
// in another structure's slab or on its columns.
TEST(PreChecks, WallGapsMeasuredPerSide) {
  const PreRun r = check(
      "walls",
      building_a(
          kColumns,
          R"(    walls: {sides: all, gap: {east: 20 cm, west: 25 cm, north: 30 cm, south: 35 cm}}
)"));
  EXPECT_EQ(r.exit_code, 0) << r.output;
  for (const char* line :
       {"a/base                       east   of it: wall east                       0.2000 m  "
        "(declared 0.2000 m)",
        "west   of it: wall west                       0.2500 m  (declared 0.2500 m)",
        "north  of it: wall north                      0.3000 m",
        "south  of it: wall south                      0.3500 m"})
    EXPECT_NE(r.output.find(line), std::string::npos) << line << "\n" << r.output;
}

TEST(PreChecks, WallInAnotherStructure) {
  // b's base slab (isolated, 6 x 6 m at x = 6.5) begins 0.5 m from a's east face, inside a's
  // 1 m thick east wall at 0.2 m.
  std::string b = building_b("[6.5 m, 0 m]", "3 m");
  b.replace(b.find("    isolated: false\n"), 20, "");
  b.replace(b.find("    damping: {type: none}\n"), 26,
            "    base: {mass: 100 t}\n    bearing: {model: linear, Tb: 2 s}\n");
  const PreRun r =
      check("wall-in", building_a(kColumns, "    walls: {sides: [east], gap: 20 cm}\n") + b);
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find(r.file + ":15:"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("structures[0].walls: the east wall of 'a' overlaps base of 'b' at rest"),
            std::string::npos)
      << r.output;
}

TEST(PreChecks, WallOnColumnsOfAFixedBaseNeighbour) {
  // b (fixed base) 0.5 m east of a: its west columns at x = 3.5 + 1 = 4.5 m stand in a's east
  // wall (x from 3.2 to 4.2 m)? No: at 4.5 m they are clear; with a 1.5 m wall they are not.
  const PreRun clear =
      check("wall-clear", building_a(kColumns, "    walls: {sides: [east], gap: 20 cm}\n") +
                              building_b("[6.5 m, 0 m]", "3 m"));
  EXPECT_EQ(count(clear.output, "stands on column"), 0) << clear.output;
  const PreRun r =
      check("wall-on",
            building_a(kColumns, "    walls: {sides: [east], gap: 20 cm, thickness: 1.5 m}\n") +
                building_b("[6.5 m, 0 m]", "3 m"));
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("the east wall of 'a' stands on column C1 of 'b'"), std::string::npos)
      << r.output;
  EXPECT_NE(r.output.find("the east wall of 'a' stands on column C4 of 'b'"), std::string::npos)
      << r.output;
}

TEST(PreChecks, AdjacentNeighbourAtItsDeclaredGap) {
  // b adjacent east of a at 20 cm: measured 0.200 m between the floors that meet.
  std::string b = building_b("[0 m, 0 m]", "3 m");
  b.replace(b.find("    position: [0 m, 0 m]\n"), 25,
            "    adjacent: {to: a, side: east, gap: 20 cm}\n");
  const PreRun ok = check("adjacent", building_a() + b);
  EXPECT_EQ(ok.exit_code, 0) << ok.output;
  EXPECT_NE(ok.output.find("a/floor 1                    east   of it: b/floor 1                   "
                           "    0.2000 m  (declared 0.2000 m)"),
            std::string::npos)
      << ok.output;
  // b's second floor overhangs 0.3 m to the west: `adjacent` places the bounding boxes, so the
  // floors that meet (floor 1 of both, at 3 m) end up 0.5 m apart, not 0.2 m.
  std::string two = b;
  two += R"(      - height: 3 m
        mass: 100 t
        plan: {polygon: [[-3.3 m, -3 m], [3 m, -3 m], [3 m, 3 m], [-3.3 m, 3 m]]}
        columns: [{at: [-2 m, -2 m]}, {at: [2 m, -2 m]}, {at: [2 m, 2 m]}, {at: [-2 m, 2 m]}]
)";
  const PreRun r = check("adjacent-off", building_a() + two);
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find(r.file + ":17:"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("structures[1].adjacent.gap: the floors of 'b' and 'a' that meet are "
                          "0.500 m apart at the closest (a/floor 1 and b/floor 1), not at the "
                          "declared gap of 0.200 m"),
            std::string::npos)
      << r.output;
}

// 2D models: the checks that apply (stiffness jumps, neighbour floors at equal levels).
TEST(PreChecks, TwoDimensionalModels) {
  const PreRun clean = check("2d", R"(building:
  name: a
  base: {mass: 340 t}
  floors: {count: 3, mass: 340 t, stiffness: 600 MN/m, height: 3.2 m}
)");
  EXPECT_EQ(clean.exit_code, 0) << clean.output;
  EXPECT_NE(clean.output.find("Fixed-base superstructure"), std::string::npos) << clean.output;
  const PreRun r = check("2d-problems", R"(building:
  name: a
  base: {mass: 340 t}
  floors:
    - {mass: 340 t, stiffness: 600 MN/m, height: 3.2 m}
    - {mass: 340 t, stiffness: 100 MN/m, height: 3.2 m}
neighbours:
  - side: right
    gap: 10 cm
    building:
      name: n
      isolated: false
      floors: {count: 2, mass: 340 t, stiffness: 600 MN/m, height: 3.0 m}
    impact: {law: kelvin_voigt, k: 2500 kN/mm, e: 0.7}
)");
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find(r.file + ":6:"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("storey stiffness jumps 6.0x from storey 1"), std::string::npos)
      << r.output;
  EXPECT_NE(r.output.find("neighbours[0]: floor 1 of 'a' at 3.200 m has no floor of 'n'"),
            std::string::npos)
      << r.output;
}

}  // namespace
}  // namespace isopound::pre::test
