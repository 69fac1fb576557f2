// plot and animate on real 2D runs: a pounding run of configs/ made by the solver, every .vtu read
// back with VTK's XML reader and checked against the run's histories and summary.json; bad input.
#include <gtest/gtest.h>
#include <vtkCell.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridReader.h>

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <regex>
#include <sstream>

#include "post/run_data.h"
#include "post_test_support.h"

namespace isopound::post {
namespace {

// The chapter-4 Kelvin-Voigt pounding run (3-storey, walls both sides, Sylmar record from
// ../shared): made once per test binary (about 0.1 s).
std::filesystem::path g_run_dir;  // removed when the test program ends

struct RunDirCleanup : ::testing::Environment {
  void TearDown() override {
    if (!g_run_dir.empty()) std::filesystem::remove_all(g_run_dir);
  }
};
[[maybe_unused]] ::testing::Environment* const g_cleanup =
    ::testing::AddGlobalTestEnvironment(new RunDirCleanup);

const std::filesystem::path& pounding_run() {
  static const std::filesystem::path dir = [] {
    const auto d = test::scratch_dir("run-c4");
    g_run_dir = d;
    const auto r = test::run_solver(
        "run " + (test::source_dir() / "configs" / "chapter4-3storey-kelvin_voigt.yaml").string() +
        " -o " + d.string());
    EXPECT_EQ(r.exit_code, 0) << r.output;
    return d;
  }();
  return dir;
}

TEST(PostAnimate, EveryFrameReadsBackWithItsArraysAndContactsOnlyWhileInContact) {
  ISOPOUND_REQUIRE_RECORDS();  // the chapter-4 configs use a shared record
  const auto run_dir = pounding_run();
  const auto out = test::scratch_dir("anim");
  const double fps = 10.0;
  const auto r =
      test::run_post("animate " + run_dir.string() +
                     " --uniform --fps 10 --end 12 --scale 5 --preview 4.8 -o " + out.string());
  ASSERT_EQ(r.exit_code, 0) << r.output;

  // Independent reading of the histories (header names) and the summary.
  const RunData run = read_run(run_dir);
  const int u_base = run.find("3-storey-bw/base", "u");
  const int f_left = run.find("3-storey-bw/wall left (base)", "force");
  const int f_right = run.find("3-storey-bw/wall right (base)", "force");
  ASSERT_GE(u_base, 0);
  ASSERT_GE(f_left, 0);
  std::ifstream sj(run_dir / "summary.json");
  const auto summary = nlohmann::json::parse(sj);
  // Largest level displacement of the run (every level's point carries its level's u), story
  // drift ratio and wall force: the frames' arrays cannot exceed them.
  // A peak in either summary shape: {peak_m | peak, time_s} now, {value, unit, time} later.
  const auto peak = [](const nlohmann::json& j) {
    for (const char* key : {"value", "peak_m", "peak"})
      if (j.contains(key)) return j[key].get<double>();
    ADD_FAILURE() << "no peak value in " << j.dump();
    return 0.0;
  };
  double peak_level = 0.0, peak_drift = 0.0, peak_force = 0.0;
  for (const auto& level : summary["structures"][0]["levels"])
    peak_level = std::max(peak_level, peak(level["displacement"]));
  for (const auto& story : summary["structures"][0]["stories"])
    peak_drift = std::max(peak_drift, peak(story["drift_ratio"]));
  for (const auto& element : summary["elements"])
    if (element["label"].get<std::string>().find("/wall ") != std::string::npos)
      peak_force = std::max(peak_force, peak(element["peak_force"]));
  ASSERT_GT(peak_force, 0.0);

  // The .pvd: one DataSet per frame at k / fps, files in order.
  {
    std::ifstream pvd(out / "animation.pvd");
    std::stringstream text;
    text << pvd.rdbuf();
    EXPECT_NE(text.str().find("<VTKFile type=\"Collection\""), std::string::npos);
  }
  const auto frames = test::read_pvd(out / "animation.pvd");
  const double t_end = 12.0;  // --end: the strong motion (the rest is free vibration)
  ASSERT_EQ(frames.size(), static_cast<std::size_t>(std::floor(t_end * fps + 1e-9)) + 1);

  double max_u = 0.0, max_drift = 0.0, max_force = 0.0;
  int contact_frames = 0;
  for (std::size_t k = 0; k < frames.size(); ++k) {
    EXPECT_NEAR(frames[k].first, k / fps, 1e-12);
    vtkNew<vtkXMLUnstructuredGridReader> reader;
    reader->SetFileName((out / frames[k].second).string().c_str());
    reader->Update();
    vtkUnstructuredGrid* g = reader->GetOutput();
    ASSERT_GT(g->GetNumberOfCells(), 0) << frames[k].second;
    EXPECT_EQ(g->GetPoints()->GetDataType(), VTK_DOUBLE);
    vtkDataArray* disp = g->GetPointData()->GetArray("displacement");
    vtkDataArray* block = g->GetCellData()->GetArray("block");
    vtkDataArray* force = g->GetCellData()->GetArray("contact_force");
    ASSERT_TRUE(disp && block && force && g->GetPointData()->GetArray("absolute_acceleration") &&
                g->GetCellData()->GetArray("drift_ratio") &&
                g->GetCellData()->GetArray("bearing_force"));
    EXPECT_EQ(disp->GetDataType(), VTK_DOUBLE);
    EXPECT_EQ(block->GetDataType(), VTK_DOUBLE);
    for (vtkIdType i = 0; i < disp->GetNumberOfTuples(); ++i)
      max_u = std::max(max_u, std::abs(disp->GetComponent(i, 0)));
    // Contact cells exactly when a wall's force or penetration is positive at this frame time.
    // Frames at k/10 s fall on history rows (every 5 ms): read the row itself, no interpolation.
    const double t = frames[k].first;
    std::size_t row = 0;
    while (row < run.rows() && std::abs(run.time()[row] - t) > 1e-9) ++row;
    ASSERT_LT(row, run.rows()) << "no history row at t = " << t;
    const int p_left = run.find("3-storey-bw/wall left (base)", "penetration");
    const int p_right = run.find("3-storey-bw/wall right (base)", "penetration");
    const int expected = (run.values[f_left][row] > 0.0 || run.values[p_left][row] > 0.0) +
                         (run.values[f_right][row] > 0.0 || run.values[p_right][row] > 0.0);
    vtkDataArray* drift = g->GetCellData()->GetArray("drift_ratio");
    for (vtkIdType c = 0; c < drift->GetNumberOfTuples(); ++c)
      max_drift = std::max(max_drift, std::abs(drift->GetComponent(c, 0)));
    for (vtkIdType c = 0; c < force->GetNumberOfTuples(); ++c)
      max_force = std::max(max_force, std::abs(force->GetComponent(c, 0)));
    int contacts = 0;
    for (vtkIdType c = 0; c < block->GetNumberOfTuples(); ++c)
      if (block->GetComponent(c, 0) == 4.0) {
        ++contacts;
        EXPECT_NE(force->GetComponent(c, 0), 0.0);
      }
    EXPECT_EQ(contacts, expected) << "t = " << t;
    contact_frames += contacts > 0;
  }
  EXPECT_GT(contact_frames, 0);  // the run pounds: some frames must show it
  const test::Image preview = test::read_png((out / "preview.png").string());
  EXPECT_EQ(preview.width, 900);
  EXPECT_GT(preview.variance(), 50.0);
  // Displacements are the true ones (not scaled): not above the summary's peak (taken over every
  // step) and within 10 % of it at 10 frames/s (the isolated building sways with a ~2 s period).
  EXPECT_LE(max_u, peak_level * (1 + 1e-9));
  EXPECT_LE(max_drift, peak_drift * (1 + 1e-9));
  EXPECT_GT(max_drift, 0.5 * peak_drift);  // drift peaks are short (impacts): a looser bound
  EXPECT_LE(max_force, peak_force * (1 + 1e-9));
  EXPECT_GT(max_force, 0.0);
  EXPECT_GT(max_u, 0.9 * peak_level);
  std::filesystem::remove_all(out);
}

TEST(PostAnimate, FlexibleWallsMoveAndAreNotLevelsOfTheBuilding) {
  ISOPOUND_REQUIRE_RECORDS();
  // The chapter-4 set-up with flexible walls (200 MN/m): each wall is a DOF of its own.
  const auto dir = test::scratch_dir("flex");
  std::ifstream in(test::source_dir() / "configs" / "chapter4-3storey-kelvin_voigt.yaml");
  std::stringstream text;
  text << in.rdbuf();
  std::string yaml = text.str();
  const auto mass = yaml.find("    mass: 500 t");
  ASSERT_NE(mass, std::string::npos);
  yaml.insert(mass, "    stiffness: 200 MN/m\n");
  const auto rec = yaml.find("../../shared/records/");
  ASSERT_NE(rec, std::string::npos);
  yaml.replace(rec, 21, (::isopound::test::records_dir() / "").string());
  std::ofstream(dir / "flex.yaml") << yaml;
  auto r =
      test::run_solver("run " + (dir / "flex.yaml").string() + " -o " + (dir / "run").string());
  ASSERT_EQ(r.exit_code, 0) << r.output;

  const RunData run = read_run(dir / "run", (dir / "flex.yaml").string());
  ASSERT_EQ(run.structures.size(), 1u);
  EXPECT_EQ(run.structures[0].levels.size(), 4u);  // base + 3 floors, no wall DOFs
  ASSERT_EQ(run.walls.size(), 2u);
  for (const Wall& w : run.walls) {
    EXPECT_GE(w.u, 0) << w.label;
    EXPECT_DOUBLE_EQ(w.gap, 0.2);
  }
  r = test::run_post("animate " + (dir / "run").string() + " --model " +
                     (dir / "flex.yaml").string() + " --uniform --fps 10 --end 8 -o " +
                     (dir / "anim").string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  double max_wall_u = 0.0;
  int contact_frames = 0;
  for (int k = 0; k <= 80; ++k) {
    char name[32];
    std::snprintf(name, sizeof name, "frame_%06d.vtu", k);
    vtkNew<vtkXMLUnstructuredGridReader> reader;
    reader->SetFileName((dir / "anim" / name).string().c_str());
    reader->Update();
    vtkUnstructuredGrid* g = reader->GetOutput();
    vtkDataArray* block = g->GetCellData()->GetArray("block");
    vtkDataArray* disp = g->GetPointData()->GetArray("displacement");
    ASSERT_TRUE(block && disp) << name;
    for (vtkIdType c = 0; c < g->GetNumberOfCells(); ++c) {
      if (block->GetComponent(c, 0) == 4.0) ++contact_frames;
      if (block->GetComponent(c, 0) != 3.0) continue;
      const vtkIdType p = g->GetCell(c)->GetPointId(0);
      max_wall_u = std::max(max_wall_u, std::abs(disp->GetComponent(p, 0)));
    }
  }
  EXPECT_GT(contact_frames, 0);
  // The walls are pushed: they move, by less than the base slab's peak.
  EXPECT_GT(max_wall_u, 0.0);
  EXPECT_LT(max_wall_u, 0.3);
  std::filesystem::remove_all(dir);
}

TEST(PostPlot, RunFiguresAreWrittenNonBlankWithTheirSize) {
  ISOPOUND_REQUIRE_RECORDS();
  const auto run_dir = pounding_run();
  const auto out = test::scratch_dir("plot");
  const auto r = test::run_post("plot " + run_dir.string() + " -o " + out.string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const test::Image th = test::read_png((out / "time_histories.png").string());
  EXPECT_EQ(th.width, 1000);
  // Five panels: base, drifts, the base's acceleration, the floors' and ground's, impacts.
  EXPECT_EQ(th.height, kHistoryPanelHeight * 5 + 40);
  EXPECT_GT(th.variance(), 100.0);
  const test::Image hy = test::read_png((out / "hysteresis.png").string());
  EXPECT_EQ(hy.width, 1000);  // isolator + two walls: two columns
  EXPECT_GT(hy.variance(), 100.0);
  std::filesystem::remove_all(out);
}

TEST(PostRunData, ColumnsByHeaderNameAndHeightsInEitherSummaryShape) {
  const ColumnName n = parse_column_name("3-storey-bw/wall left (base) penetration [m]");
  EXPECT_EQ(n.label, "3-storey-bw/wall left (base)");
  EXPECT_EQ(n.quantity, "penetration");
  EXPECT_EQ(n.unit, "m");
  EXPECT_EQ(parse_column_name("time [s]").quantity, "time");
  // A hand-made run: columns in an unusual order, story heights once as height_m and once in the
  // {value, unit} shape; elevations must follow, columns be found by name.
  const auto dir = test::scratch_dir("rundata");
  {
    std::ofstream h(dir / "histories.csv");
    h << "time [s],b/floor 2 u [m],ground_acceleration [m/s2],b/floor 1 u [m],b/base u [m]\n"
      << "0,0,0,0,0\n0.1,0.3,1,0.2,0.1\n";
    std::ofstream j(dir / "summary.json");
    j << R"({"structures": [{"name": "b", "stories": [
          {"label": "b/story 1", "height_m": 4.0},
          {"label": "b/story 2", "height": {"value": 3.5, "unit": "m"}}]}]})";
  }
  const RunData run = read_run(dir);
  ASSERT_EQ(run.structures.size(), 1u);
  const auto& levels = run.structures[0].levels;
  ASSERT_EQ(levels.size(), 3u);
  EXPECT_EQ(levels[0].label, "b/base");
  EXPECT_DOUBLE_EQ(levels[1].elevation, 4.0);
  EXPECT_DOUBLE_EQ(levels[2].elevation, 7.5);
  EXPECT_EQ(levels[2].u, 1);
  EXPECT_DOUBLE_EQ(value_at(run, levels[1].u, 0.05), 0.1);
  std::filesystem::remove_all(dir);
}

// Isolated on floor 1 (docs/isolation-level.md): summary.json's isolation_level and
// isolation_height_m put the slab at z(floor 1) + h and raise the floors above it by h.
TEST(PostRunData, SlabIsolatedAboveAStoreySitsAtItsElevation) {
  const auto dir = test::scratch_dir("rundata-mid");
  {
    std::ofstream h(dir / "histories.csv");
    h << "time [s],b/floor 1 u [m],b/base u [m],b/floor 2 u [m]\n0,0,0,0\n0.1,0.1,0.2,0.3\n";
    std::ofstream j(dir / "summary.json");
    j << R"({"structures": [{"name": "b", "isolation_level": 1, "isolation_height_m": 1.0,
          "stories": [{"label": "b/story 1", "height_m": 4.0},
                      {"label": "b/story 2", "height_m": 3.5}]}]})";
  }
  const RunData run = read_run(dir);
  ASSERT_EQ(run.structures.size(), 1u);
  const auto& levels = run.structures[0].levels;
  ASSERT_EQ(levels.size(), 3u);
  EXPECT_EQ(levels[0].label, "b/floor 1");
  EXPECT_DOUBLE_EQ(levels[0].elevation, 4.0);
  EXPECT_EQ(levels[1].label, "b/base");
  EXPECT_DOUBLE_EQ(levels[1].elevation, 5.0);
  EXPECT_EQ(levels[2].label, "b/floor 2");
  EXPECT_DOUBLE_EQ(levels[2].elevation, 8.5);
  std::filesystem::remove_all(dir);
}

TEST(PostCli, BadInputGivesOneClearErrorAndNonZeroExit) {
  const auto dir = test::scratch_dir("bad");
  auto r = test::run_post("plot " + (dir / "nope").string());
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.output.find("run directory not found"), std::string::npos) << r.output;
  r = test::run_post("animate " + dir.string());
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.output.find("histories.csv: cannot open"), std::string::npos) << r.output;
  {
    std::ofstream h(dir / "histories.csv");
    h << "time [s],ground_acceleration [m/s2],b/base u [m]\n0,0,0\n0.01,x,0\n";
  }
  r = test::run_post("plot " + dir.string());
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.output.find("histories.csv:3: column 'ground_acceleration [m/s2]': not a number"),
            std::string::npos)
      << r.output;
  r = test::run_post("spectra " + (dir / "missing.AT2").string());
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.output.find("record not found"), std::string::npos) << r.output;
  r = test::run_post("spectra a.AT2 b.AT2 c.AT2 --pair");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.output.find("two by two"), std::string::npos) << r.output;
  r = test::run_post("");
  EXPECT_NE(r.exit_code, 0);
  r = test::run_post("animate " + dir.string() + " --fps 0");
  EXPECT_NE(r.exit_code, 0);
  std::filesystem::remove_all(dir);
}

TEST(PostHeadless, PrivateXvfbIsAnnouncedInOneLineAndGoneAfterTheCommand) {
  const auto dir = test::scratch_dir("xvfb");
  {
    std::ofstream rec(dir / "rec.txt");
    rec.precision(17);
    for (int i = 0; i < 200; ++i) rec << std::sin(0.1 * i) << "\n";
  }
  const auto r = test::run_command("env -u DISPLAY " + std::string(ISOPOUND_POST_BINARY) +
                                   " spectra " + (dir / "rec.txt").string() +
                                   " --unit m/s2 --dt 0.01 -o " + (dir / "out").string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const std::regex line("private Xvfb :([0-9]+) \\(pid ([0-9]+)\\)");
  std::smatch m;
  ASSERT_TRUE(std::regex_search(r.output, m, line)) << r.output;
  const std::string pid = m[2];
  // The server was reaped: no such process (or, if the pid was reused, not an Xvfb).
  std::ifstream comm("/proc/" + pid + "/comm");
  std::string name;
  std::getline(comm, name);
  EXPECT_NE(name, "Xvfb");
  EXPECT_FALSE(std::filesystem::exists("/tmp/.X11-unix/X" + std::string(m[1])) &&
               !std::filesystem::exists("/tmp/.X" + std::string(m[1]) + "-lock"))
      << "socket left behind";
  EXPECT_GT(test::read_png((dir / "out" / "spectra.png").string()).variance(), 50.0);
  // spectra.csv: header, then T = 0 (PSA = PGA in g) and the 120 default periods, each row with
  // the damping ratio.
  std::ifstream csv(dir / "out" / "spectra.csv");
  std::string header, first, row;
  std::getline(csv, header);
  EXPECT_EQ(header, "period_s,damping_ratio,rec_PSA_g,rec_SD_m");
  std::getline(csv, first);
  double pga = 0.0;
  for (int i = 0; i < 200; ++i) pga = std::max(pga, std::abs(std::sin(0.1 * i)));
  EXPECT_EQ(first.substr(0, first.find(',', 2)), "0,0.05");
  EXPECT_NEAR(std::stod(first.substr(first.find(',', 2) + 1)), pga / 9.81, 1e-8);
  int rows = 1;
  while (std::getline(csv, row)) ++rows;
  EXPECT_EQ(rows, 121);
  // A DISPLAY that cannot be opened (ssh without X forwarding) is replaced, not fatal.
  const auto stale = test::run_command("env DISPLAY=:65000 " + std::string(ISOPOUND_POST_BINARY) +
                                       " spectra " + (dir / "rec.txt").string() +
                                       " --unit m/s2 --dt 0.01 -o " + (dir / "out2").string());
  EXPECT_EQ(stale.exit_code, 0) << stale.output;
  EXPECT_NE(stale.output.find("DISPLAY=:65000 cannot be opened, rendering on a private Xvfb"),
            std::string::npos)
      << stale.output;
  // Bad input is found before any server starts: no announcement.
  const auto bad = test::run_command("env -u DISPLAY " + std::string(ISOPOUND_POST_BINARY) +
                                     " plot " + (dir / "nope").string());
  EXPECT_NE(bad.exit_code, 0);
  EXPECT_EQ(bad.output.find("Xvfb"), std::string::npos) << bad.output;
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace isopound::post
