// End-to-end tests of `isopound geometry overlap`: the example file's numbers (derived by hand
// below), --exact agreeing with the fast path, and located errors for invalid polygons.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "tests/test_support.h"

namespace isopound {
namespace {

namespace fs = std::filesystem;

const std::string kExample =
    (test::source_dir() / "configs/geometry-overlap-example.yaml").string();

nlohmann::json overlaps(const std::string& args) {
  const test::CommandResult r = test::run_isopound("geometry overlap " + args);
  EXPECT_EQ(r.exit_code, 0) << r.output;
  return nlohmann::json::parse(r.output);
}

TEST(GeometryCli, ExampleFileGivesTheHandValues) {
  const nlohmann::json out = overlaps(kExample);
  ASSERT_EQ(out.size(), 3u);
  // Pair 0: b's face at x = 19.95 m inside a's face x = 20 m over y = 2..12 m: area 10 × 0.05,
  // centroid (19.975, 7), normal +x (from a into b), δ_N = A/|P1P2| = 0.05 (quadrilateral).
  const nlohmann::json& face = out[0];
  EXPECT_EQ(face["case"], "two_crossings");
  EXPECT_EQ(face["vertices"], 4);
  // 19.95 is not a binary fraction: the input itself is off by ~7e-16 m.
  EXPECT_NEAR(face["area_m2"].get<double>(), 0.5, 1e-13);
  EXPECT_NEAR(face["centroid_m"][0].get<double>(), 19.975, 1e-13);
  EXPECT_NEAR(face["centroid_m"][1].get<double>(), 7.0, 1e-13);
  EXPECT_EQ(face["normal"][0], 1.0);
  EXPECT_EQ(face["normal"][1], 0.0);
  EXPECT_NEAR(face["indentation_m"].get<double>(), 0.05, 1e-13);
  EXPECT_NEAR(face["separation_m"].get<double>(), -0.05, 1e-13);
  EXPECT_EQ(face["crossings_m"][0][1], 2.0);  // a's face runs upwards: enters b at y = 2 m
  EXPECT_EQ(face["crossings_m"][1][1], 12.0);
  // Pair 1: b's corner 4 cm into a's face x = 20 m, its edges at 60° and 30° to the face:
  // a triangle of height δ = 0.04 m and area δ²/sin(2·60°); the file's coordinates are rounded
  // to 0.1 mm, hence the 1e-3 relative tolerance on the area (δ_N is the exact height).
  const nlohmann::json& corner = out[1];
  EXPECT_EQ(corner["case"], "two_crossings");
  EXPECT_EQ(corner["vertices"], 3);
  EXPECT_NEAR(corner["area_m2"].get<double>(), 0.0016 / std::sin(2 * M_PI / 3), 0.0016e-3);
  EXPECT_NEAR(corner["indentation_m"].get<double>(), 0.04, 1e-13);
  EXPECT_NEAR(corner["normal"][0].get<double>(), 1.0, 1e-15);
  // Pair 2: 10 cm apart; nothing but the separation is defined.
  const nlohmann::json& apart = out[2];
  EXPECT_EQ(apart["case"], "separated");
  EXPECT_EQ(apart["area_m2"], 0.0);
  EXPECT_TRUE(apart["normal"].is_null());
  EXPECT_NEAR(apart["separation_m"].get<double>(), 0.1, 1e-13);
}

TEST(GeometryCli, ExactPathAgrees) {
  const nlohmann::json fast = overlaps(kExample), exact = overlaps("--exact " + kExample);
  ASSERT_EQ(fast.size(), exact.size());
  for (std::size_t k = 0; k < fast.size(); ++k) {
    EXPECT_EQ(fast[k]["case"], exact[k]["case"]);
    EXPECT_EQ(fast[k]["vertices"], exact[k]["vertices"]);
    EXPECT_NEAR(fast[k]["area_m2"].get<double>(), exact[k]["area_m2"].get<double>(), 1e-15);
  }
}

TEST(GeometryCli, InvalidPolygonsNameFileLineKeyAndVertex) {
  const fs::path dir =
      fs::temp_directory_path() / ("isopound-geometry-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  struct Case {
    std::string yaml, expected;
  };
  const Case cases[] = {
      {"pairs:\n  - a: [[0, 0], [1, 0], [1, 1]]\n    b: [[0, 0], [1, 0], [1, 1], [1, 0], [0, 1]]\n",
       ":3:33: pairs[0].b[3]: vertex 3 (1, 0): repeats vertex 1"},
      {"pairs:\n  - a: [[0, 0], [2, 0], [2, 2], [1, -0.5], [0, 2]]\n    b: [[0, 0], [1, 0], [1, "
       "1]]\n",
       "pairs[0].a: the outline touches or crosses itself (edge 0-1 meets edge 2-3)"},
      {"pairs:\n  - a: [[0, 0], [1, 0], [1, 1]]\n    b: [[0, 0], [1, 0]]\n",
       ":3:5: pairs[0].b: a polygon needs at least 3 vertices, got 2"},
      {"pairs:\n  - a: [[0, 0], [1, 0], [2, 0]]\n    b: [[0, 0], [1, 0], [1, 1]]\n",
       "pairs[0].a: zero area"},
      {"pairs:\n  - a: [[0, 0], [1, 0], [1, 1]]\n  - a: [[0, 0], [1 m, 0], [1 m, 1 s]]\n"
       "    b: [[0, 0], [1, 0], [1, 1]]\n",
       ":2:5: pairs[0].b: missing required key 'b'"},
      {"pairs:\n  - a: [[0, 0], [1 m, 0], [1 m, 1 s]]\n    b: [[0, 0], [1, 0], [1, 1]]\n",
       "pairs[0].a[2][1]: unit 's' is a time (s), expected a length (m)"},
      {"pairs:\n  - a: [[0, 0], [1, 0], [1, .nan]]\n    b: [[0, 0], [1, 0], [1, 1]]\n",
       "pairs[0].a[2]"},
      {"pairs:\n  - a: [[0, 0], [1, 0], [1, 1]]\n    c: [[0, 0], [1, 0], [1, 1]]\n",
       ":3:5: pairs[0].c: unknown key 'c'"},
      {"pairs: []\n", "pairs: no pairs"},
  };
  int index = 0;
  for (const Case& c : cases) {
    const fs::path file = dir / ("bad" + std::to_string(index++) + ".yaml");
    std::ofstream(file) << c.yaml;
    const test::CommandResult r = test::run_isopound("geometry overlap " + file.string());
    EXPECT_EQ(r.exit_code, 2) << c.yaml << r.output;
    EXPECT_NE(r.output.find(file.string()), std::string::npos) << r.output;
    EXPECT_NE(r.output.find(c.expected), std::string::npos)
        << "expected: " << c.expected << "\ngot: " << r.output;
  }
  fs::remove_all(dir);
}

}  // namespace
}  // namespace isopound
