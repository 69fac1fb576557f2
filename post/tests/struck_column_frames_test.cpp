// Struck columns in the animation (issue 26, docs/floor-to-column.md "In the animation"): a column
// a slab strikes between its floors is drawn bent at its node, and the slab's contact with it is
// drawn where the solver had it. The checks compare the drawing with what the solver logged:
//  - 3D: at every row of contact_events.csv in contact, the overlap of the drawn slab and the
//    drawn column section (placed by the node's drift and twist) has the logged area; each
//    struck column is two line cells meeting at the node's height.
//  - 2D: the drawn contact is as deep as the logged penetration (times the scale), and the
//    struck column line has its node at the struck height.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include "post/animation.h"
#include "post/run_data.h"
#include "post_test_support.h"

namespace isopound::post {
namespace {

// A fixed-base building next to a lighter one with 3.6 m storeys 1 cm east: the building's
// floor 2 (6.4 m) strikes the neighbour's storey-2 columns 0.4 m below its roof. Fixed 0.1 ms
// steps, a row each: the log's rows on that grid are states the histories hold exactly.
constexpr const char* kSite3D = R"(structures:
  - name: building
    isolated: false
    grid: {bays_x: [5 m], bays_y: [5 m]}
    plan: {rectangle: [5.4 m, 5.4 m]}
    columns: {section: [40 cm, 40 cm], E: 30 GPa, nu: 0.2}
    storeys: {count: 2, height: 3.2 m, mass: 100 t}
    damping: {type: rayleigh, ratios: [5 %, 5 %], modes: [1, 3]}
    struck_columns: {M_y: 300 kN*m}
  - name: east
    isolated: false
    adjacent: {to: building, side: east, gap: 1 cm}
    grid: {bays_x: [5 m], bays_y: [5 m]}
    plan: {rectangle: [5.4 m, 5.4 m]}
    columns: {section: [40 cm, 40 cm], E: 30 GPa, nu: 0.2}
    storeys: {count: 2, height: 3.6 m, mass: 30 t}
    damping: {type: rayleigh, ratios: [5 %, 5 %], modes: [1, 3]}
    struck_columns: {M_y: 300 kN*m}
ground_motion:
  L: {pulse: {amplitude: 1.5 m/s, period: 0.8 s, t_peak: 0.5 s, duration: 2 s}}
  T: {pulse: {amplitude: 0.3 m/s, period: 0.8 s, t_peak: 0.5 s, duration: 2 s}}
  angle: 10 deg
analysis: {stepping: fixed, dt: 0.1 ms, t_end: 0.125 s}
output: {interval: 0.1 ms}
)";

double polygon_area(const FrameMesh& m, const MeshCell& c) {
  double a = 0.0;
  for (std::size_t k = 0; k < c.points.size(); ++k) {
    const auto& p = m.points[static_cast<std::size_t>(c.points[k])];
    const auto& q = m.points[static_cast<std::size_t>(c.points[(k + 1) % c.points.size()])];
    a += p[0] * q[1] - q[0] * p[1];
  }
  return 0.5 * std::abs(a);
}

// The run directory of `yaml` solved in a fresh scratch directory `name`; empty if the solver
// failed (the failure reported).
std::filesystem::path solve(const std::string& name, const char* yaml) {
  const auto dir = test::scratch_dir(name);
  std::ofstream(dir / "site.yaml") << yaml;
  const auto r =
      test::run_solver("run -q " + (dir / "site.yaml").string() + " -o " + (dir / "run").string());
  EXPECT_EQ(r.exit_code, 0) << r.output;
  return r.exit_code == 0 ? dir / "run" : std::filesystem::path();
}

const MeshArray& cell_array(const FrameMesh& m, const std::string& name) {
  for (const MeshArray& a : m.cell_data)
    if (a.name == name) return a;
  throw std::runtime_error("no cell array " + name);
}

TEST(PostStruckColumns, Frames3DDrawTheLoggedOverlapAndBendTheColumnAtItsNode) {
  const auto dir = solve("struck3d", kSite3D);
  ASSERT_FALSE(dir.empty());
  const RunData run = read_run(dir);
  for (const std::string& note : run.notes)
    EXPECT_EQ(note.find("not drawn"), std::string::npos) << note;
  int struck = 0;
  for (const PlanColumn& c : run.site.columns) {
    if (c.struck.label.empty()) continue;
    ++struck;
    EXPECT_GE(c.struck.drift_x, 0) << c.struck.label;
    EXPECT_GE(c.struck.striker, 0) << c.struck.label;
  }
  ASSERT_EQ(struck, 6);  // 2 + 2 facing columns of the neighbour, 2 of the building

  AnimationOptions options;  // scale 1: drawn = true positions
  int compared = 0;
  for (const auto& [label, rows] : run.contact_log.pairs) {
    const PlanColumn* column = run.site.struck(label);
    ASSERT_NE(column, nullptr) << label << ": every contact of this site is a struck column's";
    for (const ContactEvent& e : rows) {
      if (!e.in_contact || !(e.area > 0)) continue;
      const auto& time = run.time();
      const auto row = std::lower_bound(time.begin(), time.end(), e.time - 1e-9);
      if (row == time.end() || std::abs(*row - e.time) > 1e-9) continue;  // inside a step
      const FrameMesh m = animation_frame(run, e.time, options);
      const MeshArray& block = cell_array(m, "block");
      const MeshArray& force = cell_array(m, "normal_force");
      // The contact cell of this pair: its logged force, the overlap the drawing recomputes.
      bool found = false;
      for (std::size_t k = 0; k < m.cells.size(); ++k) {
        if (block.values[k] != static_cast<double>(Block::kContact) || m.cells[k].vtk_type != 7 ||
            force.values[k] != e.normal_force)
          continue;
        found = true;
        // The histories carry 9 significant digits: ~1e-11 m on these displacements, 4e-12 m2
        // over the 0.4 m face; an onset's overlap is ~1e-7 m deep (5e-8 m2). 100x that margin.
        EXPECT_NEAR(polygon_area(m, m.cells[k]), e.area, 1e-4 * e.area + 4e-10)
            << label << " at " << e.time;
      }
      EXPECT_TRUE(found) << label << " at " << e.time;
      ++compared;
      // The struck column: two lines meeting at its node's height.
      const double z_lo = column->lower >= 0
                              ? run.site.bodies[static_cast<std::size_t>(column->lower)].elevation
                              : 0.0;
      int at_node = 0;
      for (std::size_t k = 0; k < m.cells.size(); ++k)
        if (block.values[k] == static_cast<double>(Block::kColumn))
          for (const int p : m.cells[k].points) {
            const auto& x = m.points[static_cast<std::size_t>(p)];
            at_node += std::abs(x[2] - (z_lo + column->struck.node_height)) < 1e-12 &&
                       std::hypot(x[0] - column->p_W.x, x[1] - column->p_W.y) < 0.2;
          }
      EXPECT_EQ(at_node, 2) << label << " at " << e.time;
    }
  }
  EXPECT_GT(compared, 50) << "the run must strike the columns";
  std::filesystem::remove_all(dir.parent_path());
}

// The 2D tests' case (tests/floor_to_column_test.cpp): the building's roof strikes the stiffer
// neighbour's top-storey columns 1.6 m below its roof (its top storey 4.8 m).
constexpr const char* kSite2D = R"(building:
  name: main
  isolated: false
  floors: {count: 3, mass: 340 t, roof_mass: 250 t, stiffness: 300 MN/m, height: 3.2 m}
neighbours:
  - side: right
    gap: 5 mm
    impact: {law: kelvin_voigt, k: 2500 kN/mm, e: 0.7}
    building:
      name: nb
      isolated: false
      floors:
        - {mass: 340 t, stiffness: 600 MN/m, height: 3.2 m}
        - {mass: 340 t, stiffness: 600 MN/m, height: 3.2 m}
        - {mass: 250 t, stiffness: 600 MN/m, height: 4.8 m}
      columns: {count: 4, E: 30 GPa, I: 5.208e-3 m^4, M_y: 400 kN*m}
ground_motion:
  pulse: {amplitude: 1.0 m/s, period: 0.4 s, t_peak: 0.5 s, duration: 2 s}
analysis: {t_end: 1.2 s}
)";

TEST(PostStruckColumns, Frames2DDrawTheContactAsDeepAsItsPenetrationAndBendTheColumnLine) {
  const auto dir = solve("struck2d", kSite2D);
  ASSERT_FALSE(dir.empty());
  const RunData run = read_run(dir);
  const std::string label = "main~nb/floor 3 on nb story 3";
  const int force = run.find(label, "force"), penetration = run.find(label, "penetration");
  ASSERT_GE(force, 0);
  ASSERT_GE(penetration, 0);
  AnimationOptions options;
  options.scale = 20.0;
  int compared = 0;
  for (std::size_t row = 0; row < run.rows(); ++row) {
    const double t = run.time()[row], pen = run.column(penetration)[row];
    const FrameMesh m = animation_frame(run, t, options);
    const MeshArray& block = cell_array(m, "block");
    // The struck line (the neighbour's, facing left): two segments meeting at 6.4 + 3.2 m.
    int at_node = 0;
    for (std::size_t k = 0; k < m.cells.size(); ++k)
      if (block.values[k] == static_cast<double>(Block::kColumn))
        for (const int p : m.cells[k].points)
          at_node += std::abs(m.points[static_cast<std::size_t>(p)][2] - 9.6) < 1e-9;
    EXPECT_EQ(at_node, 2) << "t = " << t;
    if (!(run.column(force)[row] > 0.0 && pen > 0.0)) continue;
    // The roof's contact (the floors below pound slab to slab): as wide as the penetration
    // drawn at the displacement scale.
    int contacts = 0;
    for (std::size_t k = 0; k < m.cells.size(); ++k) {
      if (block.values[k] != static_cast<double>(Block::kContact)) continue;
      double x0 = 1e300, x1 = -1e300, z = 0.0;
      for (const int p : m.cells[k].points) {
        x0 = std::min(x0, m.points[static_cast<std::size_t>(p)][0]);
        x1 = std::max(x1, m.points[static_cast<std::size_t>(p)][0]);
        z += m.points[static_cast<std::size_t>(p)][2] /
             static_cast<double>(m.cells[k].points.size());
      }
      if (std::abs(z - 9.6) > 1e-9) continue;
      ++contacts;
      // To 1 nm of the model (at the drawing scale): the width comes from the histories' printed
      // displacements, the penetration is its own column.
      EXPECT_NEAR(x1 - x0, options.scale * pen, options.scale * (1e-9 + 1e-6 * pen)) << "t = " << t;
    }
    EXPECT_EQ(contacts, 1) << "t = " << t;
    ++compared;
  }
  EXPECT_GT(compared, 0) << "the roof must strike the columns";
  std::filesystem::remove_all(dir.parent_path());
}

}  // namespace
}  // namespace isopound::post
