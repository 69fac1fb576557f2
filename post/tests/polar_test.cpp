// Polar figures: a synthetic envelope with its maximum at 75 deg is drawn with its farthest pixel
// at 75 deg; a synthetic contour's peak lands in the right sector and ring; the polar command
// reads a study database and fails clearly without an angle axis or with an unknown quantity.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <numbers>

#include "post/headless.h"
#include "post/polar_plot.h"
#include "post/render_png.h"
#include "post_test_support.h"
#include "solver/study/study_store.h"

namespace isopound::post {
namespace {

constexpr double kPi = std::numbers::pi;

bool near_colour(const unsigned char* p, Rgb c, int tol) {
  return std::abs(p[0] - c.r) <= tol && std::abs(p[1] - c.g) <= tol && std::abs(p[2] - c.b) <= tol;
}

TEST(PostPolar, EnvelopeMaximumAt75DegreesIsDrawnAt75Degrees) {
  const PrivateDisplay display(false);
  PolarEnvelopeData d;
  d.title = "synthetic";
  d.quantity = "u [cm]";
  PolarCurve c{"field", {}, {}, Rgb{220, 20, 20}, 2.0};
  // A smooth field 10 + 8 cos(theta - 75 deg)^... peaked at 75 deg (period 360 deg).
  for (int a = 0; a < 360; a += 5) {
    c.angle_deg.push_back(a);
    c.value.push_back(10.0 + 8.0 * std::exp(2.0 * (std::cos((a - 75.0) * kPi / 180) - 1.0)));
  }
  d.curves.push_back(c);
  PolarFrame frame;
  const Figure fig = polar_envelope_figure(d, 800, 700, &frame);
  const auto dir = test::scratch_dir("polar75");
  render_png(fig, (dir / "p.png").string());
  const test::Image img = test::read_png((dir / "p.png").string());
  ASSERT_EQ(img.width, 800);
  ASSERT_EQ(img.height, 700);
  EXPECT_GT(img.variance(), 50.0);
  // The red pixel farthest from the centre (inside the polar axes).
  double best = -1, best_angle = 0;
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x)
      if (near_colour(img.at(x, y), {220, 20, 20}, 40)) {
        const double dx = x + 0.5 - frame.centre.x, dy = y + 0.5 - frame.centre.y;
        const double r = std::hypot(dx, dy);
        if (r > frame.radius_px + 4) continue;  // the legend's sample line
        if (r > best) best = r, best_angle = std::atan2(dy, dx) * 180 / kPi;
      }
  ASSERT_GT(best, 0) << "no curve pixels";
  // The peak is flat over a few degrees at this sampling (5 deg) and line width (2 px): 3 deg.
  EXPECT_NEAR(best_angle, 75.0, 3.0);
  // ... and at the radius of the maximum value 18.
  EXPECT_NEAR(best, (18.0 - frame.r_lo) / (frame.r_hi - frame.r_lo) * frame.radius_px, 3.0);
  std::filesystem::remove_all(dir);
}

TEST(PostPolar, ContourPeakLandsInItsSectorAndRing) {
  const PrivateDisplay display(false);
  PolarContourData d;
  d.title = "synthetic contour";
  d.radius_title = "gap [cm]";
  d.value_title = "u [cm]";
  for (int a = 0; a < 360; a += 15) d.angle_deg.push_back(a);
  for (double g : {5.0, 10.0, 15.0, 20.0, 25.0}) d.radius.push_back(g);
  // Peak (value 1) at angle 135 deg, gap 15 cm; everything else lower.
  for (double g : d.radius)
    for (double a : d.angle_deg)
      d.value.push_back(std::exp(-std::pow((a - 135.0) / 40.0, 2) - std::pow((g - 15.0) / 8.0, 2)));
  PolarFrame f;
  const Figure fig = polar_contour_figure(d, 860, 700, &f);
  const auto dir = test::scratch_dir("contour");
  render_png(fig, (dir / "c.png").string());
  const test::Image img = test::read_png((dir / "c.png").string());
  ASSERT_EQ(img.width, 860);
  EXPECT_GT(img.variance(), 50.0);
  // Pixels of the top colour (the peak cell) inside the polar disc: their mean position.
  const Rgb top = colour_map(1.0);
  double sx = 0, sy = 0;
  int n = 0;
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x) {
      const double dx = x + 0.5 - f.centre.x, dy = y + 0.5 - f.centre.y;
      if (std::hypot(dx, dy) > f.radius_px) continue;
      if (near_colour(img.at(x, y), top, 6)) sx += dx, sy += dy, ++n;
    }
  ASSERT_GT(n, 20) << "peak cell not drawn";
  const double angle = std::atan2(sy / n, sx / n) * 180 / kPi;
  const double gap = f.r_lo + std::hypot(sx / n, sy / n) / f.radius_px * (f.r_hi - f.r_lo);
  EXPECT_NEAR(angle, 135.0, 7.5);  // within its sector (15 deg wide)
  EXPECT_NEAR(gap, 15.0, 2.5);     // within its ring (5 cm wide)
  std::filesystem::remove_all(dir);
}

// A small study database: axes record x angle (rad) [x gap], one output, values from a formula.
std::string make_study(const std::filesystem::path& dir, bool with_angle) {
  StoreLayout layout;
  layout.axes = with_angle ? std::vector<std::string>{"record", "angle", "gap"}
                           : std::vector<std::string>{"record", "gap"};
  layout.outputs = {"u_base", "F_impact"};
  const std::vector<std::string> records{"A", "B"};
  std::vector<double> angles;
  for (int a = 0; a < 360; a += 15) angles.push_back(a);
  const std::vector<double> gaps{0.05, 0.1, 0.15, 0.2, 0.25};
  const std::int64_t na = with_angle ? angles.size() : 1;
  const std::int64_t count = records.size() * na * gaps.size();
  const auto path = (dir / (with_angle ? "angles.db" : "noangle.db")).string();
  const auto cells = [&](std::int64_t c) {
    std::vector<Cell> v;
    const std::int64_t g = c % gaps.size(), a = (c / gaps.size()) % na, r = c / (gaps.size() * na);
    v.push_back({false, 0.0, records[r]});
    if (with_angle) v.push_back({true, angles[a] * kPi / 180, ""});
    v.push_back({true, gaps[g], ""});
    return v;
  };
  StudyStore store = StudyStore::create(path, layout, {}, count, cells);
  std::vector<RunRecord> runs;
  for (std::int64_t c = 0; c < count; ++c) {
    const std::vector<Cell> v = cells(c);
    const double a = with_angle ? v[1].number : 0.0;
    RunRecord r;
    r.case_id = c;
    r.ok = true;
    const double gap = v.back().number;
    r.values = {0.25 + 0.12 * std::cos(2 * (a - 75 * kPi / 180)) + (v[0].text == "B" ? 0.05 : 0.0),
                1e6 * (1 + std::cos(a - 75 * kPi / 180)) * (0.1 / gap)};
    runs.push_back(r);
  }
  store.commit(runs, store.begin_session(1, 1, false, count));
  return path;
}

TEST(PostPolar, CommandWritesEnvelopeAndContourFromAStudy) {
  const auto dir = test::scratch_dir("polarcli");
  const std::string db = make_study(dir, true);
  auto r = test::run_post("polar " + db + " --quantity u_base --unit cm --where gap=0.1 -o " +
                          (dir / "env").string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const test::Image img = test::read_png((dir / "env.png").string());
  EXPECT_EQ(img.width, 800);
  EXPECT_GT(img.variance(), 50.0);
  // CSV: 24 angles, columns A, B, mean, min, max; the mean at 60 deg from the formula.
  std::ifstream csv(dir / "env.csv");
  std::string header, line;
  std::getline(csv, header);
  EXPECT_EQ(header, "angle_deg,A,B,mean,min,max");
  int rows = 0;
  while (std::getline(csv, line)) {
    ++rows;
    if (line.rfind("60,", 0) == 0) {
      const double mean = std::stod(line.substr(line.find(',', line.find(',', 3) + 1) + 1));
      // In cm (--unit cm) from the SI values of the table.
      EXPECT_NEAR(mean, 100 * (0.25 + 0.12 * std::cos(-30 * kPi / 180) + 0.025), 1e-6);
    }
  }
  EXPECT_EQ(rows, 24);
  r = test::run_post("polar " + db + " --quantity F_impact --unit kN --contour gap -o " +
                     (dir / "con").string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_GT(test::read_png((dir / "con.png").string()).variance(), 50.0);
  // ISOPOUND_POST_EXAMPLES=DIR keeps the two figures (the README's synthetic polar examples).
  if (const char* keep = std::getenv("ISOPOUND_POST_EXAMPLES")) {
    std::filesystem::copy_file(dir / "env.png", std::filesystem::path(keep) / "polar-envelope.png",
                               std::filesystem::copy_options::overwrite_existing);
    std::filesystem::copy_file(dir / "con.png", std::filesystem::path(keep) / "polar-contour.png",
                               std::filesystem::copy_options::overwrite_existing);
  }
  std::filesystem::remove_all(dir);
}

TEST(PostPolar, CommandErrorsNameTheProblem) {
  const auto dir = test::scratch_dir("polarbad");
  const std::string no_angle = make_study(dir, false), with = make_study(dir, true);
  auto r = test::run_post("polar " + no_angle + " --quantity u_base");
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.output.find("no incidence-angle axis"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("record, gap"), std::string::npos) << r.output;
  r = test::run_post("polar " + with + " --quantity drift");
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.output.find("'drift' is not in the table; its quantities are: u_base, F_impact"),
            std::string::npos)
      << r.output;
  r = test::run_post("polar " + (dir / "missing.db").string() + " --quantity u_base");
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.output.find("not found"), std::string::npos) << r.output;
  r = test::run_post("polar " + with + " --quantity u_base --unit furlong");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.output.find("--unit 'furlong'"), std::string::npos) << r.output;
  r = test::run_post("polar " + with + " --quantity u_base --contour width");
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.output.find("'width' is not in the study"), std::string::npos) << r.output;
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace isopound::post
