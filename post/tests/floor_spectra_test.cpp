// floor-spectra on real runs made by the solver: (a) the ground's spectrum from the run's own
// ground-acceleration history equals `isopound-post spectra` of the record; (b) a rigid
// superstructure's floors have the base slab's spectrum; (c) a history too coarse for the periods
// asked is refused (exit 2, naming output.interval) or clipped on request; (d) 3D: without
// rotation the plan corners have the centre's spectra, and RotD50 <= RotD100 >= max(x, y); (e) 3D
// with rotation, each plan point's peak equals the solver's own plan-point peak (summary.json).
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <numbers>
#include <regex>
#include <sstream>

#include "post/floor_spectra.h"
#include "post/run_data.h"
#include "post_test_support.h"
#include "solver/core/constants.h"

namespace isopound::post {
namespace {

constexpr double kPi = std::numbers::pi;

void write_file(const std::filesystem::path& path, const std::string& text) {
  std::ofstream out(path);
  out << text;
}

// A synthetic accelerogram in m/s^2, one value a line every 5 ms (8 s), 17 digits.
void write_record(const std::filesystem::path& path) {
  std::ofstream out(path);
  out.precision(17);
  const double dt = 0.005, duration = 8.0;
  for (int i = 0; i * dt <= duration + 1e-9; ++i) {
    const double t = i * dt, env = std::sin(kPi * t / duration);
    out << env * (2.0 * std::sin(2 * kPi * 1.1 * t + 0.3) + 1.2 * std::sin(2 * kPi * 3.7 * t) +
                  0.7 * std::cos(2 * kPi * 0.45 * t + 0.6))
        << "\n";
  }
}

// A 3-storey isolated shear building (storey stiffness k), no walls; `ground` and `output` given.
std::string building_2d(const std::string& k, const std::string& ground,
                        const std::string& output) {
  return "building:\n"
         "  name: b\n"
         "  base: {mass: 340 t}\n"
         "  floors: {count: 3, mass: 340 t, roof_mass: 250 t, stiffness: " +
         k +
         ", height: 3.2 m}\n"
         "  isolator: {model: linear, Tb: 2.0 s}\n"
         "ground_motion:\n" +
         ground + "  extra_time: 0 s\noutput: " + output + "\n";
}

// The ground of building_2d in tests (c), (c') and (g): a 1 m/s pulse of 2 s over 6 s.
constexpr const char* kPulse6s =
    "  pulse: {amplitude: 1.0 m/s, period: 2 s, t_peak: 3 s, duration: 6 s, dt: 0.005 s}\n";

// A 3D 2-storey building on Bouc-Wen bearings (2 x 2 bays of 6 m; `eccentricity` a YAML line or
// "") under the built-in pulse pair (0.8 and 0.4 m/s, 1 s) at `angle`, histories at every sample.
std::string building_3d(const std::string& eccentricity, const std::string& angle) {
  return R"(structures:
  - name: building
    grid: {bays_x: [6 m, 6 m], bays_y: [6 m, 6 m]}
    columns: {section: [45 cm, 45 cm], E: 30 GPa, nu: 0.2}
    storeys: {count: 2, height: 3.2 m, mass: 300 t}
    base: {mass: 300 t}
)" + eccentricity +
         R"(    bearing: {model: bouc_wen, Tb: 2.0 s, QW: 5 %, uy: 1 cm, n: 2, A: 1, beta: 0.5, gamma: 0.5}
ground_motion:
  L: {pulse: {amplitude: 0.8 m/s, period: 1 s, t_peak: 2 s, duration: 5 s, dt: 0.005 s}}
  T: {pulse: {amplitude: 0.4 m/s, period: 1 s, t_peak: 2 s, duration: 5 s, dt: 0.005 s}}
  angle: )" +
         angle + R"(
  extra_time: 0 s
output: {interval: 0 s}
)";
}

std::filesystem::path solve(const std::filesystem::path& dir, const std::string& model) {
  write_file(dir / "model.yaml", model);
  const auto run = dir / "run";
  const auto r = test::run_solver("run " + (dir / "model.yaml").string() + " -o " + run.string());
  EXPECT_EQ(r.exit_code, 0) << r.output;
  return run;
}

// Periods from 0.05 s to 5 s, log-spaced, and 0.
std::vector<double> periods_from_50ms() {
  std::vector<double> t{0.0};
  for (int i = 0; i < 40; ++i) t.push_back(0.05 * std::pow(100.0, i / 39.0));
  return t;
}

double relative(double a, double b) {
  return std::abs(a - b) / std::max(std::abs(b), 1e-300);
}

// CSV columns by header name.
std::map<std::string, std::vector<double>> read_csv(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::string line;
  std::getline(in, line);
  std::vector<std::string> names;
  std::stringstream h(line);
  for (std::string c; std::getline(h, c, ',');) names.push_back(c);
  std::map<std::string, std::vector<double>> cols;
  while (std::getline(in, line)) {
    std::stringstream r(line);
    std::size_t k = 0;
    for (std::string c; std::getline(r, c, ',') && k < names.size(); ++k)
      cols[names[k]].push_back(std::stod(c));
  }
  return cols;
}

// (a) The ground's spectrum from histories.csv (every record sample: output.interval 0) equals
// the record's. Both integrate the same piecewise-linear samples with the same recurrence; the
// history keeps each sample to 9 significant digits (%.9g, relative rounding <= 5e-10), and the
// SD is a linear functional of the samples, so the spectra agree to about that: 1e-8 allows a
// factor 20 for the sum over the samples. The CSVs (10 digits each) agree to 1e-8 too.
TEST(PostFloorSpectra, GroundSpectrumOfTheRunEqualsTheRecordsSpectrum) {
  const auto dir = test::scratch_dir("floor-ground");
  write_record(dir / "rec.txt");
  const auto run_dir =
      solve(dir, building_2d("600 MN/m",
                             "  record: rec.txt\n  format: columns\n  dt: 0.005 s\n  unit: m/s2\n",
                             "{interval: 0 s}"));
  const RunData run = read_run(run_dir);
  RecordReadOptions ro;
  ro.format = RecordReadOptions::Format::kColumns;
  ro.dt = 0.005;
  ro.unit = AccelerationUnit::kMetrePerSecond2;
  const GroundMotion record = read_record((dir / "rec.txt").string(), ro);
  ASSERT_EQ(run.rows(), record.acceleration.size());

  FloorSpectraOptions o;
  o.periods = periods_from_50ms();
  const FloorSpectra f = floor_spectra(run, o);
  const Spectrum expected = response_spectrum(record, o.periods);
  double worst = 0.0;
  for (std::size_t i = 0; i < o.periods.size(); ++i) {
    worst = std::max({worst, relative(f.ground.x.psa[i], expected.psa[i]),
                      relative(f.ground.x.sd[i], expected.sd[i])});
    EXPECT_NEAR(f.ground.x.psa[i], expected.psa[i], 1e-8 * expected.psa[i]) << o.periods[i];
  }
  std::printf(
      "[ floor ] ground vs record spectrum, %zu periods: largest relative difference %.2e\n",
      o.periods.size(), worst);

  // The CLI, against `spectra` on its default periods (0.02 s to 10 s: the rule relaxed to 2.5
  // samples per period, since the ground's history is the record itself).
  const auto r = test::run_post("floor-spectra " + run_dir.string() + " -o " +
                                (dir / "floor").string() + " --samples-per-period 2.5");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const auto s = test::run_post("spectra " + (dir / "rec.txt").string() +
                                " --unit m/s2 --dt 0.005 -o " + (dir / "spectra").string());
  ASSERT_EQ(s.exit_code, 0) << s.output;
  auto floor_csv = read_csv(dir / "floor" / "floor-spectra.csv");
  auto spectra_csv = read_csv(dir / "spectra" / "spectra.csv");
  ASSERT_EQ(floor_csv["period_s"].size(), default_periods().size());
  ASSERT_EQ(floor_csv["period_s"], spectra_csv["period_s"]);
  double worst_csv = 0.0;
  for (std::size_t i = 0; i < floor_csv["period_s"].size(); ++i) {
    const double a = floor_csv["ground PSA [g]"][i], b = spectra_csv["rec_PSA_g"][i];
    worst_csv = std::max(worst_csv, relative(a, b));
    EXPECT_NEAR(a, b, 1e-8 * b) << floor_csv["period_s"][i];
    EXPECT_NEAR(floor_csv["ground SD [m]"][i], spectra_csv["rec_SD_m"][i],
                1e-8 * spectra_csv["rec_SD_m"][i] + 1e-15);
  }
  std::printf("[ floor ] CLI floor-spectra vs spectra, %zu periods: largest relative %.2e\n",
              floor_csv["period_s"].size(), worst_csv);
  EXPECT_TRUE(std::filesystem::file_size(dir / "floor" / "floor-spectra.png") > 10000);
  std::filesystem::remove_all(dir);
}

// The first fixed-base period of the 3-storey shear building (masses 340, 340, 250 t, storey
// stiffness k).
double fixed_base_period(double k) {
  Eigen::Matrix3d K, M = Eigen::Vector3d(340e3, 340e3, 250e3).asDiagonal();
  K << 2 * k, -k, 0, -k, 2 * k, -k, 0, -k, k;
  Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::Matrix3d> es(K, M);
  return 2 * kPi / std::sqrt(es.eigenvalues()(0));
}

// (b) A superstructure 10^4 times stiffer than the tutorial's (T1 = 3.4 ms) moves with its base
// slab: a floor's acceleration differs from the slab's by the storeys' quasi-static deformation,
// a fraction (T1/T)^2 of the content at period T, times a participation factor (< 1.3 for a
// 3-storey chain). The tolerance 2 (T1/T_min)^2, T_min = 50 ms (10 samples of 5 ms), is 0.9 %;
// the pulse's content is near 2 s, so the measured differences are far smaller.
TEST(PostFloorSpectra, RigidSuperstructureFloorsHaveTheBaseSlabsSpectrum) {
  const auto dir = test::scratch_dir("floor-rigid");
  const double k = 6e12;
  const auto run_dir = solve(
      dir, building_2d("6e12 N/m",
                       "  pulse: {amplitude: 1.0 m/s, period: 2 s, t_peak: 3 s, duration: 8 s, "
                       "dt: 0.005 s}\n",
                       "{interval: 0 s}"));
  const RunData run = read_run(run_dir);
  FloorSpectraOptions o;
  o.periods = periods_from_50ms();
  const FloorSpectra f = floor_spectra(run, o);
  ASSERT_EQ(f.places.size(), 4u);
  EXPECT_EQ(f.places[0].label, "b/base");
  const double t1 = fixed_base_period(k);
  const double tolerance = 2 * std::pow(t1 / 0.05, 2);
  double worst = 0.0;
  for (std::size_t p = 1; p < f.places.size(); ++p)
    for (std::size_t i = 0; i < o.periods.size(); ++i) {
      const double d = relative(f.places[p].x.psa[i], f.places[0].x.psa[i]);
      worst = std::max(worst, d);
      EXPECT_LE(d, tolerance) << f.places[p].label << " T = " << o.periods[i];
    }
  std::printf(
      "[ floor ] rigid superstructure: T1 = %.4f s, tolerance %.2e, largest floor/base "
      "PSA difference %.2e\n",
      t1, tolerance, worst);
  // The base slab itself, isolated at Tb = 2 s, is far from the ground (it filters the pulse).
  EXPECT_GT(relative(f.places[0].x.psa[0], f.ground.x.psa[0]), 0.05);
  std::filesystem::remove_all(dir);
}

// (c) Rows every 20 ms cannot resolve 0.1 s (rule: 10 samples per period, T >= 0.2 s): refused
// with exit 2, naming output.interval; with --short-periods clip the short periods are dropped.
TEST(PostFloorSpectra, CoarseHistoryIsRefusedOrClipped) {
  const auto dir = test::scratch_dir("floor-coarse");
  const auto run_dir = solve(dir, building_2d("600 MN/m", kPulse6s, "{interval: 0.02 s}"));
  const auto refused =
      test::run_post("floor-spectra " + run_dir.string() + " --periods 0,0.1,0.5,1");
  EXPECT_EQ(refused.exit_code, 2) << refused.output;
  EXPECT_NE(refused.output.find("output.interval"), std::string::npos) << refused.output;
  EXPECT_NE(refused.output.find("0.1 s"), std::string::npos) << refused.output;
  EXPECT_FALSE(std::filesystem::exists(run_dir / "floor-spectra.csv"));
  // The default periods start at 0.02 s: refused when asked to (by default the short ones are
  // dropped: DefaultPeriodsTheRowsCannotResolveAreDroppedWithOneNote).
  EXPECT_EQ(
      test::run_post("floor-spectra " + run_dir.string() + " --short-periods refuse").exit_code, 2);

  const auto clipped = test::run_post("floor-spectra " + run_dir.string() +
                                      " --periods 0,0.1,0.5,1 --short-periods clip");
  ASSERT_EQ(clipped.exit_code, 0) << clipped.output;
  EXPECT_NE(clipped.output.find("dropped"), std::string::npos) << clipped.output;
  auto csv = read_csv(run_dir / "floor-spectra.csv");
  EXPECT_EQ(csv["period_s"], (std::vector<double>{0.0, 0.5, 1.0}));
  EXPECT_EQ(csv.count("b/floor 3 PSA [g]"), 1u);
  std::filesystem::remove_all(dir);
}

// (c') Rows every 1 ms from fixed 5 ms steps: the rows inside a step are interpolated, so the
// solver's analysis interval (5 ms) sets the rule (T >= 0.05 s): 0.02 s is refused, naming
// analysis.dt, though the rows alone would allow T >= 0.01 s.
TEST(PostFloorSpectra, RowsDenserThanTheStepsDoNotRelaxTheRule) {
  const auto dir = test::scratch_dir("floor-steps");
  const auto run_dir =
      solve(dir, building_2d("600 MN/m", kPulse6s,
                             "{interval: 0.001 s}\nanalysis: {stepping: fixed, dt: 0.005 s}"));
  const RunData run = read_run(run_dir);
  const HistorySampling h = history_sampling(run);
  EXPECT_DOUBLE_EQ(h.row_interval, 0.001);
  EXPECT_DOUBLE_EQ(h.effective(), 0.005);
  const auto refused = test::run_post("floor-spectra " + run_dir.string() + " --periods 0,0.02,1");
  EXPECT_EQ(refused.exit_code, 2) << refused.output;
  EXPECT_NE(refused.output.find("analysis.dt"), std::string::npos) << refused.output;
  EXPECT_NE(refused.output.find("output.interval"), std::string::npos) << refused.output;
  const auto ok = test::run_post("floor-spectra " + run_dir.string() + " --periods 0,0.05,1");
  EXPECT_EQ(ok.exit_code, 0) << ok.output;
  std::filesystem::remove_all(dir);
}

// (d) 3D: a symmetric building under a pair at angle 0 does not rotate, so every plan corner
// has the centre of mass's spectra (to round-off: the corner's acceleration differs by
// |p| a_theta); RotD100 >= max(x, y) (theta = 0 and 90 deg are among the 180 angles; cos 90 deg
// is 6e-17, hence 1e-12) and RotD50 <= RotD100.
TEST(PostFloorSpectra, ThreeDCornersOfANonRotatingBuildingMatchTheCentre) {
  const auto dir = test::scratch_dir("floor-3d");
  const auto run_dir = solve(dir, building_3d("", "0 deg"));
  const RunData run = read_run(run_dir);
  ASSERT_TRUE(run.three_d);
  FloorSpectraOptions o;
  o.periods = periods_from_50ms();
  const FloorSpectra f = floor_spectra(run, o);
  ASSERT_EQ(f.places.size(), 3u * 5u);  // base + 2 floors, CM + 4 corners each
  double worst_corner = 0.0, worst_rotd = 1e300, worst_line = 0.0;
  for (std::size_t level = 0; level < 3; ++level) {
    const PlaceSpectra& cm = f.places[5 * level];
    ASSERT_NE(cm.label.find("/CM"), std::string::npos) << cm.label;
    for (std::size_t c = 1; c < 5; ++c) {
      const PlaceSpectra& corner = f.places[5 * level + c];
      ASSERT_NE(corner.label.find("/corner"), std::string::npos) << corner.label;
      EXPECT_GT(std::hypot(corner.p_W->x, corner.p_W->y), 8.0);
      for (std::size_t i = 0; i < o.periods.size(); ++i) {
        const double d = std::max({relative(corner.x.psa[i], cm.x.psa[i]),
                                   relative(corner.y->psa[i], cm.y->psa[i]),
                                   relative(corner.rotd->psa100[i], cm.rotd->psa100[i])});
        worst_corner = std::max(worst_corner, d);
        EXPECT_LE(d, 1e-9) << corner.label << " T = " << o.periods[i];
      }
    }
  }
  std::vector<const PlaceSpectra*> all{&f.ground};
  for (const PlaceSpectra& p : f.places) all.push_back(&p);
  for (const PlaceSpectra* p : all)
    for (std::size_t i = 0; i < o.periods.size(); ++i) {
      const double xy = std::max(p->x.psa[i], p->y->psa[i]);
      worst_rotd = std::min(worst_rotd, p->rotd->psa100[i] / xy - 1.0);
      EXPECT_GE(p->rotd->psa100[i], xy * (1 - 1e-12)) << p->label << " T = " << o.periods[i];
      EXPECT_LE(p->rotd->psa50[i], p->rotd->psa100[i]) << p->label;
      // a_y = a_x / 2 in phase and an isotropic building: the motion stays on the line at
      // atan(1/2) = 26.57 deg, so RotD100 = hypot(x, y) to the 1-deg grid (1 - cos 0.5 deg =
      // 3.8e-5) and RotD50 = hypot / sqrt(2) (the median |cos| over the angles; 0.5 deg of grid:
      // 0.9 %).
      const double line = std::hypot(p->x.psa[i], p->y->psa[i]);
      EXPECT_NEAR(p->rotd->psa100[i], line, 4e-5 * line) << p->label << " T = " << o.periods[i];
      EXPECT_NEAR(p->rotd->psa50[i], line / std::sqrt(2.0), 1e-2 * line)
          << p->label << " T = " << o.periods[i];
      worst_line = std::max(worst_line, relative(p->rotd->psa100[i], line));
    }
  std::printf(
      "[ floor ] 3D: corners vs CM largest relative %.2e; min RotD100/max(x,y) - 1 = "
      "%.2e; RotD100 vs hypot(x, y) %.2e; roof CM at T = %.3f s: RotD100 %.4f g, x %.4f g, y "
      "%.4f g\n",
      worst_corner, worst_rotd, worst_line, o.periods[23], f.places[10].rotd->psa100[23] / kGravity,
      f.places[10].x.psa[23] / kGravity, f.places[10].y->psa[23] / kGravity);
  // The y response is not zero (the pair acts in both directions), so RotD is a real check.
  EXPECT_GT(f.places[10].y->psa[23], 0.2 * f.places[10].x.psa[23]);
  std::filesystem::remove_all(dir);
}

// (e) The corner convention against the solver: an eccentric building (centre of mass 1.2 m, 0.6 m
// off the origin) rotates; the zero-period ordinate (the peak of the history) of every plan point,
// in x and y, equals the solver's own peak absolute acceleration of that point (summary.json,
// buildings_3d levels, taken at every analysis step): at most that (rows are a subset of the
// steps, 9 digits) and within 1 % (rows every 5 ms, steps 2.5 ms: a sampled peak of a pulse
// response). The other sign (a_x + p_y a_theta) moves a corner's x peak by about 10 %.
TEST(PostFloorSpectra, ThreeDPlanPointsPeakAsTheSolversProbes) {
  const auto dir = test::scratch_dir("floor-ecc");
  const auto run_dir = solve(dir, building_3d("    eccentricity: [1.2 m, 0.6 m]\n", "20 deg"));
  const RunData run = read_run(run_dir);
  FloorSpectraOptions o;
  o.periods = {0.0, 0.5, 1.0};
  const FloorSpectra f = floor_spectra(run, o);
  const nlohmann::json& levels = run.summary.at("buildings_3d").at(0).at("levels");
  ASSERT_EQ(f.places.size(), levels.size() * 5);
  double worst = 0.0, corner_spread = 0.0;
  for (std::size_t l = 0; l < levels.size(); ++l) {
    std::vector<const nlohmann::json*> points{&levels[l].at("centre_of_mass")};
    for (const nlohmann::json& c : levels[l].at("corners")) points.push_back(&c);
    ASSERT_EQ(points.size(), 5u);
    for (std::size_t k = 0; k < 5; ++k) {
      const PlaceSpectra& p = f.places[5 * l + k];
      const nlohmann::json& peaks = points[k]->at("absolute_acceleration");
      if (k > 0) {
        EXPECT_EQ(p.label.substr(p.label.rfind('/') + 1), points[k]->at("label"));
      }
      for (const auto& [ours, axis] : {std::pair{p.x.psa[0], "x"}, {p.y->psa[0], "y"}}) {
        const double solver = peaks.at(axis).at("value").get<double>();
        EXPECT_LE(ours, solver * (1 + 1e-8)) << p.label << " " << axis;
        EXPECT_GE(ours, solver * 0.99) << p.label << " " << axis;
        worst = std::max(worst, relative(ours, solver));
      }
      if (k > 0)
        corner_spread = std::max(corner_spread, relative(p.x.psa[0], f.places[5 * l].x.psa[0]));
    }
  }
  std::printf(
      "[ floor ] 3D eccentric: point peaks vs the solver's probes largest relative %.2e; "
      "corners differ from the CM by up to %.1f %%\n",
      worst, 100 * corner_spread);
  EXPECT_GT(corner_spread, 0.05);  // the building does rotate
  std::filesystem::remove_all(dir);
}

// (f) A default 3D run (rows at every record sample, 5 ms) with the default periods: a default
// never refuses. Exactly the default periods below 10 row intervals (the rule, from the intervals
// in summary.json) are dropped, the rest computed, one note names output.interval; periods given
// that the rows cannot resolve stay an error.
TEST(PostFloorSpectra, DefaultPeriodsTheRowsCannotResolveAreDroppedWithOneNote) {
  const auto dir = test::scratch_dir("floor-default");
  std::string model = building_3d("", "0 deg");
  model.erase(model.find("output: {interval: 0 s}\n"));  // the default: every record sample
  write_file(dir / "model.yaml", model);
  const auto run_dir = dir / "run";
  auto r = test::run_solver("run -q " + (dir / "model.yaml").string() + " --until '1 s' -o " +
                            run_dir.string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  std::ifstream summary_file(run_dir / "summary.json");
  const auto settings = nlohmann::json::parse(summary_file).at("settings");
  const double dt = std::max(settings.at("output_interval_s").get<double>(),
                             settings.value("analysis_interval_s", 0.0));
  EXPECT_DOUBLE_EQ(dt, 0.005);
  std::vector<double> kept, dropped;
  for (double t : default_periods())
    (t == 0.0 || t >= 10 * dt * (1 - 1e-9) ? kept : dropped).push_back(t);
  ASSERT_FALSE(dropped.empty());

  r = test::run_post("floor-spectra " + run_dir.string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const std::regex note(
      "isopound-post: note: ([0-9]+) of the default periods[^\n]*output\\.interval");
  std::smatch m;
  ASSERT_TRUE(std::regex_search(r.output, m, note)) << r.output;
  EXPECT_EQ(std::stoul(m[1]), dropped.size());
  std::size_t notes = 0;
  for (std::size_t at = r.output.find("note:"); at != std::string::npos;
       at = r.output.find("note:", at + 1))
    ++notes;
  EXPECT_EQ(notes, 1u) << r.output;
  auto csv = read_csv(run_dir / "floor-spectra.csv");
  ASSERT_EQ(csv["period_s"].size(), kept.size());
  for (std::size_t i = 0; i < kept.size(); ++i)
    EXPECT_NEAR(csv["period_s"][i], kept[i], 1e-9 * kept[i]) << i;
  std::printf(
      "[ floor ] default periods on rows every %g s: %zu dropped (%g s to %g s), %zu kept\n", dt,
      dropped.size(), dropped.front(), dropped.back(), kept.size());

  // Periods given: kept as given or refused.
  r = test::run_post("floor-spectra " + run_dir.string() + " --periods 0,0.02,1 -o " +
                     (dir / "given").string());
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("output.interval"), std::string::npos) << r.output;
  std::filesystem::remove_all(dir);
}

// (h) output.floor_spectra: true writes every step's accelerations; where the rows are the steps
// (fixed 1 ms steps, a row every 1 ms) the spectra from the steps equal those from the rows, in
// 3D at the centre, the corners and RotD: the same straight lines, the same recurrence, one
// sub-step per step for T >= 0.06 s. The rows keep 9 digits (%.9g), the steps every digit, the
// CSV 10: 1e-7 relative.
TEST(PostFloorSpectra, StepSpectraEqualRowSpectraWhereTheRowsAreTheSteps) {
  const auto dir = test::scratch_dir("floor-steps-rows");
  std::string model = building_3d("", "30 deg");
  model.replace(model.find("output: {interval: 0 s}"), 23,
                "analysis: {stepping: fixed, dt: 1 ms}\n"
                "output: {interval: 1 ms, floor_spectra: true}");
  const auto run_dir = solve(dir, model);
  ASSERT_TRUE(std::filesystem::exists(run_dir / "step-accelerations.csv"));
  std::vector<double> periods{0.0};
  for (int i = 0; i < 20; ++i) periods.push_back(0.06 * std::pow(50.0, i / 19.0));
  std::string list;
  for (double t : periods) {
    if (!list.empty()) list += ',';
    list += std::to_string(t);
  }
  const auto steps =
      test::run_post("floor-spectra " + run_dir.string() + " --from steps --periods " + list +
                     " -o " + (dir / "steps").string());
  ASSERT_EQ(steps.exit_code, 0) << steps.output;
  EXPECT_NE(steps.output.find("every analysis step"), std::string::npos) << steps.output;
  EXPECT_EQ(steps.output.find("note:"), std::string::npos) << steps.output;
  const auto rows = test::run_post("floor-spectra " + run_dir.string() + " --from rows --periods " +
                                   list + " -o " + (dir / "rows").string());
  ASSERT_EQ(rows.exit_code, 0) << rows.output;
  auto a = read_csv(dir / "steps" / "floor-spectra.csv");
  auto b = read_csv(dir / "rows" / "floor-spectra.csv");
  ASSERT_EQ(a.size(), b.size());
  ASSERT_GT(a.size(), 40u);  // ground + 3 levels x (CM + 4 corners), 8 columns each
  double worst = 0.0;
  for (const auto& [name, values] : a) {
    ASSERT_EQ(values.size(), b[name].size()) << name;
    for (std::size_t i = 0; i < values.size(); ++i) {
      const double d = relative(values[i], b[name][i]);
      if (b[name][i] == 0.0) continue;  // SD at T = 0
      worst = std::max(worst, d);
      EXPECT_LE(d, 1e-7) << name << " T = " << a["period_s"][i];
    }
  }
  std::printf("[ floor ] steps = rows (fixed 1 ms): largest difference %.2e over %zu columns\n",
              worst, a.size());
  // Without the key no file, and a stale one is removed by the next run in the same folder.
  model.replace(model.find(", floor_spectra: true"), 21, "");
  solve(dir, model);
  EXPECT_FALSE(std::filesystem::exists(run_dir / "step-accelerations.csv"));
  std::filesystem::remove_all(dir);
}

// (i) The point of the steps (issue 38): an adaptive pounding run with rows every 5 ms. Its
// spectra from every step are within 1 % of the spectra from rows every 0.1 ms of the same run
// (the same steps; such rows are the steps' straight lines sampled 50 times finer than the
// record; a step ends between two such rows at most 0.1 ms from one) at every level and every
// default period, 0.02 s to 10 s, where its own rows cannot give the periods below 0.05 s at all
// and smooth the impacts at the ones they keep.
TEST(PostFloorSpectra, StepSpectraOfAPoundingRunMatchDenseRows) {
  const auto dir = test::scratch_dir("floor-pounding");
  const std::string model = R"(building:
  name: main
  base: {mass: 340 t}
  floors: {count: 3, mass: 340 t, roof_mass: 250 t, stiffness: 600 MN/m, height: 3.2 m}
  isolator: {model: bouc_wen, Tb: 2 s, QW: 5 %, uy: 1 cm}
  walls: {gap: 5 cm, law: kelvin_voigt, k: 2500 kN/mm, e: 0.7, mass: 500 t}
ground_motion:
  pulse: {amplitude: 0.8 m/s, period: 1.5 s, t_peak: 3 s, duration: 6 s, dt: 5 ms}
  extra_time: 0 s
output: )";
  write_file(dir / "coarse.yaml", model + "{interval: 5 ms, floor_spectra: true}\n");
  write_file(dir / "dense.yaml", model + "{interval: 0.1 ms}\n");
  for (const char* name : {"coarse", "dense"}) {
    const auto r = test::run_solver("run -q " + (dir / (std::string(name) + ".yaml")).string() +
                                    " -o " + (dir / name).string());
    ASSERT_EQ(r.exit_code, 0) << r.output;
  }
  const auto steps = test::run_post("floor-spectra " + (dir / "coarse").string());
  ASSERT_EQ(steps.exit_code, 0) << steps.output;
  const auto coarse_rows = test::run_post("floor-spectra " + (dir / "coarse").string() +
                                          " --from rows -o " + (dir / "coarse-rows").string());
  ASSERT_EQ(coarse_rows.exit_code, 0) << coarse_rows.output;
  // The dense rows sample the steps' straight lines (rows inside a step are interpolated
  // linearly): every period may be read from them (--samples-per-period 1 lifts the rule, which
  // guards rows coarser than the motion).
  const auto dense =
      test::run_post("floor-spectra " + (dir / "dense").string() + " --samples-per-period 1");
  ASSERT_EQ(dense.exit_code, 0) << dense.output;
  auto a = read_csv(dir / "coarse" / "floor-spectra.csv");
  auto r = read_csv(dir / "coarse-rows" / "floor-spectra.csv");
  auto b = read_csv(dir / "dense" / "floor-spectra.csv");
  ASSERT_EQ(a["period_s"], b["period_s"]);  // every default period, from both
  double worst = 0.0, worst_rows = 0.0;
  for (const auto& [name, values] : a) {
    if (name.find(" PSA [g]") == std::string::npos) continue;
    for (std::size_t i = 0; i < values.size(); ++i) {
      const double d = relative(values[i], b[name][i]);
      worst = std::max(worst, d);
      EXPECT_LE(d, 0.01) << name << " T = " << a["period_s"][i];
    }
    // The coarse rows keep the periods from 0.05 s: the same periods, offset in the dense list.
    const std::size_t offset = b["period_s"].size() - r["period_s"].size();
    for (std::size_t i = 1; i < r[name].size(); ++i)
      worst_rows = std::max(worst_rows, relative(r[name][i], b[name][i + offset]));
  }
  std::printf(
      "[ floor ] pounding run: PSA from every step within %.3f %% of rows every 0.1 ms; "
      "from its own 5 ms rows within %.1f %%\n",
      100 * worst, 100 * worst_rows);

  // The step file is the solver's own acceleration: its straight lines integrate (trapezoid, the
  // average-acceleration Newmark update) to the solver's relative velocity at the end of the run,
  // the impulse of every wall impact included; rows cut the corners of the impulse spikes and
  // need not. Tolerance 1e-3 of the DOF's peak velocity: the Newton residual left at each step
  // (3D demo: 1.4e-4 at the struck base slab, 1e-11 at the floors).
  const auto step = read_csv(dir / "coarse" / "step-accelerations.csv");
  const auto hist = read_csv(dir / "coarse" / "histories.csv");
  const std::vector<double>& ts = step.at("time [s]");
  const std::vector<double>& ag = step.at("ground_acceleration [m/s2]");
  int dofs = 0;
  for (const auto& [name, a] : step) {
    const auto at = name.find(" a_abs [m/s2]");
    if (at == std::string::npos) continue;
    const std::vector<double>& v = hist.at(name.substr(0, at) + " v [m/s]");
    double integral = 0.0;
    for (std::size_t k = 0; k + 1 < ts.size(); ++k)
      integral += 0.5 * (a[k] - ag[k] + a[k + 1] - ag[k + 1]) * (ts[k + 1] - ts[k]);
    double peak = 0.0;
    for (double x : v) peak = std::max(peak, std::abs(x));
    EXPECT_NEAR(integral, v.back(), 1e-3 * peak) << name;
    ++dofs;
  }
  EXPECT_EQ(dofs, 4);  // the base and 3 floors (a wall writes no a_abs)
  std::filesystem::remove_all(dir);
}

// (g) --damping is a damping ratio read like the model files' damping.ratio: '5 %', 5% and 0.05
// give the same CSV byte for byte (the default too), which records the ratio in every row; 2 %
// gives larger ordinates; a bare 5 (500 %) is refused with exit 2 and the table's hint.
TEST(PostFloorSpectra, DampingTakesAUnitAndTheCsvRecordsIt) {
  const auto dir = test::scratch_dir("floor-damping");
  const auto run_dir = solve(dir, building_2d("600 MN/m", kPulse6s, "{interval: 0 s}"));
  const std::string args = "floor-spectra " + run_dir.string() + " --periods '0,50 ms,0.2,1 s,2'";
  test::same_text_for_every_five_percent(args, dir, "floor-spectra.csv");
  test::run_post(args + " --damping '2 %' -o " + (dir / "two").string());
  auto five = read_csv(dir / "0.05" / "floor-spectra.csv");
  EXPECT_EQ(five["period_s"], (std::vector<double>{0.0, 0.05, 0.2, 1.0, 2.0}));
  EXPECT_EQ(five["damping_ratio"], std::vector<double>(5, 0.05));
  auto two = read_csv(dir / "two" / "floor-spectra.csv");
  EXPECT_EQ(two["damping_ratio"], std::vector<double>(5, 0.02));
  ASSERT_EQ(two["b/floor 3 PSA [g]"].size(), 5u);
  ASSERT_EQ(five["b/floor 3 PSA [g]"].size(), 5u);
  for (std::size_t i = 1; i < 5; ++i)
    EXPECT_GT(two["b/floor 3 PSA [g]"][i], five["b/floor 3 PSA [g]"][i]) << five["period_s"][i];

  const auto bare = test::run_post("floor-spectra " + run_dir.string() + " --damping 5 -o " +
                                   (dir / "never").string());
  EXPECT_EQ(bare.exit_code, 2) << bare.output;
  EXPECT_NE(bare.output.find("--damping"), std::string::npos) << bare.output;
  EXPECT_NE(bare.output.find("did you mean '5 %'?"), std::string::npos) << bare.output;
  EXPECT_FALSE(std::filesystem::exists(dir / "never"));
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace isopound::post
