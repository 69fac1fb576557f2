// plan.png rendered by isopound-pre with no DISPLAY (a private Xvfb), read back: size,
// non-blank, and known features at the pixels the drawing's scale puts them.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>

#include "geometry/pre/checks.h"
#include "geometry/pre/model_scan.h"
#include "geometry/pre/plan_figure.h"
#include "geometry/pre/properties.h"
#include "pre_test_support.h"
#include "solver/structures/site_plan.h"

namespace isopound::pre::test {

namespace {

// The view plan.png was drawn with: the same model through the same steps as the tool.
PlanView view_of(const std::string& model_path, Site& site) {
  ProblemList problems;
  const ScannedModel m = scan_model(model_path, problems);
  EXPECT_TRUE(m.config.has_value());
  site = site_plan(*m.config);
  const auto properties = structure_properties(*m.config);
  const auto clearances =
      check_site3d(*m.config, m.structures, site, site_limits(*m.config), problems);
  PlanView view;
  plan_figure(site, properties, clearances, struck_column_sites(*m.config), PlanOptions{}, &view);
  return view;
}

bool near(const unsigned char* p, post::Rgb c, int tol = 40) {
  return std::abs(p[0] - c.r) < tol && std::abs(p[1] - c.g) < tol && std::abs(p[2] - c.b) < tol;
}

TEST(PrePlan, ThesisBuildingPlanWithoutDisplay) {
  const auto dir = scratch_dir("plan");
  const std::string model = (source_dir() / "configs/3d-thesis-building.yaml").string();
  const auto r = run_pre(model + " -o " + dir.string() + " --angle '30 deg'");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const Image img = read_png((dir / "plan.png").string());
  ASSERT_EQ(img.width, 1400);
  ASSERT_EQ(img.height, 1000);
  std::set<int> colours;
  for (std::size_t i = 0; i < img.rgb.size(); i += 3)
    colours.insert(img.rgb[i] << 16 | img.rgb[i + 1] << 8 | img.rgb[i + 2]);
  EXPECT_GT(colours.size(), 20u);  // not blank: slabs, columns, bearings, text

  Site site;
  const PlanView view = view_of(model, site);
  // Scale: the 16.5 m slab is drawn 16.5 * scale px wide; about 800 px in this layout.
  EXPECT_GT(view.scale * 16.5, 600);
  const auto pixel = [&](Vec2 p) {
    const post::Point2 q = view.to_px(p);
    return img.at(static_cast<int>(std::lround(q.x)), static_cast<int>(std::lround(q.y)));
  };
  // Column A1 at the south-west corner (-8.25, -8.25), a bit off its axis-1 stroke.
  EXPECT_TRUE(near(pixel({-8.25 + 0.1, -8.25 + 0.1}), kColumnColour)) << "column A1";
  // Inside the slab between columns: the slab's fill.
  EXPECT_TRUE(near(pixel({-4.0, -1.5}), slab_fill(0))) << "slab";
  // 0.6 m west of the west edge, between column lines: background.
  EXPECT_TRUE(near(pixel({-8.85, -1.5}), {255, 255, 255})) << "outside the slab";
  // East of the slab: background too (no wall in this model).
  EXPECT_TRUE(near(pixel({8.85, -1.5}), {255, 255, 255})) << "east of the slab";
  std::filesystem::remove_all(dir);
}

TEST(PrePlan, EastWallOfTheXY5SiteRightOfTheSlab) {
  // configs/3d-xy5.yaml: the thesis building (slab x in [-8.25, 8.25] m) in 1 m walls at 20 cm.
  const auto dir = scratch_dir("plan-xy5");
  const std::string model = (source_dir() / "configs/3d-xy5.yaml").string();
  const auto r = run_pre(model + " -o " + dir.string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const Image img = read_png((dir / "plan.png").string());
  ASSERT_EQ(img.width, 1400);
  Site site;
  const PlanView view = view_of(model, site);
  ASSERT_EQ(site.walls.size(), 4u);
  const auto pixel = [&](Vec2 p) {
    const post::Point2 q = view.to_px(p);
    return img.at(static_cast<int>(std::lround(q.x)), static_cast<int>(std::lround(q.y)));
  };
  // Along y = -1.5 m from west to east: slab, the 20 cm gap (background), the wall.
  EXPECT_TRUE(near(pixel({7.9, -1.5}), slab_fill(0))) << "slab";
  EXPECT_TRUE(near(pixel({8.35, -1.5}), {255, 255, 255})) << "gap";
  EXPECT_TRUE(near(pixel({8.95, -1.5}), kWallColour)) << "east wall";
  EXPECT_TRUE(near(pixel({-8.95, -1.5}), kWallColour)) << "west wall";
  // Beyond the wall: background again.
  EXPECT_TRUE(near(pixel({9.7, -1.5}), {255, 255, 255})) << "east of the wall";
  std::filesystem::remove_all(dir);
}

// configs/3d-floor-to-column.yaml: the building's floors 1-2 strike the neighbour's storeys 2-3,
// the neighbour's floors 1-3 the building's storeys 1-3, four facing columns each (20 sites at 8
// plan positions). Each position is drawn in the struck colour, labelled with its storeys;
// the legend names every striking slab with its elevation and the storey it strikes.
TEST(PrePlan, StruckColumnsOfAFloorToColumnSiteAreMarkedAndTheirSlabsNamed) {
  ProblemList problems;
  const ScannedModel m =
      scan_model((source_dir() / "configs/3d-floor-to-column.yaml").string(), problems);
  ASSERT_TRUE(m.config.has_value());
  const Site site = site_plan(*m.config);
  const std::vector<StruckColumnSite> sites = struck_column_sites(*m.config);
  ASSERT_EQ(sites.size(), 20u);
  PlanView view;
  const post::Figure f =
      plan_figure(site, structure_properties(*m.config), {}, sites, PlanOptions{}, &view);
  // The struck columns: markers of kStruckColour centred on the sections (square: the mean of
  // the corners), at least 16 px across the diagonal.
  std::vector<post::Point2> marked;
  for (const post::Marker& p : f.markers) {
    if (!(p.fill == kStruckColour)) continue;
    post::Point2 c;
    for (const post::Point2& q : p.points) c.x += q.x / 4, c.y += q.y / 4;
    EXPECT_GE(std::hypot(p.points[0].x - c.x, p.points[0].y - c.y), 7.9);
    marked.push_back(c);
  }
  EXPECT_EQ(marked.size(), 9u);  // 8 positions and the legend's swatch
  for (const StruckColumnSite& s : sites) {
    SCOPED_TRACE(s.label());
    Vec2 c;
    for (Vec2 p : s.section_W) c = c + 0.25 * p;
    const post::Point2 at = view.to_px(c);
    EXPECT_TRUE(std::any_of(
        marked.begin(), marked.end(),
        [&](const post::Point2& m) { return std::hypot(m.x - at.x, m.y - at.y) < 0.5; }))
        << "not marked at (" << at.x << ", " << at.y << ") px";
  }
  const auto has = [&](const std::string& text) {
    return std::any_of(f.texts.begin(), f.texts.end(),
                       [&](const post::Text& t) { return t.text == text; });
  };
  EXPECT_TRUE(has("struck column (a slab strikes it)"));
  EXPECT_TRUE(has("building/floor 1 at z = 3.2 m"));
  EXPECT_TRUE(has("building/floor 2 at z = 6.4 m"));
  EXPECT_TRUE(has("east-neighbour/floor 3 at z = 9 m"));
  EXPECT_TRUE(has("strikes east-neighbour storey 2 (3–6 m): 4 columns"));
  EXPECT_TRUE(has("strikes building storey 3 (6.4–9.6 m): 4 columns"));
  // One label per facing line, above its northmost column, on the side away from the striker.
  for (const auto& [text, west] :
       {std::pair{"storeys 1–3 struck", true}, std::pair{"storeys 2–3 struck", false}}) {
    const auto t = std::find_if(f.texts.begin(), f.texts.end(),
                                [&](const post::Text& x) { return x.text == text; });
    ASSERT_NE(t, f.texts.end()) << text;
    EXPECT_EQ(std::count_if(f.texts.begin(), f.texts.end(),
                            [&](const post::Text& x) { return x.text == text; }),
              1);
    EXPECT_EQ(t->h, west ? post::HAlign::kRight : post::HAlign::kLeft) << text;
    EXPECT_GT(t->at.y, view.to_px({0, 8.25}).y) << text;  // above the north column line
  }
}

}  // namespace
}  // namespace isopound::pre::test
