// A check of the PNG reading (tests/png_image.h) on a figure with a known
// rectangle, so that pixel tests elsewhere cannot pass for a misread image.
#include <gtest/gtest.h>

#include <stdexcept>

#include "post/figure.h"
#include "post/headless.h"
#include "post/render_png.h"
#include "post_test_support.h"

namespace isopound::post::test {

TEST(PostRender, FigureLandsOnTheExpectedPixels) {
  const PrivateDisplay display(false);
  Figure f;
  f.width = 320;
  f.height = 200;
  // A red rectangle from (40, 30) to (120, 90) (y up), a blue line at y = 150, a text.
  f.polygons.push_back({{{40, 30}, {120, 30}, {120, 90}, {40, 90}}, {255, 0, 0}});
  f.lines.push_back({{{10, 150}, {300, 150}}, {0, 0, 255}, 3.0});
  f.texts.push_back({{160, 180}, "u [m/s²] ξ θ", 14, {0, 0, 0}});
  const auto dir = scratch_dir("render");
  const std::string path = (dir / "f.png").string();
  render_png(f, path);
  const Image img = read_png(path);
  ASSERT_EQ(img.width, 320);
  ASSERT_EQ(img.height, 200);
  EXPECT_GT(img.variance(), 10.0);
  const auto is = [&](int x, int y, Rgb c) {
    const unsigned char* p = img.at(x, y);
    return std::abs(p[0] - c.r) < 40 && std::abs(p[1] - c.g) < 40 && std::abs(p[2] - c.b) < 40;
  };
  EXPECT_TRUE(is(80, 60, {255, 0, 0}));       // inside the rectangle
  EXPECT_TRUE(is(20, 60, {255, 255, 255}));   // left of it
  EXPECT_TRUE(is(80, 100, {255, 255, 255}));  // above it
  EXPECT_TRUE(is(150, 150, {0, 0, 255}));     // on the line
  EXPECT_TRUE(is(150, 140, {255, 255, 255}));
  // Some dark text pixels near the top centre.
  int dark = 0;
  for (int y = 165; y < 198; ++y)
    for (int x = 60; x < 260; ++x)
      if (img.at(x, y)[0] < 100) ++dark;
  EXPECT_GT(dark, 30);
  std::filesystem::remove_all(dir);
}

}  // namespace isopound::post::test
