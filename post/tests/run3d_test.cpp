// animate and plot on 3D runs: a short two-building run made by the solver with a synthetic
// contact-event log (contact episodes on and between frame times), every .vtu read back with VTK's
// XML reader: frame count and times from the .pvd, arrays, value ranges against summary.json,
// points moved by exactly scale x the displacement array, and contact blocks in exactly the frames
// where the log says the pair is in contact. A real short wall run does the same against the
// solver's own contact_events.csv; a hand-made run checks the recomputed overlap and force lines.
#include <gtest/gtest.h>
#include <vtkCell.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridReader.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <regex>
#include <sstream>

#include "post/animation3d.h"
#include "post/plot_run3d.h"
#include "post/run_data.h"
#include "post_test_support.h"
#include "solver/core/constants.h"

namespace isopound::post {
namespace {

// An isolated 2-storey building (eccentric mass) and a fixed-base neighbour 30 cm east of it,
// floors at equal levels; a 1 s pulse at 20 deg.
constexpr const char* kTwoBuildings = R"(structures:
  - name: building
    grid: {bays_x: [6 m, 6 m], bays_y: [6 m, 6 m]}
    columns: {section: [45 cm, 45 cm], E: 30 GPa, nu: 0.2}
    storeys: {count: 2, height: 3.2 m, mass: 300 t}
    base: {mass: 300 t}
    eccentricity: [0.6 m, 0 m]
    bearing: {model: bouc_wen, Tb: 2.0 s, QW: 5 %, uy: 1 cm, n: 2, A: 1, beta: 0.5, gamma: 0.5}
  - name: east
    position: [12.3 m, 0 m]
    isolated: false
    grid: {bays_x: [6 m], bays_y: [6 m, 6 m]}
    columns: {section: [35 cm, 35 cm], E: 30 GPa, nu: 0.2}
    storeys: {count: 2, height: 3.2 m, mass: 150 t}
ground_motion:
  L: {pulse: {amplitude: 0.8 m/s, period: 1 s}}
  T: {pulse: {amplitude: 0.4 m/s, period: 1 s}}
  angle: 20 deg
  extra_time: 2 s
output: {interval: 0.01 s}
)";

constexpr const char* kLogHeader =
    "time [s],pair,event,in_contact,slipping,area [m2],indentation [m],normal_force [N],"
    "tangential_force [N],x_C [m],y_C [m],n_x [-],n_y [-]\n";

// Episodes of the synthetic log (pair, onset, separation; rows every 1 ms between): one across
// several frames, one starting exactly on a frame time, one between two frames (no frame shows
// it), and a pair with a body the model does not have (never drawn).
struct Episode {
  std::string pair;
  double onset, separation;
};
const std::vector<Episode> kEpisodes{{"building/floor 1|east/floor 1", 1.0505, 1.3495},
                                     {"building/floor 1|east/floor 1", 2.5, 2.5005},
                                     {"building/floor 2|east/floor 2", 3.01, 3.05},
                                     {"building/floor 2|east/floor 2", 3.3, 3.62},
                                     {"building/base|wall east", 1.0, 2.0}};

std::string synthetic_log() {
  std::ostringstream out;
  out.precision(17);
  out << kLogHeader;
  for (const Episode& e : kEpisodes) {
    const int steps = static_cast<int>(std::round((e.separation - e.onset) / 1e-3));
    for (int k = 0; k <= steps; ++k) {
      const double t = k == steps ? e.separation : e.onset + k * 1e-3;
      const bool in = k < steps;
      out << t << "," << e.pair << ","
          << (k == 0 ? "onset"
              : in   ? "contact"
                     : "separation")
          << "," << in << ",0," << (in ? 0.02 : 0.0) << "," << (in ? 0.001 : 0.0) << ","
          << (in ? 4e5 + 1e3 * k : 0.0) << "," << (in ? -1e5 : 0.0) << ",6," << (in ? 1.5 : 0.0)
          << ",1,0\n";
    }
  }
  return out.str();
}

// The log's rule, computed here independently: in contact at t iff the pair's last row with
// time <= t has in_contact 1.
std::map<std::string, bool> in_contact_at(double t, const std::string& log = synthetic_log()) {
  std::map<std::string, std::pair<double, bool>> last;
  std::istringstream in(log);
  std::string line;
  std::getline(in, line);
  while (std::getline(in, line)) {
    std::vector<std::string> c;
    std::stringstream ss(line);
    for (std::string cell; std::getline(ss, cell, ',');) c.push_back(cell);
    const double time = std::stod(c[0]);
    if (time <= t && (!last.count(c[1]) || time >= last[c[1]].first))
      last[c[1]] = {time, c[3] == "1"};
  }
  std::map<std::string, bool> out;
  for (const auto& [pair, state] : last) out[pair] = state.second;
  return out;
}

double peak_value(const nlohmann::json& j) {
  return j.at("value").get<double>();
}

TEST(PostRun3D, AnimateFramesReadBackWithRangesAndContactBlocksExactlyWhileInContactAndPlot) {
  const auto dir = test::scratch_dir("anim3d");
  std::ofstream(dir / "two.yaml") << kTwoBuildings;
  auto r = test::run_solver("run " + (dir / "two.yaml").string() + " -o " + (dir / "run").string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  std::ofstream(dir / "run" / "contact_events.csv") << synthetic_log();
  const double fps = 10.0, t_end = 6.0, scale = 3.0;
  r = test::run_post("animate " + (dir / "run").string() + " --uniform --model " +
                     (dir / "two.yaml").string() + " --fps 10 --end 6 --scale 3 -o " +
                     (dir / "anim").string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("'building/base|wall east'"), std::string::npos) << r.output;

  // Peaks of summary.json (over every step): displacement and absolute acceleration resultants
  // at the corners (the largest of a rigid slab: both are affine in the plan point), column
  // drift ratios, bearing forces.
  std::ifstream sj(dir / "run" / "summary.json");
  const auto summary = nlohmann::json::parse(sj);
  double peak_u = 0, peak_a = 0, peak_drift = 0, peak_bearing = 0;
  for (const auto& b : summary["buildings_3d"]) {
    for (const auto& level : b["levels"])
      for (const auto& corner : level["corners"]) {
        peak_u = std::max(peak_u, peak_value(corner["displacement"]["resultant"]));
        peak_a = std::max(peak_a, peak_value(corner["absolute_acceleration"]["resultant"]));
      }
    for (const auto& storey : b["storeys"])
      for (const auto& column : storey["columns"])
        peak_drift = std::max(peak_drift, peak_value(column["drift_ratio"]));
    for (const auto& bearing : b["bearings"])
      peak_bearing = std::max(peak_bearing, peak_value(bearing["force"]));
  }
  ASSERT_GT(peak_u, 0.0);
  ASSERT_GT(peak_bearing, 0.0);

  // The .pvd: one DataSet per frame at k / fps.
  const auto frames = test::read_pvd(dir / "anim" / "animation.pvd");
  ASSERT_EQ(frames.size(), static_cast<std::size_t>(std::floor(t_end * fps + 1e-9)) + 1);

  const RunData run = read_run(dir / "run", (dir / "two.yaml").string());
  double max_u = 0, max_a = 0, max_drift = 0, max_bearing = 0;
  int contact_frames = 0;
  std::vector<std::array<double, 3>> rest;  // point - scale * displacement, from frame 0
  for (std::size_t k = 0; k < frames.size(); ++k) {
    const double t = frames[k].first;
    EXPECT_NEAR(t, k / fps, 1e-12);
    vtkNew<vtkXMLUnstructuredGridReader> reader;
    reader->SetFileName((dir / "anim" / frames[k].second).string().c_str());
    reader->Update();
    vtkUnstructuredGrid* g = reader->GetOutput();
    ASSERT_GT(g->GetNumberOfCells(), 0) << frames[k].second;
    EXPECT_EQ(g->GetPoints()->GetDataType(), VTK_DOUBLE);
    vtkDataArray* disp = g->GetPointData()->GetArray("displacement");
    vtkDataArray* acc = g->GetPointData()->GetArray("absolute_acceleration");
    vtkDataArray* block = g->GetCellData()->GetArray("block");
    vtkDataArray* drift = g->GetCellData()->GetArray("drift_ratio");
    vtkDataArray* bearing = g->GetCellData()->GetArray("bearing_force");
    vtkDataArray* force = g->GetCellData()->GetArray("contact_force");
    vtkDataArray* fn = g->GetCellData()->GetArray("normal_force");
    ASSERT_TRUE(disp && acc && block && drift && bearing && force && fn &&
                g->GetCellData()->GetArray("tangential_force") &&
                g->GetCellData()->GetArray("area") && g->GetCellData()->GetArray("penetration") &&
                g->GetCellData()->GetArray("structure"))
        << frames[k].second;
    for (vtkDataArray* a : {disp, acc, block, drift, bearing, force, fn})
      EXPECT_EQ(a->GetDataType(), VTK_DOUBLE);
    // Points move by exactly scale x their displacement: point - scale * d is the same in every
    // frame (the rest position), and the displacement of a slab point is (u - y theta, v + x theta)
    // of its level's DOFs at this frame's history row.
    for (vtkIdType p = 0; p < g->GetNumberOfPoints(); ++p) {
      double x[3];
      g->GetPoint(p, x);
      const std::array<double, 3> r0{x[0] - scale * disp->GetComponent(p, 0),
                                     x[1] - scale * disp->GetComponent(p, 1), x[2]};
      if (k == 0) rest.push_back(r0);
      if (k > 0 && static_cast<std::size_t>(p) < rest.size() && p < 8) {
        for (int i = 0; i < 3; ++i) EXPECT_NEAR(r0[i], rest[p][i], 1e-9) << "point " << p;
      }
      max_u = std::max(max_u, std::hypot(disp->GetComponent(p, 0), disp->GetComponent(p, 1)));
      max_a = std::max(max_a, std::hypot(acc->GetComponent(p, 0), acc->GetComponent(p, 1)));
    }
    // Point 0: the base slab's first vertex (bottom) — check its displacement from the columns.
    {
      std::size_t row = 0;
      while (row < run.rows() && std::abs(run.time()[row] - t) > 1e-9) ++row;
      ASSERT_LT(row, run.rows());
      const auto col = [&](const std::string& name) {
        const int c = run.find("building/base " + name, "u");
        EXPECT_GE(c, 0) << name;
        return run.values[c][row];
      };
      const double u = col("(x)"), v = col("(y)"), th = col("(theta)");
      const double px = rest[0][0], py = rest[0][1];
      EXPECT_NEAR(disp->GetComponent(0, 0), u - py * th, 1e-12);
      EXPECT_NEAR(disp->GetComponent(0, 1), v + px * th, 1e-12);
    }
    std::map<int, int> count;
    for (vtkIdType c = 0; c < block->GetNumberOfTuples(); ++c) {
      const int b = static_cast<int>(block->GetComponent(c, 0));
      ++count[b];
      if (b == 1) max_drift = std::max(max_drift, drift->GetComponent(c, 0));
      if (b == 2) max_bearing = std::max(max_bearing, bearing->GetComponent(c, 0));
      if (b == 4) {
        EXPECT_GE(fn->GetComponent(c, 0), 4e5);
        EXPECT_NEAR(force->GetComponent(c, 0), fn->GetComponent(c, 0), 1e-6);  // n = +x
        EXPECT_NEAR(force->GetComponent(c, 1), 1e5,
                    1e-6);  // on B: F_N n - F_T t, F_T = -1e5, t = +y
      }
    }
    // Contact blocks: one overlap/centroid cell and two force lines per pair in contact.
    int expected = 0;
    for (const auto& [pair, in] : in_contact_at(t))
      if (in && pair.find("wall") == std::string::npos) ++expected;
    EXPECT_EQ(count[4], expected) << "t = " << t;
    EXPECT_EQ(count[5], expected) << "t = " << t;
    EXPECT_EQ(count[6], expected) << "t = " << t;
    contact_frames += expected > 0;
    EXPECT_EQ(count[0], 5 * (2 + 4)) << "slabs: 5 quadrilaterals x (top, bottom, 4 sides)";
    EXPECT_EQ(count[1], 9 * 2 + 6 * 2) << "columns";
    EXPECT_EQ(count[2], 9) << "bearings";
  }
  // Frames 1.1..1.3 (3), 2.5 (1) and 3.3..3.6 (4): the 3.01-3.05 episode falls between frames.
  EXPECT_EQ(contact_frames, 8);
  EXPECT_LE(max_u, peak_u * (1 + 1e-9));
  EXPECT_GT(max_u, 0.95 * peak_u);  // frames every 0.1 s on a ~2 s isolated sway
  EXPECT_LE(max_a, peak_a * (1 + 1e-9));
  EXPECT_LE(max_drift, peak_drift * (1 + 1e-6));  // differences of 9-digit values (CSV)
  EXPECT_GT(max_drift, 0.5 * peak_drift);  // drift peaks ride on short pulses: a looser bound
  EXPECT_LE(max_bearing, peak_bearing * (1 + 1e-9));
  EXPECT_GT(max_bearing, 0.8 * peak_bearing);

  // plot: three figures of their sizes, not blank; the worst corner drift of each storey (the
  // plan corners are the corner columns here) against the solver's corner-column peaks.
  r = test::run_post("plot " + (dir / "run").string() + " --model " + (dir / "two.yaml").string() +
                     " -o " + (dir / "plot").string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const test::Image th = test::read_png((dir / "plot" / "time_histories.png").string());
  EXPECT_EQ(th.width, 1000);
  // Base, drifts, the base slab's acceleration, the floors' and ground's, F_N, F_T.
  EXPECT_EQ(th.height, kHistoryPanelHeight * 6 + 40);
  EXPECT_GT(th.variance(), 100.0);
  const test::Image hy = test::read_png((dir / "plot" / "hysteresis.png").string());
  EXPECT_EQ(hy.width, 1500);
  EXPECT_GT(hy.variance(), 100.0);
  const test::Image ct = test::read_png((dir / "plot" / "contacts.png").string());
  EXPECT_EQ(ct.height, 360 * 3 + 40);  // three pairs in the log, one row each
  EXPECT_GT(ct.variance(), 50.0);
  const test::Image tr = test::read_png((dir / "plot" / "trajectory.png").string());
  EXPECT_EQ(tr.width, 1400);
  EXPECT_GT(tr.variance(), 50.0);
  // The time histories mark summary.json's peak of the base slab's centre-of-mass acceleration
  // (over every step) with its value and time in the legend and a marker at that place.
  {
    const std::vector<NamedFigure> figures = run_figures3d(run);
    ASSERT_EQ(figures.front().frames.size(), 6u);
    const auto& peak = summary["buildings_3d"][0]["levels"][0]["centre_of_mass"]
                              ["absolute_acceleration"]["resultant"];
    const double a = peak_value(peak) / kGravity, at = peak.at("time_s").get<double>();
    char want[96];
    std::snprintf(want, sizeof want, "building/base — peak %.4g g at %.3f s", a, at);
    bool legend = false;
    for (const auto& t : figures.front().figure.texts) legend = legend || t.text == want;
    EXPECT_TRUE(legend) << want;
    const auto p = figures.front().frames[2].to_pixel(at, a);
    bool marker = false;
    for (const auto& m : figures.front().figure.markers) {
      double x = 0, y = 0;
      for (const auto& q : m.points) x += q.x / m.points.size(), y += q.y / m.points.size();
      marker = marker || std::hypot(x - p.x, y - p.y) < 1e-9;
    }
    EXPECT_TRUE(marker);
  }
  const std::vector<CornerDrift> drifts = corner_drifts(run);
  ASSERT_EQ(drifts.size(), 4u);  // 2 storeys of each building
  std::size_t i = 0;
  for (const auto& b : summary["buildings_3d"])
    for (const auto& storey : b["storeys"]) {
      double corner_peak = 0.0;
      for (const auto& column : storey["columns"]) {
        const std::string label = column["label"];
        // Corner columns of the grids: A1, C1, A3, C3 (building), A1, B1, A3, B3 (east).
        if ((label[0] == 'A' || label[0] == (i < 2 ? 'C' : 'B')) &&
            (label[1] == '1' || label[1] == '3'))
          corner_peak = std::max(corner_peak, peak_value(column["drift_ratio"]));
      }
      // histories.csv holds 9 significant digits; a drift is a difference of two of them.
      EXPECT_LE(drifts[i].peak, corner_peak * (1 + 1e-6)) << drifts[i].label;
      EXPECT_GT(drifts[i].peak, 0.9 * corner_peak) << drifts[i].label;  // rows every 10 ms
      ++i;
    }

  // Without its model file a 3D run cannot be drawn: one clear error naming the way out.
  std::filesystem::rename(dir / "two.yaml", dir / "moved.yaml");
  r = test::run_post("animate " + (dir / "run").string() + " -o " + (dir / "anim2").string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.output.find("give it with --model FILE"), std::string::npos) << r.output;
  std::filesystem::remove_all(dir);
}

// A hand-made 3D run: slab A (4 x 4 m at the origin, DOFs "a/floor 1") and a fixed slab B
// overlapping A's east edge by 0.1 m at rest; A moves east 0.05 m at t = 1. The overlap drawn is
// the recomputed A ∩ B (0.15 x 4 m at t = 1), the force lines start at the logged centroid.
TEST(PostRun3D, ContactBlockIsTheRecomputedOverlapWithForceLinesAtTheCentroid) {
  RunData run;
  run.three_d = true;
  run.columns = {"time [s]", "a/floor 1 (x) u [m]", "a/floor 1 (y) u [m]",
                 "a/floor 1 (theta) u [rad]"};
  run.values = {{0.0, 1.0}, {0.0, 0.05}, {0.0, 0.0}, {0.0, 0.0}};
  Level l;
  l.label = "a/floor 1";
  l.u = 1, l.u_y = 2, l.theta = 3, l.body = 0;
  run.structures.push_back({"a", {l}});
  PlanBody a;
  a.structure = "a", a.level = "floor 1", a.role = "slab", a.elevation = 3.0;
  a.plan_W = {{-2, -2}, {2, -2}, {2, 2}, {-2, 2}};
  a.dof_label = "a/floor 1";
  PlanBody b = a;
  b.structure = "b", b.dof_label = "";
  b.plan_W = {{1.9, -3}, {5, -3}, {5, 3}, {1.9, 3}};
  run.site.bodies = {a, b};
  ContactEvent on;
  on.time = 0.5, on.event = "onset", on.in_contact = true, on.normal_force = 2e6;
  on.tangential_force = 5e5, on.x_C = 2.0, on.y_C = 0.0, on.n_x = 1.0, on.area = 0.6;
  run.contact_log.pairs["a/floor 1|b/floor 1"] = {on};
  AnimationOptions o;
  o.scale = 1.0;
  o.force_length = 4.0;
  const FrameMesh m = animation_frame3d(run, 1.0, o);
  const MeshArray& block = m.cell_data[0];
  ASSERT_EQ(block.name, "block");
  int overlap = -1, normal = -1, tangential = -1;
  for (std::size_t c = 0; c < m.cells.size(); ++c) {
    if (block.values[c] == 4.0) overlap = static_cast<int>(c);
    if (block.values[c] == 5.0) normal = static_cast<int>(c);
    if (block.values[c] == 6.0) tangential = static_cast<int>(c);
  }
  ASSERT_GE(overlap, 0);
  ASSERT_EQ(m.cells[overlap].vtk_type, 7);
  // Shoelace area of the drawn polygon: A spans x in [-1.95, 2.05], B starts at 1.9: 0.15 x 4.
  double area2 = 0.0;
  const auto& pts = m.cells[overlap].points;
  for (std::size_t k = 0; k < pts.size(); ++k) {
    const auto& p = m.points[pts[k]];
    const auto& q = m.points[pts[(k + 1) % pts.size()]];
    area2 += p[0] * q[1] - q[0] * p[1];
    EXPECT_NEAR(p[2], 3.02, 1e-12);  // on A's top
  }
  EXPECT_NEAR(0.5 * area2, 0.15 * 4.0, 1e-12);
  // Force lines: from the centroid (2, 0) along n (+x) by 4 m (the largest force) and along
  // -t = -y by 4 x 0.5/2 = 1 m (the force on B is F_N n - F_T t).
  ASSERT_GE(normal, 0);
  ASSERT_GE(tangential, 0);
  const auto& n0 = m.points[m.cells[normal].points[0]];
  const auto& n1 = m.points[m.cells[normal].points[1]];
  EXPECT_NEAR(n0[0], 2.0, 1e-12);
  EXPECT_NEAR(n1[0] - n0[0], 4.0, 1e-12);
  EXPECT_NEAR(n1[1] - n0[1], 0.0, 1e-12);
  const auto& t0 = m.points[m.cells[tangential].points[0]];
  const auto& t1 = m.points[m.cells[tangential].points[1]];
  EXPECT_NEAR(t1[1] - t0[1], -1.0, 1e-12);
  EXPECT_NEAR(t1[0] - t0[0], 0.0, 1e-12);
  // After separation: no contact cells.
  ContactEvent off = on;
  off.time = 1.5, off.event = "separation", off.in_contact = false;
  run.contact_log.pairs["a/floor 1|b/floor 1"].push_back(off);
  const FrameMesh later = animation_frame3d(run, 1.5, o);
  for (double b : later.cell_data[0].values) EXPECT_LT(b, 4.0);
}

// A real short pounding run: the isolated building of the first test inside moat walls on all
// four sides at 4 cm, the pulse from 3 s, stopped at 4.2 s (t_end) after about a dozen impacts
// per wall. Frames every 10 ms (on history rows) from 3.4 s: contact blocks exactly where the
// solver's own contact_events.csv says in contact; the walls are drawn; logged forces and areas
// within the summary's contacts_3d peaks.
TEST(PostRun3D, RealWallRunHasContactBlocksExactlyWhereItsEventLogSaysInContact) {
  const auto dir = test::scratch_dir("walls3d");
  std::string yaml = kTwoBuildings;
  yaml = yaml.substr(0, yaml.find("  - name: east"));
  yaml += "    walls: {sides: all, gap: 4 cm}\n";
  yaml += std::string(kTwoBuildings).substr(std::string(kTwoBuildings).find("ground_motion:"));
  yaml.replace(yaml.find("  extra_time: 2 s\n"), 17, "");
  yaml.replace(yaml.find("output: {interval: 0.01 s}"), 26,
               "analysis: {t_end: 4.2 s}\noutput: {interval: 0.005 s}");
  std::ofstream(dir / "walls.yaml") << yaml;
  auto r =
      test::run_solver("run " + (dir / "walls.yaml").string() + " -o " + (dir / "run").string());
  ASSERT_EQ(r.exit_code, 0) << r.output << yaml;
  r = test::run_post("animate " + (dir / "run").string() +
                     " --uniform --start 3.4 --end 4.2 --fps 100 -o " + (dir / "anim").string());
  ASSERT_EQ(r.exit_code, 0) << r.output;

  std::ifstream log_file(dir / "run" / "contact_events.csv");
  std::stringstream log;
  log << log_file.rdbuf();
  std::ifstream sj(dir / "run" / "summary.json");
  const auto summary = nlohmann::json::parse(sj);
  ASSERT_EQ(summary["contacts_3d"].size(), 4u);
  double peak_fn = 0.0, peak_area = 0.0;
  int impacts = 0;
  for (const auto& c : summary["contacts_3d"]) {
    peak_fn = std::max(peak_fn, peak_value(c["normal_force"]));
    peak_area = std::max(peak_area, peak_value(c["area"]));
    impacts += c["impacts"].get<int>();
  }
  ASSERT_GT(impacts, 8) << "the run must pound";

  int frames_in_contact = 0, polygons = 0;
  double max_fn = 0.0, max_area = 0.0;
  for (int k = 0; k <= 80; ++k) {
    const double t = 3.4 + k / 100.0;
    char name[32];
    std::snprintf(name, sizeof name, "frame_%06d.vtu", k);
    vtkNew<vtkXMLUnstructuredGridReader> reader;
    reader->SetFileName((dir / "anim" / name).string().c_str());
    reader->Update();
    vtkUnstructuredGrid* g = reader->GetOutput();
    vtkDataArray* block = g->GetCellData()->GetArray("block");
    vtkDataArray* fn = g->GetCellData()->GetArray("normal_force");
    vtkDataArray* area = g->GetCellData()->GetArray("area");
    ASSERT_TRUE(block && fn && area) << name;
    std::map<int, int> count;
    for (vtkIdType c = 0; c < block->GetNumberOfTuples(); ++c) {
      const int b = static_cast<int>(block->GetComponent(c, 0));
      ++count[b];
      if (b == 4) {
        polygons += g->GetCellType(c) == VTK_POLYGON;
        max_fn = std::max(max_fn, fn->GetComponent(c, 0));
        max_area = std::max(max_area, area->GetComponent(c, 0));
      }
    }
    int expected = 0;
    for (const auto& [pair, in] : in_contact_at(t, log.str())) expected += in;
    EXPECT_EQ(count[4], expected) << "t = " << t;
    EXPECT_EQ(count[5], expected) << "t = " << t;
    EXPECT_EQ(count[6], expected) << "t = " << t;
    EXPECT_EQ(count[3], 4 * 6) << "four walls, each 6 faces";
    frames_in_contact += expected > 0;
  }
  EXPECT_GT(frames_in_contact, 3);
  EXPECT_GT(polygons, 0) << "some recomputed overlaps are polygons";
  // The log holds 9 significant digits of what the summary's peak holds in full.
  EXPECT_LE(max_fn, peak_fn * (1 + 1e-8));
  EXPECT_LE(max_area, peak_area * (1 + 1e-8));
  EXPECT_GT(max_fn, 0.0);
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace isopound::post
