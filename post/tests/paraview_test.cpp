// The impact-aware animation and its view.py: frame times against the contact episodes counted
// here from contact_events.csv (independently of post/frame_timeline.cpp), the budget, the
// removal of an earlier animation's frames, and view.py in the real client (pvpython under a
// private Xvfb): it loads, its time steps are the .pvd's, a frame inside an impact has contact
// cells and the screenshot shows the contact colour where the contact is, and a frame outside
// every impact shows neither; view.py's displacement scale (the largest displacement drawn 2 to
// 5 % of the site), the walls' gap offsets that keep bodies touching at that scale, and its
// colour bar in MN; view.py in the GUI itself, and the GUI's packages (its toolbar icons need
// Qt's SVG support).
//
// pvpython: the tests that need it skip when it is not on PATH, unless ISOPOUND_REQUIRE_PARAVIEW
// is set (.ci/run sets it; .ci/setup installs ParaView).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <regex>
#include <sstream>

#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridReader.h>

#include "post/contact_log.h"
#include "post/headless.h"
#include "post/paraview_run.h"
#include "post_test_support.h"
#include "solver/io/child_process.h"

namespace fs = std::filesystem;
namespace isopound::post {
namespace {

// The thesis building in 3D with moat walls 15 cm away on all four sides under the built-in
// pulse pair: 30-odd impacts in 10 s, under two seconds to run.
constexpr const char* kWallRun = R"(structures:
  - name: building
    grid: {bays_x: [5.5 m, 5.5 m, 5.5 m], bays_y: [5.5 m, 5.5 m, 5.5 m]}
    columns: {section: [45 cm, 45 cm], E: 30 GPa, nu: 0.2}
    storeys: {count: 3, height: 3.2 m, mass: 340 t, roof_mass: 250 t}
    base: {mass: 340 t}
    bearing: {model: bouc_wen, Tb: 2.0 s, QW: 5 %, uy: 1 cm, n: 2, A: 1, beta: 0.5, gamma: 0.5}
    damping: {type: rayleigh, ratios: [5 %, 2 %], modes: [1, 4], bearing_stiffness: post_yield}
    walls: {sides: all, gap: 15 cm, thickness: 1 m, height: 1 m, extension: 1 m, mass_per_length: 5 t/m}
contact: {k_normal: 2.58e10 N/m2, k_tangential: 5.74e9 N/m, mu_static: 0.8, mu_kinetic: 0.6, restitution: 0.65}
ground_motion:
  L: {pulse: {amplitude: 1.0 m/s, period: 2 s}}
  T: {pulse: {amplitude: 0.5 m/s, period: 2 s}}
  angle: 30 deg
  extra_time: 0 s
analysis: {t_end: 8 s}
output: {interval: 0.002 s}
)";

struct Episode {
  double start = 0, end = 0, peak_force = 0, peak_time = 0;
};

// Episodes of contact_events.csv read here: a run of in_contact rows of one pair, to the row
// after it (the separation) or the last row.
std::vector<Episode> log_episodes(const fs::path& csv) {
  std::ifstream in(csv);
  std::string line;
  std::getline(in, line);
  std::map<std::string, std::vector<std::vector<std::string>>> rows;
  while (std::getline(in, line)) {
    const std::vector<std::string> cells = split_csv(line);
    rows[cells.at(1)].push_back(cells);
  }
  std::vector<Episode> out;
  for (const auto& [pair, r] : rows) {
    for (std::size_t i = 0; i < r.size();) {
      if (r[i][3] != "1") {
        ++i;
        continue;
      }
      Episode e;
      e.start = std::stod(r[i][0]);
      std::size_t j = i;
      for (; j < r.size() && r[j][3] == "1"; ++j)
        if (std::stod(r[j][7]) > e.peak_force) {
          e.peak_force = std::stod(r[j][7]);
          e.peak_time = std::stod(r[j][0]);
        }
      e.end = std::stod(r[std::min(j, r.size() - 1)][0]);
      out.push_back(e);
      i = j;
    }
  }
  return out;
}

std::vector<double> pvd_times(const fs::path& pvd) {
  std::vector<double> times;
  for (const auto& [t, file] : test::read_pvd(pvd)) times.push_back(t);
  return times;
}

// A frame's field data value (TimeValue, slow_motion).
double field_value(const fs::path& vtu, const char* name) {
  vtkNew<vtkXMLUnstructuredGridReader> reader;
  reader->SetFileName(vtu.string().c_str());
  reader->Update();
  vtkDataArray* a = reader->GetOutput()->GetFieldData()->GetArray(name);
  return a ? a->GetTuple1(0) : -1.0;
}

std::size_t frames_within(const std::vector<double>& times, double a, double b) {
  return static_cast<std::size_t>(std::count_if(
      times.begin(), times.end(), [&](double t) { return t >= a - 1e-12 && t <= b + 1e-12; }));
}

// The pulse run with walls, once per test binary.
const fs::path& wall_run() {
  static const fs::path dir = [] {
    const fs::path d = test::scratch_dir("pv-wall-run");
    std::ofstream(d / "walls.yaml") << kWallRun;
    const auto r =
        test::run_solver("run -q " + (d / "walls.yaml").string() + " -o " + (d / "run").string());
    EXPECT_EQ(r.exit_code, 0) << r.output;
    return d;
  }();
  return dir;
}

bool paraview_required() {
  const char* env = std::getenv("ISOPOUND_REQUIRE_PARAVIEW");
  return env && std::string(env) != "" && std::string(env) != "0";
}

#define ISOPOUND_REQUIRE_PVPYTHON()                                                          \
  do {                                                                                       \
    if (find_pvpython().empty()) {                                                           \
      if (paraview_required()) FAIL() << "pvpython is required (ISOPOUND_REQUIRE_PARAVIEW)"; \
      GTEST_SKIP() << "pvpython not on PATH";                                                \
    }                                                                                        \
  } while (0)

TEST(PostTimeline, EveryContactEpisodeGetsItsFramesWithinTheBudgetAndSlowMotionSaysSo) {
  const fs::path run = wall_run() / "run";
  const auto episodes = log_episodes(run / "contact_events.csv");
  ASSERT_GE(episodes.size(), 10u) << "the run must pound";
  const fs::path out = wall_run() / "anim-default";
  const auto r = test::run_post("animate " + run.string() + " -o " + out.string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const std::vector<double> times = pvd_times(out / "animation.pvd");
  ASSERT_TRUE(std::is_sorted(times.begin(), times.end()));
  EXPECT_EQ(std::adjacent_find(times.begin(), times.end()), times.end()) << "a repeated time";
  EXPECT_LE(times.size(), 1500u);
  for (const Episode& e : episodes)
    EXPECT_GE(frames_within(times, e.start, e.end), 8u) << "episode " << e.start << ".." << e.end;
  // The regular frames stay: every 1/25 s up to the end (8 s).
  for (int k = 0; k <= 200; ++k)
    EXPECT_GE(frames_within(times, k / 25.0 - 1e-9, k / 25.0 + 1e-9), 1u) << "frame at " << k;
  EXPECT_NE(r.output.find(std::to_string(episodes.size()) + " contact episodes"), std::string::npos)
      << r.output;
  EXPECT_TRUE(fs::exists(out / "view.py"));
  // Each frame carries its time and its slow-motion factor (1/fps over the frame's spacing):
  // 1 at the first frame (0 s, before any contact), the spacing's inverse inside an episode.
  char name[32];
  for (std::size_t k : {std::size_t{0}, times.size() / 2}) {
    std::snprintf(name, sizeof name, "frame_%06zu.vtu", k);
    EXPECT_DOUBLE_EQ(field_value(out / name, "TimeValue"), times[k]);
    const double h = k == 0 ? times[1] - times[0] : (times[k + 1] - times[k - 1]) / 2;
    EXPECT_NEAR(field_value(out / name, "slow_motion"), std::max(1.0, 1.0 / (25.0 * h)), 1e-9)
        << name;
  }
  double fastest = 0.0;
  for (std::size_t k = 1; k + 1 < times.size(); ++k) {
    std::snprintf(name, sizeof name, "frame_%06zu.vtu", k);
    if ((times[k + 1] - times[k - 1]) / 2 < 0.004) {  // dense: inside an episode
      fastest = std::max(fastest, field_value(out / name, "slow_motion"));
      break;
    }
  }
  EXPECT_GT(fastest, 10.0) << "no slowed frame";

  // --uniform: the regular frames only, 201 of them.
  const auto u = test::run_post("animate " + run.string() + " --uniform -o " + out.string());
  ASSERT_EQ(u.exit_code, 0) << u.output;
  EXPECT_EQ(pvd_times(out / "animation.pvd").size(), 201u);
  // The default animation's frames beyond 200 were removed, a user's file next to them was not.
  std::size_t vtu = 0;
  for (const auto& f : fs::directory_iterator(out)) vtu += f.path().extension() == ".vtu";
  EXPECT_EQ(vtu, 201u);

  // A budget that cannot hold 8 frames per episode at the rates given is refused with what to
  // change (defaults are thinned to fit it: frame_budget_test.cpp).
  const auto b = test::run_post("animate " + run.string() +
                                " --fps 25 --impact-frames 8 --max-frames 300 -o " +
                                (wall_run() / "anim-budget").string());
  EXPECT_EQ(b.exit_code, 2) << b.output;
  EXPECT_NE(b.output.find("--max-frames"), std::string::npos) << b.output;
  // A budget that can is kept, with fewer regular frames or fewer (>= 8) frames per episode.
  const std::size_t budget = 201 + 9 * episodes.size();
  const auto c = test::run_post("animate " + run.string() + " --max-frames " +
                                std::to_string(budget) + " -o " + (wall_run() / "anim-9").string());
  ASSERT_EQ(c.exit_code, 0) << c.output;
  const auto tight = pvd_times(wall_run() / "anim-9" / "animation.pvd");
  EXPECT_LE(tight.size(), budget);
  for (const Episode& e : episodes) EXPECT_GE(frames_within(tight, e.start, e.end), 8u);
}

// 2D: the thesis building between rigid walls 10 cm away under the built-in pulse.
constexpr const char* kWallRun2D = R"(building:
  name: 3-storey
  base: {mass: 340 t}
  floors: {count: 3, mass: 340 t, roof_mass: 250 t, stiffness: 600 MN/m, height: 3.2 m}
  isolator: {model: bouc_wen, Tb: 2.0 s, QW: 5 %, uy: 1 cm, n: 2, A: 1, beta: 0.5, gamma: 0.5}
  walls: {sides: both, level: 0, gap: 10 cm, mass: 500 t, law: kelvin_voigt, k: 2500 kN/mm, e: 0.7}
analysis: {t_end: 10 s}
output: {interval: 0.001 s}
)";

TEST(PostTimeline, TwoDimensionalEpisodesFromTheForceHistoriesGetTheirFramesToo) {
  const fs::path dir = test::scratch_dir("pv-2d");
  std::ofstream(dir / "walls.yaml") << kWallRun2D;
  auto r =
      test::run_solver("run -q " + (dir / "walls.yaml").string() + " -o " + (dir / "run").string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  // Episodes read here: runs of rows with a positive wall force, from the row before to the row
  // after.
  std::ifstream csv(dir / "run" / "histories.csv");
  std::string line;
  std::getline(csv, line);
  const std::vector<std::string> header = split_csv(line);
  std::vector<std::size_t> force_columns;
  for (std::size_t c = 0; c < header.size(); ++c)
    if (header[c].find("/wall ") != std::string::npos &&
        header[c].find(" force [N]") != std::string::npos)
      force_columns.push_back(c);
  ASSERT_EQ(force_columns.size(), 2u) << line;
  std::vector<double> time;
  std::vector<std::vector<double>> force(2);
  while (std::getline(csv, line)) {
    const std::vector<std::string> cells = split_csv(line);
    time.push_back(std::stod(cells[0]));
    for (int k = 0; k < 2; ++k) force[k].push_back(std::stod(cells[force_columns[k]]));
  }
  std::vector<std::pair<double, double>> episodes;
  for (const auto& f : force)
    for (std::size_t i = 0; i < f.size();) {
      if (!(f[i] > 0.0)) {
        ++i;
        continue;
      }
      std::size_t j = i;
      while (j < f.size() && f[j] > 0.0) ++j;
      episodes.emplace_back(time[i > 0 ? i - 1 : 0], time[std::min(j, f.size() - 1)]);
      i = j;
    }
  ASSERT_GE(episodes.size(), 3u) << "the run must pound";
  r = test::run_post("animate " + (dir / "run").string() + " -o " + (dir / "anim").string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const auto times = pvd_times(dir / "anim" / "animation.pvd");
  for (const auto& [a, b] : episodes) EXPECT_GE(frames_within(times, a, b), 8u) << a << ".." << b;
  EXPECT_NE(r.output.find(std::to_string(episodes.size()) + " contact episodes"), std::string::npos)
      << r.output;
}

TEST(PostTimeline, EarlierFramesAreRemovedOnlyWhenThisToolWroteThem) {
  const fs::path run = wall_run() / "run";
  const fs::path out = test::scratch_dir("pv-stale");
  std::ofstream(out / "frame_notes.txt") << "mine";
  std::ofstream(out / "frame_999999.vtu") << "not listed in animation.pvd";
  auto r = test::run_post("animate " + run.string() + " --fps 10 -o " + out.string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const std::size_t first = pvd_times(out / "animation.pvd").size();
  r = test::run_post("animate " + run.string() + " --fps 10 --uniform -o " + out.string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  ASSERT_LT(81u, first);
  std::size_t frames = 0;
  for (const auto& f : fs::directory_iterator(out))
    frames += std::regex_match(f.path().filename().string(), std::regex(R"(frame_[0-9]{6}\.vtu)"));
  EXPECT_EQ(frames, 81u + 1u);  // this animation's 81 and the user's unlisted file
  EXPECT_TRUE(fs::exists(out / "frame_notes.txt"));
  EXPECT_TRUE(fs::exists(out / "frame_999999.vtu"));
}

TEST(PostTimeline, XY5ToFiveSecondsHasEightFramesInEveryEpisodeOfItsLog) {
  ISOPOUND_REQUIRE_RECORDS();
  const fs::path dir = test::scratch_dir("pv-xy5");
  auto r = test::run_solver("run -q " + (test::source_dir() / "configs" / "3d-xy5.yaml").string() +
                            " --until '5 s' -o " + (dir / "run").string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  r = test::run_post("animate " + (dir / "run").string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const auto episodes = log_episodes(dir / "run" / "contact_events.csv");
  ASSERT_GE(episodes.size(), 20u);
  const auto times = pvd_times(dir / "run" / "animation" / "animation.pvd");
  EXPECT_LE(times.size(), 1500u);
  for (const Episode& e : episodes) EXPECT_GE(frames_within(times, e.start, e.end), 8u);
}

// Contact colours of view.py: yellow (no force) to dark red (the peak), outlined dark red.
bool warm(const unsigned char* p) {
  return p[0] > 150 && p[2] < 70 && p[0] > p[1] + 50;
}

int warm_pixels_near(const test::Image& image, double x, double y_down, int half) {
  int n = 0;
  for (int dy = -half; dy <= half; ++dy)
    for (int dx = -half; dx <= half; ++dx) {
      const int px = static_cast<int>(std::lround(x)) + dx;
      const int py = static_cast<int>(std::lround(y_down)) + dy;
      if (px < 0 || py < 0 || px >= image.width || py >= image.height) continue;
      n += warm(image.at(px, image.height - 1 - py));
    }
  return n;
}

TEST(PostParaView, ViewScriptLoadsInPvpythonWithTheRunsTimesAndShowsTheContactWhereItIs) {
  ISOPOUND_REQUIRE_PVPYTHON();
  const fs::path run = wall_run() / "run";
  const fs::path out = test::scratch_dir("pv-view");
  auto r = test::run_post("animate " + run.string() + " -o " + out.string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const std::vector<double> times = pvd_times(out / "animation.pvd");
  // A frame inside the hardest impact (the frame nearest its peak) and a regular frame in no
  // episode at all.
  const auto episodes = log_episodes(run / "contact_events.csv");
  const Episode hardest = *std::max_element(
      episodes.begin(), episodes.end(),
      [](const Episode& a, const Episode& b) { return a.peak_force < b.peak_force; });
  double inside = times.front();
  for (double t : times)
    if (t >= hardest.start && t < hardest.end &&
        std::abs(t - hardest.peak_time) < std::abs(inside - hardest.peak_time))
      inside = t;
  ASSERT_TRUE(inside >= hardest.start && inside < hardest.end);
  double outside = -1.0;
  for (double t : times) {
    bool in_any = false;
    for (const Episode& e : episodes) in_any = in_any || (t >= e.start - 0.05 && t <= e.end + 0.05);
    if (!in_any && t > 1.0) {
      outside = t;
      break;
    }
  }
  ASSERT_GT(outside, 0.0);

  const PrivateDisplay display(false);
  char t_in[40], t_out[40];
  std::snprintf(t_in, sizeof t_in, "%.17g", inside);
  std::snprintf(t_out, sizeof t_out, "%.17g", outside);
  ASSERT_NO_THROW(
      run_pvpython(out / "view.py", {"--time", t_in, "--screenshot", (out / "inside.png").string(),
                                     "--report", (out / "inside.json").string()}));
  ASSERT_NO_THROW(run_pvpython(
      out / "view.py", {"--time", t_out, "--screenshot", (out / "outside.png").string(), "--report",
                        (out / "outside.json").string()}));
  std::ifstream in_json(out / "inside.json"), out_json(out / "outside.json");
  const auto report_in = nlohmann::json::parse(in_json);
  const auto report_out = nlohmann::json::parse(out_json);

  // ParaView's time steps are the .pvd's, which are the simulation's frame times.
  const auto steps = report_in["time_steps"].get<std::vector<double>>();
  ASSERT_EQ(steps.size(), times.size());
  for (std::size_t k = 0; k < steps.size(); ++k) EXPECT_DOUBLE_EQ(steps[k], times[k]) << k;

  const auto& frame_in = report_in["frames"].at(0);
  EXPECT_DOUBLE_EQ(frame_in["time"].get<double>(), inside);
  EXPECT_GE(frame_in["contact_cells"].get<int>(), 1);
  ASSERT_TRUE(frame_in.contains("pixel"));
  const double px = frame_in["pixel"][0].get<double>(), py = frame_in["pixel"][1].get<double>();
  const test::Image shot_in = test::read_png((out / "inside.png").string());
  EXPECT_GE(warm_pixels_near(shot_in, px, py, 6), 3) << "no contact colour at " << px << "," << py;

  const auto& frame_out = report_out["frames"].at(0);
  EXPECT_EQ(frame_out["contact_cells"].get<int>(), 0);
  const test::Image shot_out = test::read_png((out / "outside.png").string());
  EXPECT_EQ(warm_pixels_near(shot_out, px, py, 6), 0);
}

// A frame's points and one of its 3-component point arrays.
struct FramePoints {
  std::vector<std::array<double, 3>> points, values;
};

FramePoints frame_points(const fs::path& vtu, const char* array) {
  vtkNew<vtkXMLUnstructuredGridReader> reader;
  reader->SetFileName(vtu.string().c_str());
  reader->Update();
  vtkUnstructuredGrid* grid = reader->GetOutput();
  vtkDataArray* a = grid->GetPointData()->GetArray(array);
  FramePoints out;
  for (vtkIdType i = 0; i < grid->GetNumberOfPoints(); ++i) {
    std::array<double, 3> p{}, v{};
    grid->GetPoint(i, p.data());
    if (a) a->GetTuple(i, v.data());
    out.points.push_back(p);
    out.values.push_back(v);
  }
  return out;
}

TEST(PostParaView, WallPointsCarryTheirGapSoThatAViewerScalesGapsWithDisplacements) {
  const fs::path run = wall_run() / "run";
  const fs::path out = test::scratch_dir("pv-gaps");
  const auto r =
      test::run_post("animate " + run.string() + " --uniform --fps 1 -o " + out.string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  // At rest (t = 0): the building's points carry no gap; every wall's points carry the model's
  // 15 cm gap, pointing away from the building's centre (the walls' offsets outward).
  const FramePoints f = frame_points(out / "frame_000000.vtu", "gap_offset");
  ASSERT_FALSE(f.points.empty());
  // The building's centre: the mean of the points without a gap.
  double cx = 0, cy = 0;
  std::size_t n = 0;
  for (std::size_t j = 0; j < f.points.size(); ++j)
    if (f.values[j] == std::array<double, 3>{}) cx += f.points[j][0], cy += f.points[j][1], ++n;
  ASSERT_GT(n, 0u);
  cx /= static_cast<double>(n), cy /= static_cast<double>(n);
  std::size_t wall_points = 0;
  for (std::size_t i = 0; i < f.points.size(); ++i) {
    const auto& [gx, gy, gz] = f.values[i];
    const double g = std::hypot(gx, gy, gz);
    if (g == 0.0) continue;
    ++wall_points;
    EXPECT_NEAR(g, 0.15, 1e-9) << "point " << i;
    const auto& p = f.points[i];
    EXPECT_GT((p[0] - cx) * gx + (p[1] - cy) * gy, 0.0) << "point " << i << ": gap points inward";
  }
  EXPECT_GT(wall_points, 0u);
}

TEST(PostParaView, ViewScriptDrawsTheMotionAtAVisibleScaleAndForcesInMN) {
  ISOPOUND_REQUIRE_PVPYTHON();
  const fs::path run = wall_run() / "run";
  const fs::path out = test::scratch_dir("pv-scale");
  auto r = test::run_post("animate " + run.string() + " -o " + out.string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  // The largest displacement of any point in any frame, and the site's size (frame 0), read here.
  double largest = 0.0, extent = 0.0;
  std::array<double, 3> lo{1e300, 1e300, 1e300}, hi{-1e300, -1e300, -1e300};
  std::size_t k = 0;
  for (const auto& [t, file] : test::read_pvd(out / "animation.pvd")) {
    const FramePoints f = frame_points(out / file, "displacement");
    for (const auto& d : f.values) largest = std::max(largest, std::hypot(d[0], d[1], d[2]));
    if (k++ == 0)
      for (const auto& p : f.points)
        for (int i = 0; i < 3; ++i) lo[i] = std::min(lo[i], p[i]), hi[i] = std::max(hi[i], p[i]);
  }
  for (int i = 0; i < 3; ++i) extent = std::max(extent, hi[i] - lo[i]);
  ASSERT_GT(largest, 0.05) << "the building must move";
  double peak = 0.0;
  for (const Episode& e : log_episodes(run / "contact_events.csv"))
    peak = std::max(peak, e.peak_force);
  ASSERT_GT(peak, 1e6) << "this run's impacts reach MN";

  const PrivateDisplay display(false);
  ASSERT_NO_THROW(run_pvpython(out / "view.py", {"--report", (out / "report.json").string()}));
  std::ifstream in(out / "report.json");
  const auto report = nlohmann::json::parse(in);
  const double scale = report["scale"].get<double>();
  // A round factor (1, 2 or 5 x 10^k) that draws the largest displacement 4 to 10 % of the site:
  // 10 % rounded down to the next such factor (at most a factor 2.5 below).
  const double mantissa = scale / std::pow(10.0, std::floor(std::log10(scale) + 1e-12));
  EXPECT_TRUE(std::abs(mantissa - 1) < 1e-9 || std::abs(mantissa - 2) < 1e-9 ||
              std::abs(mantissa - 5) < 1e-9)
      << scale;
  EXPECT_GT(scale, 1.0);
  EXPECT_LE(scale * largest, 0.1 * extent * (1 + 1e-9)) << largest << " m in " << extent << " m";
  EXPECT_GT(scale * largest, 0.04 * extent) << largest << " m in " << extent << " m";
  // The pipeline's warps: the frames are drawn at scale 1 with gaps true (3D), so view.py moves
  // points by (scale - 1) x displacement and walls by (scale - 1) x their gap.
  EXPECT_DOUBLE_EQ(report["displacement_warp"].get<double>(), scale - 1.0);
  EXPECT_DOUBLE_EQ(report["gap_warp"].get<double>(), scale - 1.0);
  // Forces that reach MN are shown in MN, on [0, the run's peak].
  EXPECT_EQ(report["colour_bar"]["title"].get<std::string>(), "contact F_N [MN]");
  EXPECT_DOUBLE_EQ(report["colour_bar"]["range"][0].get<double>(), 0.0);
  EXPECT_NEAR(report["colour_bar"]["range"][1].get<double>(), peak / 1e6, 1e-9 * peak / 1e6);
  // The scale is stated on screen.
  std::ostringstream stated;
  stated << "displacements and gaps drawn x " << scale << " ";
  const std::string note = report["note"].get<std::string>();
  EXPECT_NE(note.find(stated.str()), std::string::npos) << note;
  EXPECT_NE(note.find(" MN = "), std::string::npos) << note;

  // --view-scale sets it; SCALE at the top of view.py is the one place that holds it.
  r = test::run_post("animate " + run.string() + " --view-scale 20 -o " + out.string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  std::ifstream script(out / "view.py");
  std::stringstream text;
  text << script.rdbuf();
  EXPECT_NE(text.str().find("\nSCALE = 20\n"), std::string::npos);
}

// The GUI (paraview --script=view.py) draws its toolbar buttons' icons from SVG: without Qt's
// SVG support (Debian's libqt5svg5, only recommended by Qt) every button is drawn blank.
// .ci/setup installs it; checked where ParaView is required.
TEST(PostParaView, TheGuiHasQtSvgForItsToolbarIcons) {
  if (!paraview_required()) GTEST_SKIP() << "ISOPOUND_REQUIRE_PARAVIEW not set";
  const auto r = test::run_command("dpkg -s libqt5svg5");
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("Status: install ok installed"), std::string::npos) << r.output;
}

// view.py in the GUI itself (paraview --script, as the demo tells the user), not only pvpython:
// a wrapper runs it with --report inside the GUI, which then exits (--exit); the GUI prints a
// script's Python errors but exits 0, so the report is the proof that the script ran through.
TEST(PostParaView, ViewScriptRunsInTheParaViewGui) {
  const std::string gui = find_on_path("paraview");
  if (gui.empty()) {
    if (paraview_required()) FAIL() << "paraview is required (ISOPOUND_REQUIRE_PARAVIEW)";
    GTEST_SKIP() << "paraview not on PATH";
  }
  const fs::path run = wall_run() / "run";
  const fs::path out = test::scratch_dir("pv-gui");
  auto r = test::run_post("animate " + run.string() + " -o " + out.string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  std::ofstream(out / "in_gui.py") << "import sys\n"
                                      "sys.argv = ['view.py', '--report', r'"
                                   << (out / "gui.json").string()
                                   << "']\n"
                                      "exec(open(r'"
                                   << (out / "view.py").string() << "').read())\n";
  fs::create_directories(out / "config");
  const PrivateDisplay display(false);
  r = test::run_command("XDG_CONFIG_HOME=" + (out / "config").string() + " timeout 300 " + gui +
                        " --dr --script=" + (out / "in_gui.py").string() + " --exit");
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(r.output.find("Traceback"), std::string::npos) << r.output;
  ASSERT_TRUE(fs::exists(out / "gui.json")) << r.output;
  std::ifstream in(out / "gui.json");
  const auto report = nlohmann::json::parse(in);
  EXPECT_EQ(report["time_steps"].size(), pvd_times(out / "animation.pvd").size());
  EXPECT_EQ(report["colour_bar"]["title"].get<std::string>(), "contact F_N [MN]");
  EXPECT_GT(report["scale"].get<double>(), 1.0);
}

}  // namespace
}  // namespace isopound::post
