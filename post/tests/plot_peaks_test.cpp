// Plots that agree with the numbers: a 2D pounding run under the built-in pulse (no ../shared),
// histories every 20 ms, so the drawn impact and base-acceleration curves peak well below the
// run; every time-history panel marks summary.json's peak (value and time) with a diamond and its
// label, and the PNG has the marker's colour at that place. Spectra of a set: the band is
// exp(mean ln ± σ_ln), computed here independently, and positive.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>

#include "post/headless.h"
#include "post/plot_run.h"
#include "post/plot_spectra.h"
#include "post/render_png.h"
#include "post/run_data.h"
#include "post/spectra.h"
#include "post_test_support.h"
#include "solver/core/constants.h"

namespace isopound::post {
namespace {

// The chapter-4 building between walls 10 cm away, a strong pulse, histories every 20 ms.
constexpr const char* kPounding = R"(building:
  name: b
  base: {mass: 340 t}
  floors: {count: 2, mass: 340 t, stiffness: 600 MN/m, height: 3.2 m}
  isolator: {model: bouc_wen, Tb: 2.0 s, QW: 5 %, uy: 1 cm, n: 2, A: 1, beta: 0.5, gamma: 0.5}
  damping:
    superstructure: {type: rayleigh, ratio: 2 %, modes: [1, 2]}
    isolation: 5 %
  walls: {sides: both, level: 0, gap: 10 cm, mass: 500 t, law: kelvin_voigt, k: 2500 kN/mm, e: 0.7}
ground_motion: {pulse: {amplitude: 1.0 m/s, period: 1.5 s, t_peak: 2 s, dt: 0.005 s, duration: 5 s}}
output: {interval: 0.02 s}
)";

std::string fmt(const char* f, double a, double b) {
  char buf[96];
  std::snprintf(buf, sizeof buf, f, a, b);
  return buf;
}

// The Figure's marker whose centroid is nearest `at` (px) and that distance.
double nearest_marker(const Figure& fig, Point2 at, Rgb* fill) {
  double best = 1e30;
  for (const Marker& m : fig.markers) {
    Point2 c;
    for (const Point2& p : m.points) c.x += p.x, c.y += p.y;
    c.x /= m.points.size(), c.y /= m.points.size();
    const double d = std::hypot(c.x - at.x, c.y - at.y);
    if (d < best) best = d, *fill = m.fill;
  }
  return best;
}

bool has_text(const Figure& fig, const std::string& text) {
  for (const Text& t : fig.texts)
    if (t.text == text) return true;
  return false;
}

TEST(PostPlotPeaks, EveryTimeHistoryPanelMarksSummaryPeakWithValueAndTimeAtItsPlace) {
  const auto dir = test::scratch_dir("peaks2d");
  std::ofstream(dir / "b.yaml") << kPounding;
  auto r = test::run_solver("run " + (dir / "b.yaml").string() + " -o " + (dir / "run").string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  std::ifstream sj(dir / "run" / "summary.json");
  const auto summary = nlohmann::json::parse(sj);
  const auto& levels = summary["structures"][0]["levels"];
  const auto& stories = summary["structures"][0]["stories"];
  const nlohmann::json* wall = nullptr;
  for (const auto& e : summary["elements"])
    if (e["label"] == "b/wall left (base)" || e["label"] == "b/wall right (base)")
      if (!wall || e["peak_force"]["value"] > (*wall)["peak_force"]["value"]) wall = &e;
  ASSERT_TRUE(wall);
  ASSERT_GT((*wall)["peak_force"]["value"].get<double>(), 0.0) << "the run must pound";

  const RunData run = read_run(dir / "run");
  const std::vector<NamedFigure> figures = run_figures(run);
  ASSERT_FALSE(figures.empty());
  const NamedFigure& th = figures.front();
  ASSERT_EQ(th.file, "time_histories.png");
  // Ground and base, drifts, the base's acceleration, the floors' and ground's, impacts.
  ASSERT_EQ(th.frames.size(), 5u);
  EXPECT_NE(th.figure.texts.front().text.find("histories.csv every 20 ms"), std::string::npos)
      << th.figure.texts.front().text;

  // The largest peak of each panel, as summary.json has it, in the panel's unit.
  struct Expected {
    std::size_t panel;
    nlohmann::json peak;
    double divisor;
    const char* text;  // printf of value and time
  };
  const nlohmann::json& base = levels[0];
  double best_drift = 0.0;
  nlohmann::json drift;
  for (const auto& s : stories)
    if (s["drift_ratio"]["value"].get<double>() > best_drift)
      best_drift = s["drift_ratio"]["value"], drift = s["drift_ratio"];
  const std::vector<Expected> expected{
      {0, base["displacement"], 0.01, "peak %.4g cm at %.3f s (summary.json)"},
      {1, drift, 0.01, "peak %.4g %% at %.3f s (summary.json)"},
      {2, base["absolute_acceleration"], kGravity, "peak %.4g g at %.3f s (summary.json)"},
      {4, (*wall)["peak_force"], 1e6, "peak %.4g MN at %.3f s (summary.json)"}};
  std::string force_unit;
  ASSERT_EQ(force_scale((*wall)["peak_force"]["value"].get<double>(), force_unit), 1e6);
  const auto png = dir / "th.png";
  const PrivateDisplay display(false);
  render_png(th.figure, png.string());
  const test::Image image = test::read_png(png.string());
  for (const Expected& e : expected) {
    const double value = e.peak["value"].get<double>(), time = e.peak["time_s"].get<double>();
    // The signed extreme: summary.json's negative when it is the larger.
    const double y = (-e.peak["negative"].get<double>() >= value ? -value : value) / e.divisor;
    SCOPED_TRACE("panel " + std::to_string(e.panel));
    EXPECT_TRUE(has_text(th.figure, fmt(e.text, value / e.divisor, time)))
        << fmt(e.text, value / e.divisor, time);
    const Point2 at = th.frames[e.panel].to_pixel(time, y);
    Rgb fill;
    EXPECT_LT(nearest_marker(th.figure, at, &fill), 1e-9);
    // The PNG: the marker's fill at its centre, and a sampled curve that peaks lower (every 20 ms;
    // impacts last milliseconds) does not reach it there.
    const unsigned char* px =
        image.at(static_cast<int>(std::lround(at.x)), static_cast<int>(std::lround(at.y)));
    EXPECT_LE(std::abs(px[0] - fill.r) + std::abs(px[1] - fill.g) + std::abs(px[2] - fill.b), 6)
        << int(px[0]) << "," << int(px[1]) << "," << int(px[2]);
  }
  // The floors and the ground set their acceleration panel's axis, not the base's impacts; the
  // peak texts are clear of the legends and of each other.
  double floors = 0.0;
  for (std::size_t k = 1; k < levels.size(); ++k)
    floors = std::max(floors, levels[k]["absolute_acceleration"]["value"].get<double>() / kGravity);
  const double pga = summary["ground_motion"]["pga_m_s2"].get<double>() / kGravity;
  const double base_a = base["absolute_acceleration"]["value"].get<double>() / kGravity;
  // 7.8 g against 5.3 g: the base in the panel would raise its top above 1.5 x 7.8 g.
  ASSERT_GT(base_a, 1.4 * floors);
  EXPECT_GE(th.frames[3].y_hi, std::max(floors, pga));
  EXPECT_LE(th.frames[3].y_lo, -std::max(floors, pga));
  EXPECT_LT(th.frames[3].y_hi, 2.0 * floors);
  test::expect_labels_clear(th);
  // The sampled curves peak lower than the run: the marks are needed.
  double drawn = 0.0;
  for (const ElementColumns& c : run.contacts)
    drawn = std::max(drawn, peak_of(run.column(c.force)));
  EXPECT_LT(drawn, (*wall)["peak_force"]["value"].get<double>());
  const double drawn_a = peak_of(run.column(run.structures[0].levels[0].a_abs));
  EXPECT_LT(drawn_a, 0.9 * base["absolute_acceleration"]["value"].get<double>());  // 65.5 vs 76.5
  // Storeys are named by their levels; the ground is drawn.
  EXPECT_TRUE(has_text(th.figure, "storey 1 (base–floor 1) — peak " +
                                      fmt("%.4g %% at %.3f s",
                                          stories[0]["drift_ratio"]["value"].get<double>() / 0.01,
                                          stories[0]["drift_ratio"]["time_s"].get<double>())));
  bool ground = false;
  for (const Text& t : th.figure.texts) ground = ground || t.text.rfind("ground (", 0) == 0;
  EXPECT_TRUE(ground);
  std::filesystem::remove_all(dir);
}

TEST(PostSpectraSet, BandIsExpOfMeanLnPlusMinusSigmaLnAndPositive) {
  // Three records of different scale: the arithmetic mean - sigma went below 0 here.
  std::vector<Spectrum> set{{"a", {0.0, 0.5, 1.0}, {0.0, 0.01, 0.05}, {3.0, 8.0, 2.0}},
                            {"b", {0.0, 0.5, 1.0}, {0.0, 0.20, 0.90}, {1.0, 0.5, 30.0}},
                            {"c", {0.0, 0.5, 1.0}, {0.0, 0.02, 0.10}, {0.2, 1.0, 1.5}}};
  const SpectrumStatistics st = spectrum_statistics(set);
  for (std::size_t i = 0; i < 3; ++i) {
    double m = 0.0, ss = 0.0, am = 0.0, as = 0.0;
    for (const Spectrum& s : set) m += std::log(s.psa[i]) / 3.0, am += s.psa[i] / 3.0;
    for (const Spectrum& s : set)
      ss += std::pow(std::log(s.psa[i]) - m, 2), as += std::pow(s.psa[i] - am, 2);
    const double sg = std::sqrt(ss / 2.0);
    EXPECT_NEAR(st.median_psa[i], std::exp(m), 1e-12 * std::exp(m));
    EXPECT_NEAR(st.sigma_ln_psa[i], sg, 1e-12);
    EXPECT_NEAR(st.lower_psa[i], std::exp(m - sg), 1e-12 * std::exp(m));
    EXPECT_NEAR(st.upper_psa[i], std::exp(m + sg), 1e-12 * std::exp(m));
    EXPECT_GT(st.lower_psa[i], 0.0);
    if (i == 1) {
      EXPECT_LT(am - std::sqrt(as / 2.0), 0.0) << "the old band was negative here";
    }
  }
  EXPECT_EQ(st.median_sd[0], 0.0);  // SD(T = 0) = 0: no log statistics
  EXPECT_GT(st.lower_sd[1], 0.0);

  // The figure: each record named in the legend; the band's curves are the statistics, > 0.
  std::vector<PanelFrame> frames;
  const Figure fig = spectra_figure(set, st, {}, 5.0, &frames);
  for (const char* name : {"a", "b", "c", "median exp(mean ln)", "exp(mean ln ± σ_ln)"})
    EXPECT_TRUE(has_text(fig, name)) << name;
  ASSERT_EQ(frames.size(), 2u);
  // Log-log axes: a value <= 0 would not be drawn. Every curve of the PSA panel has a point at
  // both periods > 0 (2 points; T = 0 is off a log axis), and the band's lower curve is drawn
  // at exp(mean ln - sigma_ln) of both.
  ASSERT_TRUE(frames[0].log_x && frames[0].log_y);
  int curves = 0, lower = 0;
  for (const Polyline& l : fig.lines) {
    if (l.points.size() != 2 || l.points[0].x == l.points[1].x || l.points[0].y == l.points[1].y ||
        l.points[0].x > frames[0].left + frames[0].width)
      continue;  // grid lines, ticks, the other panel
    ++curves;
    bool is_lower = true;
    for (std::size_t i = 1; i < 3; ++i) {
      const Point2 want = frames[0].to_pixel(set[0].period[i], st.lower_psa[i] / kGravity);
      is_lower = is_lower && std::abs(l.points[i - 1].x - want.x) < 1e-9 &&
                 std::abs(l.points[i - 1].y - want.y) < 1e-9;
    }
    lower += is_lower;
  }
  EXPECT_EQ(curves, 3 + 3);  // records, median, upper, lower
  EXPECT_EQ(lower, 1);
}

}  // namespace
}  // namespace isopound::post
