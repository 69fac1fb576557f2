// Polar figures: a synthetic envelope with its maximum at 75 deg is drawn with its farthest pixel
// at 75 deg; a synthetic contour's peak lands in the right sector and ring; the polar command
// reads a study database and fails clearly without an angle axis or with an unknown quantity.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <numbers>

#include "post/headless.h"
#include "post/polar_plot.h"
#include "post/polar_study.h"
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
                          (dir / "env.png").string());
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
  // The title states the filter that chose the rows drawn.
  PolarStudyOptions where;
  where.quantity = "u_base";
  where.where = {{"gap", "0.1"}};
  EXPECT_EQ(read_polar_study(db, where).envelope.title,
            "u_base against incidence angle (where gap = 0.1)");
  // -o a directory, as for every command: the default names inside it.
  r = test::run_post("polar " + db + " --quantity u_base -o " + (dir / "figures").string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const std::string stem = std::filesystem::path(db).stem().string() + "-polar-u_base";
  EXPECT_TRUE(std::filesystem::exists(dir / "figures" / (stem + ".png"))) << r.output;
  EXPECT_TRUE(std::filesystem::exists(dir / "figures" / (stem + ".csv"))) << r.output;
  r = test::run_post("polar " + db + " --quantity F_impact --unit kN --contour gap -o " +
                     (dir / "con.png").string());
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

// An ensemble study: axes record x angle (rad), outputs u_base (member 0) and its ensemble
// statistics u_base_ens_min, _mean, _max, _std and the horizon, values from formulas (SI, m).
double ens_mean(double a_deg, int record) {
  return 0.20 + 0.05 * std::cos((a_deg - 75.0) * kPi / 180) + 0.03 * record;
}
std::string make_ensemble_study(const std::filesystem::path& dir, int records,
                                bool member0 = true) {
  StoreLayout layout;
  layout.axes = {"record", "angle"};
  // The study engine's naming (docs/studies.md, `ensemble: N`): c_ens_min, _mean, _max, _std.
  layout.outputs = {"u_base",         "u_base_ens_min", "u_base_ens_mean",
                    "u_base_ens_max", "u_base_ens_std", "ens_horizon_s"};
  if (!member0) layout.outputs[0] = "other";
  const std::int64_t na = 24, count = records * na;
  const auto cells = [&](std::int64_t c) {
    return std::vector<Cell>{{false, 0.0, std::string(1, static_cast<char>('A' + c / na))},
                             {true, (c % na) * 15.0 * kPi / 180, ""}};
  };
  const auto path =
      (dir / ("ensemble" + std::to_string(records) + (member0 ? "" : "s") + ".db")).string();
  StudyStore store = StudyStore::create(path, layout, {}, count, cells);
  std::vector<RunRecord> runs;
  for (std::int64_t c = 0; c < count; ++c) {
    const double m = ens_mean((c % na) * 15.0, static_cast<int>(c / na));
    RunRecord r;
    r.case_id = c;
    r.ok = true;
    r.values = {m + 0.01, m - 0.04, m, m + 0.06, 0.02, 3.5};
    runs.push_back(r);
  }
  store.commit(runs, store.begin_session(1, 1, false, count));
  return path;
}

TEST(PostPolar, EnsembleColumnsAreFoundBesideTheQuantityInEveryAcceptedSpelling) {
  const std::vector<std::string> outputs{"u",         "u_min",           "u_max",     "F.min",
                                         "F.mean",    "F.max",           "d_ens_min", "d_ens_max",
                                         "d_ens_std", "r_ensemble_mean", "u_base"};
  const EnsembleColumns u = ensemble_columns(outputs, "u");
  EXPECT_EQ(u.min, 1);
  EXPECT_EQ(u.max, 2);
  EXPECT_EQ(u.mean, -1);
  EXPECT_TRUE(u.band());
  const EnsembleColumns f = ensemble_columns(outputs, "F");
  EXPECT_EQ(f.min, 3);
  EXPECT_EQ(f.mean, 4);
  EXPECT_EQ(f.max, 5);
  const EnsembleColumns d = ensemble_columns(outputs, "d");
  EXPECT_EQ(d.min, 6);
  EXPECT_EQ(d.std, 8);
  EXPECT_TRUE(d.band());
  const EnsembleColumns r = ensemble_columns(outputs, "r");
  EXPECT_EQ(r.mean, 9);
  EXPECT_FALSE(r.band());
  EXPECT_FALSE(ensemble_columns(outputs, "u_base").band());  // "u_base" is not u's statistic
}

TEST(PostPolar, EnsembleBandIsShadedBetweenMinAndMaxWithTheMeanLineOnIt) {
  const PrivateDisplay display(false);
  const auto dir = test::scratch_dir("polarens");
  PolarStudyOptions opt;
  opt.quantity = "u_base";
  opt.unit = "cm";
  const std::string db = make_ensemble_study(dir, 1);
  const PolarStudyResult r = read_polar_study(db, opt);
  const PolarEnvelopeData& e = r.envelope;
  ASSERT_EQ(e.curves.size(), 1u);
  ASSERT_TRUE(e.mean.has_value());
  ASSERT_EQ(e.bands.size(), 1u);
  EXPECT_TRUE(e.band_angle_deg.empty());  // no min-max over curves: the band is the ensemble's
  ASSERT_EQ(e.bands[0].angle_deg.size(), 24u);
  for (std::size_t a = 0; a < 24; ++a) {
    const double m = 100 * ens_mean(15.0 * a, 0);
    EXPECT_NEAR(e.mean->value[a], m, 1e-9);
    EXPECT_NEAR(e.bands[0].lo[a], m - 4.0, 1e-9);
    EXPECT_NEAR(e.bands[0].hi[a], m + 6.0, 1e-9);
    EXPECT_NEAR(e.curves[0].value[a], m + 1.0, 1e-9);
  }
  EXPECT_EQ(r.csv.substr(0, r.csv.find('\n')), "angle_deg,A,min,mean,max");

  // Pixels along the 195 deg ray (a data angle, off the 30 deg spokes and the 15 deg tick
  // labels): band colour between min and max (away from the lines), background outside.
  PolarFrame f;
  render_png(polar_envelope_figure(e, 800, 700, &f), (dir / "band.png").string());
  const test::Image img = test::read_png((dir / "band.png").string());
  const double m = 100 * ens_mean(195.0, 0);
  const auto pixel = [&](double value) {
    const Point2 p = f.to_pixel(195.0, value);
    return img.at(static_cast<int>(p.x), static_cast<int>(p.y));
  };
  const double px_per_cm = f.radius_px / (f.r_hi - f.r_lo);
  ASSERT_GT(px_per_cm * 4.0, 12.0) << "band too thin to probe";
  const Rgb shade = e.bands[0].colour;
  EXPECT_TRUE(near_colour(pixel(m - 2.0), shade, 8));   // between min and the mean
  EXPECT_TRUE(near_colour(pixel(m + 3.5), shade, 8));   // between member 0 and max
  EXPECT_TRUE(near_colour(pixel(m), {0, 0, 0}, 60));    // the mean line (3 px, black)
  EXPECT_FALSE(near_colour(pixel(m - 6.0), shade, 8));  // below min
  EXPECT_FALSE(near_colour(pixel(m + 8.0), shade, 8));  // above max
  EXPECT_TRUE(near_colour(pixel(m + 8.0), {255, 255, 255}, 8));

  // Several records: one band and one ensemble-mean curve each, the mean over records on top.
  opt.unit = "m";
  const PolarStudyResult two = read_polar_study(make_ensemble_study(dir, 2), opt);
  ASSERT_EQ(two.envelope.curves.size(), 2u);
  ASSERT_EQ(two.envelope.bands.size(), 2u);
  EXPECT_EQ(two.envelope.curves[1].label, "B");
  EXPECT_NEAR(two.envelope.curves[1].value[5], ens_mean(75.0, 1), 1e-12);
  EXPECT_NEAR(two.envelope.mean->value[5], ens_mean(75.0, 0) + 0.015, 1e-12);
  EXPECT_NEAR(two.envelope.bands[1].hi[5], ens_mean(75.0, 1) + 0.06, 1e-12);
  EXPECT_EQ(two.csv.substr(0, two.csv.find('\n')),
            "angle_deg,A,A_min,A_mean,A_max,B,B_min,B_mean,B_max,mean");
  // The command draws it too (exit 0, a non-blank PNG).
  const auto cli = test::run_post("polar " + db + " --quantity u_base --unit cm -o " +
                                  (dir / "cli.png").string());
  ASSERT_EQ(cli.exit_code, 0) << cli.output;
  EXPECT_GT(test::read_png((dir / "cli.png").string()).variance(), 50.0);
  // ISOPOUND_POST_EXAMPLES=DIR keeps the figure (the README's synthetic ensemble example).
  if (const char* keep = std::getenv("ISOPOUND_POST_EXAMPLES"))
    std::filesystem::copy_file(dir / "cli.png", std::filesystem::path(keep) / "polar-ensemble.png",
                               std::filesystem::copy_options::overwrite_existing);
  std::filesystem::remove_all(dir);
}

TEST(PostPolar, ATableWithOnlyEnsembleStatisticsDrawsTheEnsembleMean) {
  const auto dir = test::scratch_dir("polarensonly");
  PolarStudyOptions opt;
  opt.quantity = "u_base";  // only u_base_ens_min, _mean, _max, _std are columns
  const std::string db = make_ensemble_study(dir, 1, false);
  const PolarStudyResult r = read_polar_study(db, opt);
  ASSERT_EQ(r.notes.size(), 1u);
  EXPECT_NE(r.notes[0].find("its ensemble mean 'u_base_ens_mean' is drawn"), std::string::npos);
  ASSERT_EQ(r.envelope.bands.size(), 1u);
  EXPECT_NEAR(r.envelope.curves[0].value[3], ens_mean(45.0, 0), 1e-12);
  // A name with no column and no statistics is still an error listing the columns.
  opt.quantity = "u";
  try {
    read_polar_study(db, opt);
    ADD_FAILURE() << "no error";
  } catch (const PolarStudyError& e) {
    EXPECT_NE(std::string(e.what()).find("its quantities are: other, u_base_ens_min"),
              std::string::npos)
        << e.what();
  }
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace isopound::post
