// The 3D run pictures read at a glance (issue 38 item 2), checked on the Figures' data: a run like
// the demo (16 bearings, 3 storeys, moat walls 15 cm away on all sides, the near-fault pulse at
// 30 deg, stopped after the first impacts on every wall) with friction coefficients other than the
// defaults. The floors' acceleration panel is set by the floors and the ground, not by the base
// slab's impact spikes; no peak text lies on the legend or on another; the trajectory is zoomed to
// the motion with the slab and walls at true scale in an equal-axes inset; every F_T-F_N panel
// draws ±μ_s F_N and ±μ_k F_N with the model's μ; the bearings' legends name what they draw.
#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "post/plot_run3d.h"
#include "post/run_data.h"
#include "post_test_support.h"
#include "solver/core/constants.h"
#include "solver/io/model_input.h"
#include "solver/structures/job.h"

namespace isopound::post {
namespace {

constexpr const char* kDemoLike = R"(structures:
  - name: building
    grid: {bays_x: [5.5 m, 5.5 m, 5.5 m], bays_y: [5.5 m, 5.5 m, 5.5 m]}
    columns: {section: [45 cm, 45 cm], E: 30 GPa, nu: 0.2,
              hysteresis: {model: bouc_wen, yield_drift_ratio: 0.5 %, post_yield_ratio: 5 %,
                           n: 2, A: 1, beta: 0.5, gamma: 0.5}}
    storeys: {count: 3, height: 3.2 m, mass: 340 t, roof_mass: 250 t}
    base: {mass: 340 t}
    bearing: {model: bouc_wen, Tb: 2.0 s, QW: 5 %, uy: 1 cm, n: 2, A: 1, beta: 0.5, gamma: 0.5}
    damping: {type: rayleigh, ratios: [5 %, 2 %], modes: [1, 4], bearing_stiffness: post_yield}
    walls: {sides: all, gap: 15 cm, thickness: 1 m, height: 1 m, extension: 1 m,
            mass_per_length: 5 t/m}
contact: {k_normal: 2.58e10 N/m2, k_tangential: 5.74e9 N/m, mu_static: 0.5, mu_kinetic: 0.3,
          restitution: 0.65}
ground_motion:
  L: {pulse: {amplitude: 1.0 m/s, period: 2 s}}
  T: {pulse: {amplitude: 0.5 m/s, period: 2 s}}
  angle: 30 deg
  extra_time: 0 s
analysis: {t_end: 4.7 s, dt: 2 ms}
output: {interval: 5 ms}
)";

const NamedFigure& named(const std::vector<NamedFigure>& figures, const std::string& file) {
  for (const NamedFigure& f : figures)
    if (f.file == file) return f;
  ADD_FAILURE() << file << " not drawn";
  return figures.front();
}

bool has_text(const Figure& fig, const std::string& text) {
  for (const Text& t : fig.texts)
    if (t.text == text) return true;
  return false;
}

// A pixel of a panel back in its data units.
Point2 to_data(const PanelFrame& f, Point2 p) {
  return {f.x_lo + (p.x - f.left) / f.width * (f.x_hi - f.x_lo),
          f.y_lo + (p.y - f.bottom) / f.height * (f.y_hi - f.y_lo)};
}

// xy_plot's placement on its own: three peaks close together under a top-right legend, each
// with a long text. Beside its marker each text would run into the legend or the next one.
TEST(XyPlotMarks, TextsPlacedClearOfTheLegendTheOtherTextsAndTheFrame) {
  Panel p{"crowded", "t [s]", "y [-]", {}, true};
  std::vector<double> t;
  for (int i = 0; i <= 100; ++i) t.push_back(0.1 * i);
  for (int k = 0; k < 3; ++k) {
    std::vector<double> y;
    for (double x : t) y.push_back((3.0 - 0.1 * k) * std::exp(-std::pow(x - 8.0 - 0.2 * k, 2)));
    p.series.push_back(line_series("series " + std::to_string(k) + " with a long name", t, y));
    p.marks.push_back({8.0 + 0.2 * k, 3.0 - 0.1 * k,
                       "peak of series " + std::to_string(k) + " at its time (summary.json)"});
  }
  NamedFigure figure{"crowded.png", {}, {}};
  figure.figure = xy_figure({p}, 1, 800, 300, "", &figure.frames);
  ASSERT_EQ(figure.frames.size(), 1u);
  ASSERT_EQ(figure.frames[0].label_boxes.size(), 3u);
  for (const Box& b : figure.frames[0].label_boxes) EXPECT_FALSE(b.empty());
  test::expect_labels_clear(figure);
}

class RunPictures : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = new std::filesystem::path(test::scratch_dir("pictures3d"));
    std::ofstream(*dir_ / "m.yaml") << kDemoLike;
    const auto r =
        test::run_solver("run " + (*dir_ / "m.yaml").string() + " -o " + (*dir_ / "run").string());
    ASSERT_EQ(r.exit_code, 0) << r.output;
    run_ = new RunData(read_run(*dir_ / "run"));
    std::ifstream sj(*dir_ / "run" / "summary.json");
    summary_ = new nlohmann::json(nlohmann::json::parse(sj));
    figures_ = new std::vector<NamedFigure>(run_figures3d(*run_));
  }
  static void TearDownTestSuite() {
    std::filesystem::remove_all(*dir_);
    delete figures_, delete summary_, delete run_, delete dir_;
  }
  static std::filesystem::path* dir_;
  static RunData* run_;
  static nlohmann::json* summary_;
  static std::vector<NamedFigure>* figures_;
};
std::filesystem::path* RunPictures::dir_ = nullptr;
RunData* RunPictures::run_ = nullptr;
nlohmann::json* RunPictures::summary_ = nullptr;
std::vector<NamedFigure>* RunPictures::figures_ = nullptr;

TEST_F(RunPictures, FloorsAndGroundSetTheirAccelerationAxisNotTheBaseSlabsImpacts) {
  const NamedFigure& th = named(*figures_, "time_histories.png");
  // Displacement, drifts, the base slab's acceleration, the floors' and ground's, F_N, F_T.
  ASSERT_EQ(th.frames.size(), 6u);
  double floors = 0.0, slab = 0.0;
  for (const auto& level : (*summary_)["buildings_3d"][0]["levels"]) {
    const double a =
        level["centre_of_mass"]["absolute_acceleration"]["resultant"]["value"].get<double>() /
        kGravity;
    (level["label"] == "base" ? slab : floors) =
        std::max(level["label"] == "base" ? slab : floors, a);
  }
  double ground = 0.0;
  const std::vector<double>& ax = run_->column(run_->find("", "ground_acceleration"));
  const std::vector<double>& ay = run_->column(run_->find("", "ground_acceleration_y"));
  for (std::size_t r = 0; r < ax.size(); ++r)
    ground = std::max(ground, std::hypot(ax[r], ay[r]) / kGravity);
  ASSERT_GT(slab, 10 * floors) << "the run must pound: the slab's spikes dwarf the floors'";
  ASSERT_GT(ground, 0.05);
  const PanelFrame& f = th.frames[3];
  EXPECT_LE(f.y_lo, 0.0);
  EXPECT_GE(f.y_hi, floors);
  EXPECT_GE(f.y_hi, ground);
  EXPECT_LT(f.y_hi, 2.0 * floors) << "the axis is the floors', not the slab's " << slab << " g";
  // The slab's own panel holds its spikes.
  EXPECT_GE(th.frames[2].y_hi, slab);
  EXPECT_TRUE(has_text(th.figure, "ground (resultant)"));
}

TEST_F(RunPictures, PeakTextsClearOfTheLegendEachOtherAndTheFrame) {
  for (const NamedFigure& figure : *figures_) test::expect_labels_clear(figure);
  int placed = 0;
  for (const PanelFrame& f : named(*figures_, "time_histories.png").frames)
    for (const Box& b : f.label_boxes) placed += !b.empty();
  // One "(summary.json)" text per time-history panel (displacement, drift, 2 accelerations,
  // F_N, F_T), each with a legend.
  EXPECT_EQ(placed, 6);
  for (const PanelFrame& f : named(*figures_, "time_histories.png").frames)
    EXPECT_FALSE(f.legend_box.empty());
}

TEST_F(RunPictures, TrajectoryZoomedToTheMotionWithTheSlabAtTrueScaleInAnEqualAxesInset) {
  const NamedFigure& tr = named(*figures_, "trajectory.png");
  ASSERT_EQ(tr.frames.size(), 2u);  // the displacements, the true-scale inset
  double reach = 0.0;               // cm, the largest corner displacement (summary.json)
  for (const auto& c : (*summary_)["buildings_3d"][0]["levels"][0]["corners"])
    reach = std::max(reach, 100 * c["displacement"]["resultant"]["value"].get<double>());
  ASSERT_GT(reach, 15.0) << "the slab reaches the walls 15 cm away";
  const PanelFrame& main = tr.frames[0];
  for (double span : {main.x_hi - main.x_lo, main.y_hi - main.y_lo}) {
    EXPECT_GT(span, 2 * reach);  // the motion and the clearance lines on both sides
    EXPECT_LT(span, 5 * reach);  // ... and not much more
  }
  const PanelFrame& inset = tr.frames[1];
  EXPECT_NEAR((inset.x_hi - inset.x_lo) / inset.width, (inset.y_hi - inset.y_lo) / inset.height,
              1e-9 * (inset.x_hi - inset.x_lo) / inset.width);
  const PlanBody& slab = run_->site.bodies[run_->site.find("building/base")];
  double size = 0.0;
  for (Vec2 p : slab.plan_W) {
    EXPECT_TRUE(p.x > inset.x_lo && p.x < inset.x_hi && p.y > inset.y_lo && p.y < inset.y_hi);
    size = std::max(size, std::abs(p.x));
  }
  EXPECT_LT(inset.x_hi - inset.x_lo, 4 * size) << "the slab fills the inset";
  // The inset smaller than the main panel and beside it.
  EXPECT_LT(inset.width * inset.height, 0.5 * main.width * main.height);
  EXPECT_GE(inset.left, main.left + main.width);
  // Its corners numbered as the main panel's legend names them.
  for (const char* text : {"1", "2", "3", "4", "corner 1", "corner 4"})
    EXPECT_TRUE(has_text(tr.figure, text)) << text;
}

TEST_F(RunPictures, FrictionLimitsWithTheModelsCoefficientsOnEveryTangentialPanel) {
  const NamedFigure& ct = named(*figures_, "contacts.png");
  ASSERT_EQ(ct.frames.size(), 2 * run_->contact_log.pairs.size());
  ASSERT_EQ(run_->contact_log.pairs.size(), 4u);
  EXPECT_TRUE(has_text(ct.figure, "±μ_s F_N, μ_s = 0.5"));
  EXPECT_TRUE(has_text(ct.figure, "±μ_k F_N, μ_k = 0.3"));
  // Per F_T panel: 2 lines of slope ±0.5 and 2 of slope ±0.3 from the origin (data units).
  for (std::size_t p = 1; p < ct.frames.size(); p += 2) {
    const PanelFrame& f = ct.frames[p];
    int mu_s = 0, mu_k = 0;
    for (const Polyline& l : ct.figure.lines) {
      if (l.points.size() != 2) continue;
      const Point2 a = to_data(f, l.points[0]), b = to_data(f, l.points[1]);
      if (std::abs(a.x) > 1e-6 * f.x_hi || std::abs(a.y) > 1e-6 * f.x_hi || !(b.x > 0.0)) continue;
      if (l.points[1].x > f.left + f.width + 1e-9 || l.points[0].x < f.left - 1e-9) continue;
      if (l.points[0].y < f.bottom - 1e-9 || l.points[0].y > f.bottom + f.height + 1e-9) continue;
      mu_s += std::abs(std::abs(b.y / b.x) - 0.5) < 1e-9;
      mu_k += std::abs(std::abs(b.y / b.x) - 0.3) < 1e-9;
    }
    EXPECT_EQ(mu_s, 2) << "panel " << p;
    EXPECT_EQ(mu_k, 2) << "panel " << p;
  }
}

TEST_F(RunPictures, BearingLegendsNameAllBearingsAndTheFarthest) {
  const NamedFigure& hy = named(*figures_, "hysteresis.png");
  ASSERT_EQ(run_->isolators.size(), 16u);
  int all = 0, farthest = 0;
  for (const Text& t : hy.figure.texts) {
    all += t.text == "all 16 bearings";
    farthest += t.text.find("(largest: ") != std::string::npos;
  }
  EXPECT_EQ(all, 3);  // x, y and orbit panels
  EXPECT_EQ(farthest, 3);
}

// The friction of every contact the solver builds, by its label: a bumpered wall's rubber (both
// its contacts), a bumpered slab face's rubber, and the contact law's for the concrete pairs.
TEST(RunFriction, EveryContactOfTheModelGetsItsOwnCoefficients) {
  const std::string yaml = std::string(R"(structures:
  - name: building
    grid: {bays_x: [6 m, 6 m], bays_y: [6 m, 6 m]}
    plan: {rectangle: [12.45 m, 12.45 m]}
    columns: {section: [45 cm, 45 cm], E: 30 GPa, nu: 0.2}
    storeys: {count: 2, height: 3.2 m, mass: 300 t}
    base: {mass: 300 t}
    bearing: {model: bouc_wen, Tb: 2.0 s, QW: 5 %, uy: 1 cm}
    walls: {sides: [east], gap: 8 cm, bumper: {thickness: 4 cm, E: 10 MPa, height: 50 cm, e: 0.8,
                                               mu_static: 0.7, mu_kinetic: 0.4}}
  - name: west
    isolated: false
    adjacent: {to: building, side: west, gap: 10 cm}
    grid: {bays_x: [6 m], bays_y: [6 m, 6 m]}
    plan: {rectangle: [6.35 m, 12.35 m]}
    columns: {section: [35 cm, 35 cm], E: 30 GPa, nu: 0.2}
    storeys: {count: 2, height: 3.2 m, mass: 150 t}
    bumper: {thickness: 5 cm, E: 10 MPa, height: 30 cm, e: 0.7, mu_static: 0.9, mu_kinetic: 0.2}
contact: {mu_static: 0.5, mu_kinetic: 0.3}
ground_motion:
  L: {pulse: {amplitude: 0.8 m/s, period: 1 s}}
  T: {pulse: {amplitude: 0.4 m/s, period: 1 s}}
)");
  const ModelConfig config = load_model(YAML::Load(yaml), "inline.yaml", "");
  const Model model = build_model(config);
  int wall_rubber = 0, face_rubber = 0, concrete = 0;
  for (const auto& e : model.elements) {
    const std::string& label = e->label();
    if (label.find('|') == std::string::npos || label.find("/bearing") != std::string::npos)
      continue;
    const auto f = pair_friction(config, label);
    ASSERT_TRUE(f) << label;
    const bool bumper = label.ends_with("bumper") || label.ends_with("bumper bottomed");
    if (bumper && label.find("|wall east") != std::string::npos) {
      EXPECT_EQ(f->mu_static, 0.7) << label;
      EXPECT_EQ(f->mu_kinetic, 0.4) << label;
      ++wall_rubber;
    } else if (bumper) {
      EXPECT_EQ(f->mu_static, 0.9) << label;
      EXPECT_EQ(f->mu_kinetic, 0.2) << label;
      ++face_rubber;
    } else {
      EXPECT_EQ(f->mu_static, 0.5) << label;
      EXPECT_EQ(f->mu_kinetic, 0.3) << label;
      ++concrete;
    }
  }
  EXPECT_EQ(wall_rubber, 2);
  EXPECT_EQ(face_rubber, 4);  // the neighbour's two at each pounding floor
  EXPECT_GE(concrete, 3);     // the wall and two floors
}

}  // namespace
}  // namespace isopound::post
