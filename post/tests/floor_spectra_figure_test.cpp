// The floor-spectra figure's axes and draw order (post/plot_floor_spectra.h) on spectra built by
// hand: a log period axis when the periods span decades, a log PSA axis only in the panel whose
// peak dwarfs its long periods (a base slab's impacts), every curve inside its panel's range, the
// peak floor acceleration in the title, and the centre of mass's RotD100 drawn over the corners'.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <tuple>

#include "post/plot_floor_spectra.h"
#include "solver/core/constants.h"

namespace isopound::post {
namespace {

// A spectrum of `peak` g at `at` s falling to `tail` g at 4 s (smooth enough for the rules).
std::vector<double> shape(const std::vector<double>& T, double peak, double at, double tail) {
  std::vector<double> psa;
  for (double t : T) {
    const double s = std::exp(-std::pow(std::log((t + 1e-3) / at), 2));
    psa.push_back(kGravity * (tail + (peak - tail) * s));
  }
  return psa;
}

PlaceSpectra place3d(const std::string& level, double z, const std::vector<double>& T, double peak,
                     double at, double tail, const std::string& point) {
  PlaceSpectra p;
  p.structure = "building";
  p.level = level;
  p.label = "building/" + level + "/" + point;
  p.elevation = z;
  p.x = {p.label, T, {}, shape(T, 0.7 * peak, at, tail)};
  p.y = Spectrum{p.label, T, {}, shape(T, 0.9 * peak, at, tail)};
  RotDSpectrum r;
  r.period = T;
  r.psa100 = shape(T, peak, at, tail);
  r.psa50 = r.psa100;
  p.rotd = r;
  return p;
}

// Periods 0, 0.02 ... 4 s (k / 50, exact at 4 s); a base slab peaking at 90 g (0.05 s) over 1 g, a
// floor at 5 g over 2 g; the corners 10 % above the centre of mass.
FloorSpectra three_d() {
  FloorSpectra f;
  f.three_d = true;
  f.steps = 1000;
  f.periods.push_back(0.0);
  for (int k = 1; k <= 200; ++k) f.periods.push_back(k / 50.0);
  const auto& T = f.periods;
  f.ground = place3d("", 0, T, 0.5, 1.0, 0.1, "");
  for (const auto& [level, z, peak, tail] :
       {std::tuple{"base", 0.0, 90.0, 1.0}, std::tuple{"floor 1", 3.2, 5.0, 2.0}}) {
    f.places.push_back(place3d(level, z, T, peak, 0.05, tail, "CM"));
    for (int k = 1; k <= 4; ++k)
      f.places.push_back(place3d(level, z, T, 1.1 * peak, 0.05, 1.1 * tail, "corner"));
    // The T = 0 values (the peak floor accelerations): a corner's above the centre's.
    f.places[f.places.size() - 5].rotd->psa100[0] = 0.5 * peak * kGravity;
    f.places[f.places.size() - 2].rotd->psa100[0] = 0.6 * peak * kGravity;
  }
  return f;
}

// The largest and smallest PSA [g] of a level's drawn curves (0 < T <= 4 s) and the ground's.
std::pair<double, double> psa_range(const FloorSpectra& f, const std::string& level) {
  double lo = 1e300, hi = 0.0;
  const auto take = [&](const std::vector<double>& psa) {
    for (std::size_t i = 0; i < f.periods.size(); ++i)
      if (f.periods[i] > 0.0 && f.periods[i] <= 4.0)
        lo = std::min(lo, psa[i] / kGravity), hi = std::max(hi, psa[i] / kGravity);
  };
  take(f.ground.rotd->psa100);
  for (const PlaceSpectra& p : f.places)
    if (p.level == level) take(p.x.psa), take(p.y->psa), take(p.rotd->psa100);
  return {lo, hi};
}

bool has_text(const Figure& fig, const std::string& text) {
  return std::any_of(fig.texts.begin(), fig.texts.end(),
                     [&](const Text& t) { return t.text == text; });
}

TEST(PostFloorSpectraFigure, LogAxesWhereThePeriodsAndThePeaksSpanDecades) {
  std::vector<PanelFrame> frames;
  const FloorSpectra f = three_d();
  const Figure fig = floor_spectra_figure(f, &frames);
  ASSERT_EQ(frames.size(), 2u);  // floor 1 first, then the base
  // 0.02 to 4 s: two decades and more, a log period axis on both panels, said in the titles.
  for (const PanelFrame& p : frames) {
    EXPECT_TRUE(p.log_x);
    EXPECT_LE(p.x_lo, std::log10(0.02));
    EXPECT_GE(p.x_hi, std::log10(4.0));
  }
  EXPECT_TRUE(has_text(fig, "period T [s], log scale"));
  // The floor (5 g over 2 g) stays linear from 0; the base (99 g over 1.1 g) is log and shows
  // both its peak and its 4 s value.
  const auto [floor_lo, floor_hi] = psa_range(f, "floor 1");
  const auto [base_lo, base_hi] = psa_range(f, "base");
  ASSERT_GT(base_hi, 90.0);
  ASSERT_LT(base_lo, 0.2);
  EXPECT_FALSE(frames[0].log_y);
  EXPECT_EQ(frames[0].y_lo, 0.0);
  EXPECT_GE(frames[0].y_hi, floor_hi);
  EXPECT_TRUE(frames[1].log_y);
  EXPECT_LE(frames[1].y_lo, std::log10(base_lo));
  EXPECT_GE(frames[1].y_hi, std::log10(base_hi));
  EXPECT_TRUE(has_text(fig, "PSA [g], log scale"));
  EXPECT_TRUE(has_text(fig, "PSA [g]"));
  // The T = 0 values (off a log axis) in the titles: the corners' 0.6 x 90 g at the base.
  EXPECT_TRUE(has_text(fig, "building/base (z = 0 m): PFA 54 g"));
  EXPECT_TRUE(has_text(fig, "building/floor 1 (z = 3.2 m): PFA 3 g"));
  // The legend names what each curve is.
  for (const char* label :
       {"CM, x", "CM, y", "corners, largest RotD100", "CM, RotD100", "ground, RotD100"})
    EXPECT_TRUE(has_text(fig, label)) << label;
  EXPECT_TRUE(has_text(fig,
                       "Floor response spectra, ξ = 5 % (every analysis step); CM: centre of "
                       "mass"));
}

TEST(PostFloorSpectraFigure, CentreOfMassRotD100IsDrawnOverTheCornersAndNarrower) {
  const Figure fig = floor_spectra_figure(three_d());
  // Per panel: the corners' curve (many points, wide) and then the centre's (narrower).
  std::vector<std::size_t> corners, centre;
  for (std::size_t i = 0; i < fig.lines.size(); ++i) {
    if (fig.lines[i].points.size() < 50) continue;  // legend swatches, ticks, frames
    if (fig.lines[i].colour == kCornersColour) corners.push_back(i);
    if (fig.lines[i].colour == kCentreRotDColour) centre.push_back(i);
  }
  ASSERT_EQ(corners.size(), 2u);
  ASSERT_EQ(centre.size(), 2u);
  for (std::size_t p = 0; p < 2; ++p) {
    EXPECT_LT(corners[p], centre[p]) << "panel " << p;
    EXPECT_GT(fig.lines[corners[p]].width, 2 * fig.lines[centre[p]].width);
  }
}

TEST(PostFloorSpectraFigure, PeriodsWithinADecadeKeepALinearAxis) {
  FloorSpectra f;
  f.periods = {0.5, 1.0, 2.0, 3.0, 4.0};
  const std::vector<double> psa{2 * kGravity, 3 * kGravity, 2 * kGravity, kGravity, kGravity};
  f.ground.x = {"ground", f.periods, {}, psa};
  PlaceSpectra floor;
  floor.structure = "frame";
  floor.level = "floor 1";
  floor.x = {"floor", f.periods, {}, psa};
  f.places.push_back(floor);
  std::vector<PanelFrame> frames;
  const Figure fig = floor_spectra_figure(f, &frames);
  ASSERT_EQ(frames.size(), 1u);
  EXPECT_FALSE(frames[0].log_x);
  EXPECT_FALSE(frames[0].log_y);
  EXPECT_TRUE(has_text(fig, "period T [s]"));
  EXPECT_TRUE(has_text(fig, "frame/floor 1 (z = 0 m)"));  // no T = 0: no PFA
}

}  // namespace
}  // namespace isopound::post
