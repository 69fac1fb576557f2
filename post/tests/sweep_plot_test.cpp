// isopound-post sweep-plot on small real studies (isopound sweep, 2D, a 6 s pulse): the curves are
// the table's values exactly, one per --group level in study order; the ensemble band is the
// members' min-max that `isopound export` writes; bad input exits 2 naming the option and value;
// the PNG has one colour per curve.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>

#include "post/figure.h"
#include "post/headless.h"
#include "post/render_png.h"
#include "post/sweep_plot.h"
#include "post/sweep_plot_figure.h"
#include "post_test_support.h"
#include "solver/study/study_table.h"

namespace isopound::post {
namespace {

namespace fs = std::filesystem;

// 3 gaps x 2 QW x 3 variants (KV, soft, free), or with `ensemble` 3 gaps x 2 variants x 3 members.
std::string make_study(const fs::path& dir, bool ensemble) {
  const std::string model = (test::source_dir() / "configs" / "thesis-3storey-bw.yaml").string();
  std::string yaml = "name: tiny\nmodel: " + model + R"(
set:
  ground_motion.pulse: {amplitude: 0.8 m/s, period: 2 s, duration: 6 s, dt: 0.01 s}
  building.walls: {gap: 20 cm, law: kelvin_voigt, k: 2500 kN/mm, e: 0.7, mass: 500 t, sides: both}
axes:
)";
  if (!ensemble) yaml += "  - {path: building.isolator.QW, values: [5 %, 10 %]}\n";
  yaml += "  - {path: building.walls.gap, values: [10 cm, 15 cm, 20 cm]}\n";
  // A soft wall (k / 25) lets the base go much further than KV: curves apart for the pixel test.
  yaml +=
      "variants:\n  KV: {building.walls.law: kelvin_voigt}\n  soft: {building.walls.k: 100 "
      "kN/mm}\n";
  if (!ensemble) yaml += "  free: {building.walls: ~}\n";
  yaml += "outputs: {u_base: base.displacement, F_impact: wall*.force}\n";
  if (ensemble) yaml += "ensemble: 3\n";
  const std::string name = ensemble ? "ens" : "plain";
  std::ofstream(dir / (name + ".yaml")) << yaml;
  const std::string db = (dir / (name + ".db")).string();
  const auto r = test::run_solver("sweep '" + (dir / (name + ".yaml")).string() +
                                  "' -q -j 2 --db '" + db + "'");
  EXPECT_EQ(r.exit_code, 0) << r.output;
  return db;
}

// The study's row at these axis texts (numbers as the table holds them).
const StudyTableRow* row_at(const StudyTable& t, const std::map<std::string, std::string>& at) {
  for (const StudyTableRow& r : t.rows) {
    bool all = true;
    for (const auto& [axis, text] : at) {
      const std::size_t a = std::find(t.axes.begin(), t.axes.end(), axis) - t.axes.begin();
      const StudyTableCell& c = r.axes.at(a);
      if (c.numeric ? std::abs(c.number - std::stod(text)) > 1e-12 : c.text != text) all = false;
    }
    if (all) return &r;
  }
  return nullptr;
}

std::vector<std::vector<std::string>> read_csv(const fs::path& path) {
  std::vector<std::vector<std::string>> rows;
  std::ifstream in(path);
  for (std::string line; std::getline(in, line);) {
    std::vector<std::string> cells;
    std::stringstream split(line);
    for (std::string cell; std::getline(split, cell, ',');) cells.push_back(cell);
    rows.push_back(cells);
  }
  return rows;
}

class PostSweepPlot : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = new fs::path(test::scratch_dir("sweepplot"));
    plain_ = new std::string(make_study(*dir_, false));
    ens_ = new std::string(make_study(*dir_, true));
  }
  static void TearDownTestSuite() {
    fs::remove_all(*dir_);
    delete dir_;
    delete plain_;
    delete ens_;
  }
  static fs::path* dir_;
  static std::string *plain_, *ens_;
};
fs::path* PostSweepPlot::dir_ = nullptr;
std::string* PostSweepPlot::plain_ = nullptr;
std::string* PostSweepPlot::ens_ = nullptr;

TEST_F(PostSweepPlot, CurvesAreTheTableValuesOnePerGroupInStudyOrder) {
  const StudyTable table = read_study_table(*plain_);
  ASSERT_EQ(table.axes, (std::vector<std::string>{"QW", "gap", "variant"}));
  SweepPlotOptions o;
  o.x_axis = "gap";
  o.output = "u_base";
  o.group_axis = "variant";
  o.where = {{"QW", "0.1"}};
  o.unit = "m";
  o.x_unit = "m";
  const SweepPlotData d = sweep_plot_data(table, *plain_, o);
  ASSERT_EQ(d.curves.size(), 3u);
  EXPECT_FALSE(d.band);
  const std::vector<std::string> labels{"KV", "soft", "free"};
  for (std::size_t k = 0; k < 3; ++k) {
    const SweepCurve& c = d.curves[k];
    EXPECT_EQ(c.label, labels[k]);
    ASSERT_EQ(c.x, (std::vector<double>{0.1, 0.15, 0.2})) << c.label;
    for (std::size_t i = 0; i < c.x.size(); ++i) {
      const StudyTableRow* r =
          row_at(table, {{"QW", "0.1"}, {"gap", std::to_string(c.x[i])}, {"variant", c.label}});
      ASSERT_NE(r, nullptr);
      EXPECT_EQ(c.y[i], r->values[0]) << c.label << " gap " << c.x[i];  // exactly: unit m
    }
  }
  // The walls matter: KV at 10 cm pounds harder than at 20 cm, and free is the same at any gap.
  EXPECT_NE(d.curves[0].y[0], d.curves[0].y[2]);
  EXPECT_EQ(d.curves[2].y[0], d.curves[2].y[2]);
  // The default display units: cm for both, from the axis name and the selector's quantity.
  o.unit.clear();
  o.x_unit.clear();
  const SweepPlotData cm = sweep_plot_data(table, *plain_, o);
  EXPECT_EQ(cm.unit, "cm");
  EXPECT_EQ(cm.x_unit, "cm");
  EXPECT_DOUBLE_EQ(cm.curves[1].y[2], d.curves[1].y[2] / 0.01);
  // Titles in words with units (the study's selector), the column's key kept in the subtitle.
  EXPECT_EQ(sweep_plot_title(cm),
            "Peak base displacement [cm] against gap [cm], one curve per variant");
  EXPECT_EQ(sweep_plot_subtitle(cm), "u_base = base.displacement; where QW = 0.1");
  {
    PanelFrame frame;
    const Figure fig = sweep_plot_figure(cm, 1000, 640, &frame);
    const auto has = [&](const std::string& text) {
      return std::any_of(fig.texts.begin(), fig.texts.end(),
                         [&](const Text& t) { return t.text == text; });
    };
    EXPECT_TRUE(has("peak base displacement [cm]"));  // y axis
    EXPECT_TRUE(has("gap [cm]"));                     // x axis
    EXPECT_FALSE(has("peak u_base [cm]"));
  }
  // A wall peak is empty without walls: the free variant has no F_impact curve (and says so).
  o.output = "F_impact";
  const SweepPlotData f = sweep_plot_data(table, *plain_, o);
  ASSERT_EQ(f.curves.size(), 2u);
  EXPECT_EQ(f.curves[1].label, "soft");
  EXPECT_EQ(sweep_plot_y_title(f), "peak wall force (largest wall) [kN]");
  ASSERT_EQ(f.notes.size(), 1u);
  EXPECT_NE(f.notes[0].find("free"), std::string::npos) << f.notes[0];
  // A numeric group axis: curves named with the level in its display unit; a --where value with
  // a unit selects the same runs as the SI number.
  o.output = "u_base";
  o.group_axis = "QW";
  o.where = {{"variant", "KV"}};
  const SweepPlotData q = sweep_plot_data(table, *plain_, o);
  ASSERT_EQ(q.curves.size(), 2u);
  EXPECT_EQ(q.curves[0].label, "QW = 5 %");
  EXPECT_EQ(q.curves[1].label, "QW = 10 %");
  EXPECT_EQ(q.curves[1].y, cm.curves[0].y);
  o.group_axis = "variant";
  o.where = {{"QW", "10 %"}};
  EXPECT_EQ(sweep_plot_data(table, *plain_, o).curves[0].y, cm.curves[0].y);
}

TEST_F(PostSweepPlot, CommandWritesTheTableValuesAsCsvBesideThePng) {
  const fs::path out = *dir_ / "fig";
  const auto r = test::run_post("sweep-plot " + *plain_ +
                                " --x gap --y u_base --group variant --where QW=0.05 --unit m "
                                "--x-unit m -o " +
                                out.string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const fs::path stem = out / "plain-sweep-u_base-gap";
  ASSERT_TRUE(fs::exists(stem.string() + ".png")) << r.output;
  const auto csv = read_csv(stem.string() + ".csv");
  ASSERT_EQ(csv.size(), 1u + 9u);
  EXPECT_EQ(csv[0], (std::vector<std::string>{"variant", "gap_m", "u_base_m"}));
  const StudyTable table = read_study_table(*plain_);
  for (std::size_t i = 1; i < csv.size(); ++i) {
    const StudyTableRow* row =
        row_at(table, {{"QW", "0.05"}, {"gap", csv[i][1]}, {"variant", csv[i][0]}});
    ASSERT_NE(row, nullptr) << i;
    EXPECT_EQ(std::stod(csv[i][2]), row->values[0]) << i;  // shortest round-trip text
  }
  EXPECT_EQ(csv[1][0], "KV");
  EXPECT_EQ(csv[4][0], "soft");
  EXPECT_EQ(csv[7][0], "free");
  // -o FILE.png: that name, the CSV beside it.
  const auto png = test::run_post("sweep-plot " + *plain_ +
                                  " --x gap --y u_base --group variant --where QW=0.05 -o " +
                                  (*dir_ / "named.png").string());
  ASSERT_EQ(png.exit_code, 0) << png.output;
  EXPECT_TRUE(fs::exists(*dir_ / "named.png"));
  EXPECT_TRUE(fs::exists(*dir_ / "named.csv"));
}

// The ensemble band against an independent reading of the same members: `isopound export`'s
// runs.csv (the study's CSV writer, not the table API) holds each case's member statistics.
TEST_F(PostSweepPlot, EnsembleBandIsTheMembersMinMaxAndTheLineTheirMean) {
  const fs::path out = *dir_ / "ens-fig";
  auto r = test::run_post("sweep-plot " + *ens_ + " --x gap --y u_base --group variant --unit m " +
                          "--x-unit m -o " + out.string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const auto csv = read_csv(out / "ens-sweep-u_base-gap.csv");
  ASSERT_EQ(csv.size(), 1u + 6u);
  EXPECT_EQ(csv[0],
            (std::vector<std::string>{"variant", "gap_m", "u_base_member0_m", "u_base_ens_min_m",
                                      "u_base_ens_mean_m", "u_base_ens_max_m"}));
  const fs::path exported = *dir_ / "ens-export";
  const auto e = test::run_solver("export " + *ens_ + " -o " + exported.string());
  ASSERT_EQ(e.exit_code, 0) << e.output;
  const auto runs = read_csv(exported / "runs.csv");
  const auto col = [&](const std::string& name) {
    return static_cast<std::size_t>(std::find(runs[0].begin(), runs[0].end(), name) -
                                    runs[0].begin());
  };
  int matched = 0;
  for (std::size_t i = 1; i < csv.size(); ++i)
    for (std::size_t k = 1; k < runs.size(); ++k) {
      if (runs[k][col("variant")] != csv[i][0] ||
          std::stod(runs[k][col("gap")]) != std::stod(csv[i][1]))
        continue;
      ++matched;
      const double member0 = std::stod(runs[k][col("u_base")]);
      const double lo = std::stod(runs[k][col("u_base_ens_min")]);
      const double mean = std::stod(runs[k][col("u_base_ens_mean")]);
      const double hi = std::stod(runs[k][col("u_base_ens_max")]);
      EXPECT_EQ(std::stod(csv[i][2]), member0) << i;
      EXPECT_EQ(std::stod(csv[i][3]), lo) << i;
      EXPECT_EQ(std::stod(csv[i][4]), mean) << i;
      EXPECT_EQ(std::stod(csv[i][5]), hi) << i;
      EXPECT_LE(lo, member0);
      EXPECT_LE(member0, hi);
      EXPECT_LT(lo, hi) << "the members must differ";
    }
  EXPECT_EQ(matched, 6);
  // In the data: the line is the ensemble mean, and the title says what the band is.
  SweepPlotOptions o;
  o.x_axis = "gap";
  o.output = "u_base";
  o.group_axis = "variant";
  const SweepPlotData d = read_sweep_plot(*ens_, o);
  ASSERT_TRUE(d.band);
  EXPECT_EQ(d.curves[0].y, d.curves[0].mean);
  EXPECT_EQ(sweep_plot_subtitle(d),
            "u_base = base.displacement; lines: ensemble means, shaded: ensemble min–max");
}

TEST_F(PostSweepPlot, BadInputExitsTwoNamingTheOptionAndTheValue) {
  const auto expect_refusal = [&](const std::string& args, const std::string& message) {
    const auto r = test::run_post("sweep-plot " + *plain_ + " " + args);
    EXPECT_EQ(r.exit_code, 2) << args << "\n" << r.output;
    EXPECT_NE(r.output.find(message), std::string::npos) << args << "\n" << r.output;
  };
  expect_refusal("--x gapp --y u_base --group variant --where QW=0.05",
                 "--x 'gapp': not an axis of the study; its axes are: QW, gap, variant");
  expect_refusal("--x gap --y drift --group variant --where QW=0.05",
                 "--y 'drift': not an output of the study; its outputs are: u_base, F_impact");
  expect_refusal("--x variant --y u_base --group QW --where gap=0.1",
                 "--x 'variant': the axis holds labels (KV, soft, free), not numbers");
  expect_refusal("--x gap --y u_base --group variant --where QW=0.07",
                 "--where 'QW=0.07': no run has QW = 0.07; its values are: 0.05, 0.1");
  expect_refusal("--x gap --y u_base --group variant --where colour=red",
                 "--where 'colour=red': 'colour': not an axis of the study");
  expect_refusal("--x gap --y u_base --group gap", "--group 'gap': it is the --x axis");
  expect_refusal("--x gap --y u_base --group variant --where QW=0.05 --unit furlong",
                 "--unit 'furlong'");
  expect_refusal("--x gap --y u_base --where QW", "--where 'QW': write AXIS=VALUE");
  const auto missing =
      test::run_post("sweep-plot " + (*dir_ / "none.db").string() + " --x gap --y u_base");
  EXPECT_EQ(missing.exit_code, 2);
  EXPECT_NE(missing.output.find("study database not found"), std::string::npos) << missing.output;
}

// With neither --where nor --group for an axis that varies (a default), the curves are drawn at
// the study's first run's value of it, as if --where had fixed it there: the same numbers,
// one note, the subtitle saying where (runs are never averaged).
TEST_F(PostSweepPlot, VaryingAxesLeftOpenAreDrawnAtTheFirstRunsValueWithANote) {
  const StudyTable table = read_study_table(*plain_);
  SweepPlotOptions o;
  o.x_axis = "gap";
  o.output = "u_base";
  o.group_axis = "variant";
  const SweepPlotData open = sweep_plot_data(table, *plain_, o);
  o.where = {{"QW", "0.05"}};
  const SweepPlotData fixed = sweep_plot_data(table, *plain_, o);
  ASSERT_EQ(open.curves.size(), 3u);
  for (std::size_t k = 0; k < 3; ++k) {
    EXPECT_EQ(open.curves[k].label, fixed.curves[k].label);
    EXPECT_EQ(open.curves[k].x, fixed.curves[k].x);
    EXPECT_EQ(open.curves[k].y, fixed.curves[k].y);
  }
  ASSERT_EQ(open.notes.size(), 1u);
  EXPECT_NE(open.notes[0].find("QW (2 values: 0.05, 0.1); drawn at QW = 5 %"), std::string::npos)
      << open.notes[0];
  EXPECT_EQ(sweep_plot_subtitle(open), "u_base = base.displacement; where QW = 5 %");
  // No --group either: QW and variant at the first run's (5 %, KV), one curve, exit 0.
  const fs::path out = *dir_ / "open";
  const auto r = test::run_post("sweep-plot " + *plain_ + " --x gap --y u_base -o " + out.string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("note: axes that are neither --x nor --group vary: QW (2 values: 0.05, "
                          "0.1), variant (3 values: KV, soft, free); drawn at QW = 5 %, variant = "
                          "KV"),
            std::string::npos)
      << r.output;
  const auto csv = read_csv(out / "plain-sweep-u_base-gap.csv");
  ASSERT_EQ(csv.size(), 4u);  // header and the three gaps
  for (std::size_t i = 0; i < 3; ++i)
    EXPECT_EQ(std::stod(csv[i + 1][1]), fixed.curves[0].y[i]) << csv[i + 1][1];
}

// One colour per group curve: each of the three variants' colours is on the plot (left half of
// the plot area: the legend is at most the right half), the next series colour is not.
TEST_F(PostSweepPlot, PngHasOneColourPerGroupCurve) {
  const fs::path png = *dir_ / "colours.png";
  const auto r =
      test::run_post("sweep-plot " + *plain_ +
                     " --x gap --y u_base --group variant --where QW=0.05 -o " + png.string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  SweepPlotOptions o;
  o.x_axis = "gap";
  o.output = "u_base";
  o.group_axis = "variant";
  o.where = {{"QW", "0.05"}};
  PanelFrame frame;
  sweep_plot_figure(read_sweep_plot(*plain_, o), 1000, 640, &frame);
  const test::Image img = test::read_png(png.string());
  ASSERT_EQ(img.width, 1000);
  ASSERT_EQ(img.height, 640);
  const auto count = [&](Rgb c) {
    int n = 0;
    for (int y = static_cast<int>(frame.bottom) + 2; y < frame.bottom + frame.height - 2; ++y)
      for (int x = static_cast<int>(frame.left) + 2; x < frame.left + 0.5 * frame.width - 4; ++x) {
        const unsigned char* p = img.at(x, y);
        n += std::abs(p[0] - c.r) <= 12 && std::abs(p[1] - c.g) <= 12 && std::abs(p[2] - c.b) <= 12;
      }
    return n;
  };
  for (int k = 0; k < 3; ++k) EXPECT_GT(count(series_colour(k)), 40) << "curve " << k;
  EXPECT_EQ(count(series_colour(3)), 0) << "a fourth curve";
}

// The band is shaded between min and max in the tint of its curve's colour, and nowhere else.
TEST(PostSweepPlotFigure, BandIsShadedBetweenMinAndMaxInTheTintOfItsCurve) {
  SweepPlotData d;
  d.output = "u_base";
  d.x_axis = "gap";
  d.group_axis = "variant";
  d.unit = d.x_unit = "cm";
  d.band = true;
  for (const double level : {10.0, 20.0}) {
    SweepCurve c;
    c.label = level == 10.0 ? "A" : "B";
    c.x = {0, 1, 2};
    c.y = c.mean = c.member0 = {level, level, level};
    c.lo = {level - 1, level - 1, level - 1};
    c.hi = {level + 1, level + 1, level + 1};
    d.curves.push_back(c);
  }
  PanelFrame frame;
  const Figure fig = sweep_plot_figure(d, 1000, 640, &frame);
  const auto dir = test::scratch_dir("sweepband");
  {
    const PrivateDisplay display(false);
    render_png(fig, (dir / "band.png").string());
  }
  const test::Image img = test::read_png((dir / "band.png").string());
  const auto colour_at = [&](double x, double y) {
    const Point2 p = frame.to_pixel(x, y);
    const unsigned char* c = img.at(static_cast<int>(p.x), static_cast<int>(p.y));
    return Rgb{c[0], c[1], c[2]};
  };
  const auto near = [](Rgb a, Rgb b) {
    return std::abs(a.r - b.r) <= 6 && std::abs(a.g - b.g) <= 6 && std::abs(a.b - b.b) <= 6;
  };
  for (int k = 0; k < 2; ++k) {
    const double level = 10.0 + 10.0 * k;
    const Rgb tint = band_tint(series_colour(k));
    EXPECT_TRUE(near(colour_at(0.33, level + 0.6), tint)) << "inside band " << k;
    EXPECT_TRUE(near(colour_at(0.33, level - 0.6), tint)) << "inside band " << k;
    EXPECT_TRUE(near(colour_at(0.33, level + 1.5), Rgb{255, 255, 255})) << "above band " << k;
  }
  fs::remove_all(dir);
}

}  // namespace
}  // namespace isopound::post
