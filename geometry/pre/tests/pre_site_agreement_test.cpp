// One model check (issue 24 item 2): `isopound check`, `isopound run` and isopound-pre run the
// same site checks (solver/io/site_checks.h), so each broken site model below fails all three
// with exit code 2 and the same error lines, in the same order.
#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <vector>

#include "pre_test_support.h"

namespace isopound::pre::test {
namespace {

// The lines of `output` that begin with `prefix`, without it.
std::vector<std::string> lines_after(const std::string& output, const std::string& prefix) {
  std::vector<std::string> out;
  std::istringstream in(output);
  for (std::string line; std::getline(in, line);)
    if (line.rfind(prefix, 0) == 0) out.push_back(line.substr(prefix.size()));
  return out;
}

std::string replace(std::string s, const std::string& from, const std::string& to) {
  const auto at = s.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return at == std::string::npos ? s : s.replace(at, from.size(), to);
}

struct BrokenSite {
  std::string name;
  std::string yaml;
  std::string what;  // a part of the expected message (the intended problem is the one found)
};

// b with its columns on its slab's corners, placed by `adjacent` east of a at `gap`.
std::string corner_columns_adjacent(const std::string& gap) {
  return replace(replace(building_b("[0 m, 0 m]", "3 m"), "    position: [0 m, 0 m]\n",
                         "    adjacent: {to: a, side: east, gap: " + gap + "}\n"),
                 "columns: [{at: [-2 m, -2 m]}, {at: [2 m, -2 m]}, {at: [2 m, 2 m]}, {at: [-2 m, 2 "
                 "m]}]",
                 "columns: [{at: [-3 m, -3 m]}, {at: [3 m, -3 m]}, {at: [3 m, 3 m]}, {at: [-3 m, 3 "
                 "m]}]");
}

std::string isolated_b(const std::string& position) {
  std::string b = building_b(position, "3 m");
  b = replace(b, "    isolated: false\n", "");
  return replace(b, "    damping: {type: none}\n",
                 "    base: {mass: 100 t}\n    bearing: {model: linear, Tb: 2 s}\n");
}

// A 2D building and a fixed-base neighbour on its right; the neighbour's floors follow.
std::string two_d(const std::string& neighbour_floors) {
  return R"(building:
  name: a
  base: {mass: 340 t}
  floors: {count: 2, mass: 340 t, stiffness: 600 MN/m, height: 3.2 m}
neighbours:
  - building:
      name: n
      isolated: false
)" + neighbour_floors +
         R"(    side: right
    gap: 10 cm
    impact: {law: kelvin_voigt, k: 2500 kN/mm, e: 0.7}
)";
}

std::vector<BrokenSite> broken_sites() {
  const std::string storey2_small = R"(      - height: 3 m
        mass: 100 t
        plan: {rectangle: [5 m, 5 m]}
        columns:
)" + kColumns;
  std::string two_storeys = building_a();
  two_storeys.insert(two_storeys.find("    base:"), storey2_small);
  const std::string bearings_one_out = R"(    bearings:
      - {at: [-3 m, -3 m]}
      - {at: [3.2 m, -3 m]}
      - {at: [3 m, 3 m]}
)";
  std::string storey_eccentric = building_a();
  storey_eccentric.insert(storey_eccentric.find("        columns:"),
                          "        eccentricity: [0 m, 4 m]\n");
  std::string adjacent_off = replace(building_b("[0 m, 0 m]", "3 m"), "    position: [0 m, 0 m]\n",
                                     "    adjacent: {to: a, side: east, gap: 20 cm}\n");
  adjacent_off += R"(      - height: 3 m
        mass: 100 t
        plan: {polygon: [[-3.3 m, -3 m], [3 m, -3 m], [3 m, 3 m], [-3.3 m, 3 m]]}
        columns: [{at: [-2 m, -2 m]}, {at: [2 m, -2 m]}, {at: [2 m, 2 m]}, {at: [-2 m, 2 m]}]
)";
  std::string fixed_small = building_b("[20 m, 0 m]", "3 m", "{rectangle: [3 m, 3 m]}");
  return {
      {"bearing-outside", building_a(kColumns, bearings_one_out),
       "bearing B2 is outside the base slab's plan"},
      {"column-outside-base", replace(building_a(), "[3 m, 3 m]", "[3 m, 3.5 m]"),
       "column C3 (and the bearing under it) is outside the base slab's plan"},
      {"column-outside-floor", two_storeys, "column C1 of storey 2 is outside its slab's plan"},
      {"column-outside-fixed-base", building_a() + fixed_small,
       "column C1 of storey 1 is outside its slab's plan"},
      {"centre-of-mass-structure",
       replace(building_a(), "    storeys:", "    eccentricity: [3.5 m, 0 m]\n    storeys:"),
       "the centre of mass of the base of 'a'"},
      {"centre-of-mass-storey", storey_eccentric,
       "the centre of mass of floor 1 of 'a' at (0.000 m, 4.000 m)"},
      {"two-problems",
       replace(building_a(kColumns, bearings_one_out),
               "    storeys:", "    eccentricity: [0 m, -3.5 m]\n    storeys:"),
       "bearing B2 is outside"},
      {"overlap", building_a() + building_b("[5 m, 0 m]", "3 m"),
       "structures 'a' and 'b' overlap at rest"},
      {"overlap-and-levels", building_a() + building_b("[5 m, 0 m]", "3.5 m"),
       "has no floor of 'b' at its level"},
      {"levels", building_a() + building_b("[6.5 m, 0 m]", "3.5 m"),
       "floor 1 of 'a' at 3.000 m has no floor of 'b' at its level"},
      {"adjacent-columns", building_a() + corner_columns_adjacent("20 cm"),
       "columns of 'a' and 'b' stand in each other at rest"},
      {"column-in-slab", building_a() + building_b("[6.1 m, 0 m]", "3 m"),
       "stands in floor 1 of 'b'"},
      {"adjacent-gap", building_a() + adjacent_off,
       "the floors of 'b' and 'a' that meet are 0.500 m apart"},
      {"wall-in-slab",
       building_a(kColumns, "    walls: {sides: [east], gap: 20 cm}\n") +
           isolated_b("[6.5 m, 0 m]"),
       "the east wall of 'a' overlaps base of 'b' at rest"},
      {"wall-on-columns",
       building_a(kColumns, "    walls: {sides: [east], gap: 20 cm, thickness: 1.5 m}\n") +
           building_b("[6.5 m, 0 m]", "3 m"),
       "the east wall of 'a' stands on column C1 of 'b'"},
      {"2d-neighbour-lower-storeys",
       two_d("      floors: {count: 2, mass: 340 t, stiffness: 600 MN/m, height: 3.0 m}\n"),
       "floor 1 of 'a' at 3.200 m has no floor of 'n'"},
      {"2d-neighbour-taller", two_d(R"(      floors:
        - {mass: 340 t, stiffness: 600 MN/m, height: 3.2 m}
        - {mass: 340 t, stiffness: 600 MN/m, height: 3.5 m}
        - {mass: 340 t, stiffness: 600 MN/m, height: 3.2 m}
)"),
       "floor 2 of 'a' at 6.400 m has no floor of 'n'"},
  };
}

TEST(PreSiteAgreement, CheckRunAndPreFailEveryBrokenSiteWithTheSameErrors) {
  const auto cases = broken_sites();
  ASSERT_GE(cases.size(), 15u);
  for (const BrokenSite& c : cases) {
    const auto dir = scratch_dir("agree-" + c.name);
    const std::string model = write_model(dir, c.yaml);
    const auto check = isopound::test::run_isopound("check " + model);
    const auto run = isopound::test::run_isopound("run " + model + " -o " + (dir / "run").string());
    const auto pre = run_pre(model + " -o " + (dir / "pre").string() + " --no-plan");
    EXPECT_EQ(check.exit_code, 2) << c.name << "\n" << check.output;
    EXPECT_EQ(run.exit_code, 2) << c.name << "\n" << run.output;
    EXPECT_EQ(pre.exit_code, 2) << c.name << "\n" << pre.output;
    const auto from_check = lines_after(check.output, "isopound: error: ");
    ASSERT_FALSE(from_check.empty()) << c.name << "\n" << check.output;
    EXPECT_EQ(from_check, lines_after(run.output, "isopound: error: ")) << c.name;
    EXPECT_EQ(from_check, lines_after(pre.output, "error: ")) << c.name << "\n" << pre.output;
    bool found = false;
    for (const std::string& line : from_check) {
      found = found || line.find(c.what) != std::string::npos;
      EXPECT_EQ(line.rfind(model + ":", 0), 0u) << line;  // file:line:col first
    }
    EXPECT_TRUE(found) << c.name << ": no '" << c.what << "' in\n" << check.output;
    std::filesystem::remove_all(dir);
  }
}

// The two-problem model is reported whole by all three (the reader does not stop at the first).
TEST(PreSiteAgreement, EverySiteErrorIsReportedNotOnlyTheFirst) {
  const auto dir = scratch_dir("agree-all");
  const std::string model = write_model(dir, broken_sites()[6].yaml);
  const auto check = isopound::test::run_isopound("check " + model);
  const auto errors = lines_after(check.output, "isopound: error: ");
  ASSERT_EQ(errors.size(), 2u) << check.output;
  EXPECT_NE(errors[0].find("structures[0].bearings[1].at: bearing B2 is outside"),
            std::string::npos)
      << errors[0];
  EXPECT_NE(errors[1].find("structures[0].eccentricity: the centre of mass of the base of 'a'"),
            std::string::npos)
      << errors[1];
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace isopound::pre::test
