// isopound-post pushover on a real `isopound pushover` of the thesis frame: the PNG is written at
// its size, the reader's points are the CSV rows the JSON names, the first-yield and capping
// markers are drawn at their points (and only when the points exist); bad input exits 2 naming
// the file.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "post/headless.h"
#include "post/plot_pushover.h"
#include "post/pushover_data.h"
#include "post/render_png.h"
#include "post_test_support.h"

namespace isopound::post {
namespace {

namespace fs = std::filesystem;

// configs/thesis-3storey-pushover.yaml pushed to 2 % roof drift (first mode): it yields and caps.
fs::path g_pushover_dir;  // removed when the test program ends

struct PushoverDirCleanup : ::testing::Environment {
  void TearDown() override {
    if (!g_pushover_dir.empty()) fs::remove_all(g_pushover_dir);
  }
};
[[maybe_unused]] ::testing::Environment* const g_cleanup =
    ::testing::AddGlobalTestEnvironment(new PushoverDirCleanup);

const fs::path& thesis_pushover() {
  static const fs::path dir = [] {
    const auto d = test::scratch_dir("pushover-thesis");
    g_pushover_dir = d;
    const auto r = test::run_solver(
        "pushover " + (test::source_dir() / "configs" / "thesis-3storey-pushover.yaml").string() +
        " -o " + d.string());
    EXPECT_EQ(r.exit_code, 0) << r.output;
    return d;
  }();
  return dir;
}

std::string text_of(const fs::path& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

void write_text(const fs::path& path, const std::string& text) {
  std::ofstream out(path);
  out << text;
}

// Data row `row` (0-based, after the header) of a CSV, split at commas and read with strtod.
std::vector<double> csv_row(const fs::path& path, int row) {
  std::ifstream in(path);
  std::string line;
  for (int k = 0; k <= row + 1; ++k) std::getline(in, line);
  std::vector<double> v;
  std::stringstream cells(line);
  std::string cell;
  while (std::getline(cells, cell, ',')) v.push_back(std::strtod(cell.c_str(), nullptr));
  return v;
}

bool near_colour(const unsigned char* p, Rgb c, int tol) {
  return std::abs(p[0] - c.r) <= tol && std::abs(p[1] - c.g) <= tol && std::abs(p[2] - c.b) <= tol;
}

int count_colour(const test::Image& img, Rgb c, int tol) {
  int n = 0;
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x) n += near_colour(img.at(x, y), c, tol);
  return n;
}

TEST(PostPushover, ThesisCapacityCurveIsWrittenAndItsPointsAreTheRowsTheJsonNames) {
  const fs::path dir = thesis_pushover();
  const auto out = test::scratch_dir("pushover-png");
  auto r = test::run_post("pushover " + dir.string() + " -o " + (out / "curve.png").string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("Wrote " + (out / "curve.png").string()), std::string::npos) << r.output;
  const test::Image img = test::read_png((out / "curve.png").string());
  EXPECT_EQ(img.width, 1240);  // two panels, 620 px each
  EXPECT_EQ(img.height, 520);
  EXPECT_GT(img.variance(), 100.0);
  // -o DIR writes DIR/pushover.png; no -o writes it into the pushover directory.
  r = test::run_post("pushover " + dir.string() + " -o " + (out / "sub").string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_TRUE(fs::exists(out / "sub" / "pushover.png"));
  r = test::run_post("pushover " + dir.string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_TRUE(fs::exists(dir / "pushover.png"));

  // The reader against an independent reading of the two files.
  const PushoverData d = read_pushover(dir);
  const auto j = nlohmann::json::parse(text_of(dir / "pushover.json"));
  EXPECT_EQ(d.building, j["building"].get<std::string>());
  EXPECT_EQ(d.pattern, "first_mode");
  EXPECT_EQ(d.dimension, 2);
  EXPECT_EQ(d.storeys, 3);
  ASSERT_TRUE(d.first_yield.has_value());
  ASSERT_TRUE(d.capping.has_value());
  for (const auto& [p, key] :
       {std::pair{*d.first_yield, "first_yield"}, std::pair{*d.capping, "capping"}}) {
    SCOPED_TRACE(key);
    const int row = j[key]["row"].get<int>();
    EXPECT_EQ(p.row, row);
    const std::vector<double> v = csv_row(dir / "pushover.csv", row);
    ASSERT_GE(v.size(), 3u);
    EXPECT_EQ(p.roof_displacement, v[0]);
    EXPECT_EQ(p.roof_drift_ratio, v[1]);
    EXPECT_EQ(p.base_shear, v[2]);
    // ... and the JSON's full-precision values (the CSV keeps 10 digits).
    EXPECT_NEAR(p.roof_displacement, j[key]["roof_displacement_m"].get<double>(),
                1e-9 * std::abs(v[0]));
    EXPECT_NEAR(p.base_shear, j[key]["base_shear_N"].get<double>(), 1e-9 * std::abs(v[2]));
  }
  EXPECT_LT(d.first_yield->row, d.capping->row);
  EXPECT_EQ(d.rows(), static_cast<std::size_t>(j["steps"].get<int>() + 1));
  std::filesystem::remove_all(out);
}

TEST(PostPushover, MarkersAreDrawnAtTheirPointsAndOnlyWhenThePointsExist) {
  const PushoverData with = read_pushover(thesis_pushover());
  ASSERT_TRUE(with.first_yield && with.capping);
  PushoverData without = with;
  without.first_yield.reset();
  without.capping.reset();

  const PrivateDisplay display(false);
  const auto dir = test::scratch_dir("pushover-markers");
  std::vector<PanelFrame> frames;
  const Figure fig_with = pushover_figure(with, &frames);
  render_png(fig_with, (dir / "with.png").string());
  render_png(pushover_figure(without), (dir / "without.png").string());
  const test::Image a = test::read_png((dir / "with.png").string());
  const test::Image b = test::read_png((dir / "without.png").string());
  ASSERT_EQ(frames.size(), 2u);

  // The legend names each point with its numbers, as the solver prints them.
  const auto legend_has = [&](const std::string& s) {
    for (const Text& t : fig_with.texts)
      if (t.text == s) return true;
    return false;
  };
  const auto label = [](const char* name, const PushoverPoint& p) {
    char buf[120];
    std::snprintf(buf, sizeof buf, "%s (roof %.2f cm, %.1f kN)", name, p.roof_displacement * 100,
                  p.base_shear / 1e3);
    return std::string(buf);
  };
  EXPECT_TRUE(legend_has(label("first yield", *with.first_yield)));
  EXPECT_TRUE(legend_has(label("capping", *with.capping)));

  for (const auto& [p, colour] : {std::pair{*with.first_yield, kFirstYieldColour},
                                  std::pair{*with.capping, kCappingColour}}) {
    SCOPED_TRACE(p.row);
    // The marker's fill at the point's pixel (data to pixel by the panel's own mapping), over
    // the curve that passes through it; without the point, the curve's colour or white there.
    const Point2 at = frames[0].to_pixel(p.roof_displacement * 100, p.base_shear / 1e3);
    const int x = static_cast<int>(at.x), y = static_cast<int>(at.y);
    EXPECT_TRUE(near_colour(a.at(x, y), colour, 30))
        << int(a.at(x, y)[0]) << " " << int(a.at(x, y)[1]) << " " << int(a.at(x, y)[2]);
    EXPECT_FALSE(near_colour(b.at(x, y), colour, 30));
    // Pixels of the marker's colour: a marker's worth in panel 0 with the points (plus the
    // legend's and the drift panel's), none at all without them.
    int in_panel = 0;
    const PanelFrame& f = frames[0];
    for (int py = static_cast<int>(f.bottom); py < static_cast<int>(f.bottom + f.height); ++py)
      for (int px = static_cast<int>(f.left); px < static_cast<int>(f.left + f.width); ++px)
        in_panel +=
            near_colour(a.at(px, py), colour, 30) && std::hypot(px - at.x, py - at.y) < 10.0;
    EXPECT_GT(in_panel, 40);  // a 13-15 px marker around the point
    EXPECT_EQ(count_colour(b, colour, 30), 0);
  }
  std::filesystem::remove_all(dir);
}

// An isolated building (configs/3d-xy5-yielding.yaml: bearings Q/W 5 %, columns yielding at 0.5 %
// drift) pushed to 10 %: the roof travels 76 cm before a column yields, nearly all of it in the
// bearings. The figure draws the capacity curve against the superstructure's drift (the storeys'
// drifts summed, read here from the CSV), where first yield is at storey 1's 0.5 %, and a panel
// of the base shear against the bearings' displacement (the rest of the roof's).
TEST(PostPushover, IsolatedBuildingIsDrawnAgainstItsSuperstructureDriftBesideItsBearings) {
  const auto dir = test::scratch_dir("pushover-isolated");
  const auto r = test::run_solver(
      "pushover " + (test::source_dir() / "configs" / "3d-xy5-yielding.yaml").string() +
      " --target-drift 10% -o " + dir.string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const PushoverData d = read_pushover(dir);
  ASSERT_TRUE(d.isolated());
  EXPECT_FALSE(read_pushover(thesis_pushover()).isolated());  // fixed base: as before
  ASSERT_TRUE(d.first_yield.has_value());
  const int row = d.first_yield->row;
  // Independently: the storeys' drifts of the first-yield row from the CSV.
  const std::vector<std::string>& cols = d.columns;
  const auto at = [&](int k, const std::string& name) {
    const std::size_t c = std::find(cols.begin(), cols.end(), name) - cols.begin();
    return csv_row(dir / "pushover.csv", k).at(c);
  };
  double drift = 0.0;
  for (int s = 1; s <= 3; ++s) drift += at(row, "story" + std::to_string(s) + "_drift_m");
  const double bearings = at(row, "roof_displacement_m") - drift;
  EXPECT_GT(d.first_yield->roof_displacement, 0.7);  // the 76 cm of the roof
  EXPECT_LT(drift, 0.05);                            // a few cm of the superstructure's
  // First yield where storey 1's columns reach their 0.5 % yield drift (pushed along x, no
  // rotation: the columns' drift is the storey's): at or just past it, the row before below.
  EXPECT_GE(at(row, "story1_drift_ratio"), 0.005);
  EXPECT_LT(at(row - 1, "story1_drift_ratio"), 0.005);

  std::vector<PanelFrame> frames;
  const Figure fig = pushover_figure(d, &frames);
  ASSERT_EQ(frames.size(), 3u);
  const auto has = [&](const std::string& text) {
    return std::any_of(fig.texts.begin(), fig.texts.end(),
                       [&](const Text& t) { return t.text == text; });
  };
  EXPECT_TRUE(
      has("superstructure drift: roof relative to the base slab [cm]   (1 % drift = 9.6 cm)"));
  EXPECT_TRUE(has("bearing displacement: roof less superstructure drift [cm]"));
  char label[96];
  std::snprintf(label, sizeof label, "first yield (drift %.2f cm, %.1f kN)", drift * 100,
                d.first_yield->base_shear / 1e3);
  EXPECT_TRUE(has(label)) << label;
  std::snprintf(label, sizeof label, "first yield (bearings %.2f cm)", bearings * 100);
  EXPECT_TRUE(has(label)) << label;
  // Panel 0's x axis spans the superstructure's drift (4 cm at the end), not the roof's 96 cm;
  // panel 1's the bearings' 92 cm.
  const double end_drift = d.superstructure_drift().back();
  EXPECT_LT(frames[0].x_hi, 1.2 * end_drift * 100);
  EXPECT_GE(frames[0].x_hi, end_drift * 100);
  EXPECT_GE(frames[1].x_hi, d.bearing_displacement().back() * 100);
  // The first-yield markers where those coordinates put them.
  const auto marker_at = [&](Point2 p) {
    return std::any_of(fig.markers.begin(), fig.markers.end(), [&](const Marker& m) {
      if (!(m.fill == kFirstYieldColour)) return false;
      Point2 c;
      for (const Point2& q : m.points) c.x += q.x / m.points.size(), c.y += q.y / m.points.size();
      return std::hypot(c.x - p.x, c.y - p.y) < 0.5;
    });
  };
  const double shear_kN = d.first_yield->base_shear / 1e3;
  EXPECT_TRUE(marker_at(frames[0].to_pixel(drift * 100, shear_kN)));
  EXPECT_TRUE(marker_at(frames[1].to_pixel(bearings * 100, shear_kN)));
  EXPECT_TRUE(marker_at(frames[2].to_pixel(drift * 100, at(row, "story1_drift_ratio") * 100)));
  std::filesystem::remove_all(dir);
}

TEST(PostPushover, BadInputExitsTwoNamingTheFile) {
  const fs::path good = thesis_pushover();
  const auto dir = test::scratch_dir("pushover-bad");
  const std::string csv = text_of(good / "pushover.csv"), json = text_of(good / "pushover.json");

  // No such directory.
  auto r = test::run_post("pushover " + (dir / "nope").string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.output.find((dir / "nope").string() + ": pushover directory not found"),
            std::string::npos)
      << r.output;
  // A directory with pushover.csv but no pushover.json.
  write_text(dir / "pushover.csv", csv);
  r = test::run_post("pushover " + dir.string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.output.find((dir / "pushover.json").string() + ": cannot open"), std::string::npos)
      << r.output;
  EXPECT_FALSE(fs::exists(dir / "pushover.png"));
  // A CSV without base_shear_N (and a JSON that agrees with it, so the CSV is what is wrong).
  {
    std::string renamed = csv;
    renamed.replace(renamed.find("base_shear_N"), 12, "base_shear_kN");
    write_text(dir / "pushover.csv", renamed);
    write_text(dir / "pushover.json", json);
  }
  r = test::run_post("pushover " + dir.string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.output.find((dir / "pushover.csv").string() + ":1: no column 'base_shear_N'"),
            std::string::npos)
      << r.output;
  // A malformed number on data row 4 (line 6), column 2.
  {
    std::stringstream in(csv);
    std::string line, out;
    for (int k = 1; std::getline(in, line); ++k) {
      if (k == 6) {
        const std::size_t a = line.find(','), b = line.find(',', a + 1);
        line = line.substr(0, a + 1) + "1.2.3" + line.substr(b);
      }
      out += line + "\n";
    }
    write_text(dir / "pushover.csv", out);
  }
  r = test::run_post("pushover " + dir.string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.output.find((dir / "pushover.csv").string() + ":6: column 'roof_drift_ratio': not a "
                                                            "number: '1.2.3'"),
            std::string::npos)
      << r.output;
  // A first-yield row outside the table.
  write_text(dir / "pushover.csv", csv);
  {
    auto j = nlohmann::json::parse(json);
    j["first_yield"]["row"] = 201;  // 201 data rows: 0 to 200
    write_text(dir / "pushover.json", j.dump(2));
  }
  r = test::run_post("pushover " + dir.string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.output.find((dir / "pushover.json").string() + ": 'first_yield.row' 201 is not a "
                                                             "data row of"),
            std::string::npos)
      << r.output;
  // A JSON of another pushover (its point's base shear is not its row's).
  {
    auto j = nlohmann::json::parse(json);
    j["capping"]["base_shear_N"] = j["capping"]["base_shear_N"].get<double>() * 1.01;
    write_text(dir / "pushover.json", j.dump(2));
  }
  r = test::run_post("pushover " + dir.string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.output.find((dir / "pushover.json").string() + ": 'capping.base_shear_N'"),
            std::string::npos)
      << r.output;
  EXPECT_FALSE(fs::exists(dir / "pushover.png"));
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace isopound::post
