// Helpers of the isopound-post tests: temporary directories, running the tools, reading PNGs.
// PNG rows are read top to bottom; pixel(x, y_up) takes y from the bottom like Figure coordinates.
#pragma once

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "png_image.h"
#include "post/plot_run.h"
#include "test_support.h"

namespace isopound::post::test {

using ::isopound::test::file_text;
using ::isopound::test::run_command;
using ::isopound::test::source_dir;

// A fresh directory under the build tree for one test.
inline std::filesystem::path scratch_dir(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() /
                   ("isopound-post-test-" + std::to_string(::getpid()) + "-" + name);
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

inline ::isopound::test::CommandResult run_post(const std::string& args) {
  return ::isopound::test::run_command(std::string(ISOPOUND_POST_BINARY) + " " + args);
}
inline ::isopound::test::CommandResult run_solver(const std::string& args) {
  return ::isopound::test::run_command(std::string(ISOPOUND_BINARY) + " " + args);
}

// The DataSets of a .pvd collection in file order: (timestep, file).
inline std::vector<std::pair<double, std::string>> read_pvd(const std::filesystem::path& pvd) {
  std::ifstream in(pvd);
  std::stringstream text;
  text << in.rdbuf();
  const std::string s = text.str();
  const std::regex item("<DataSet timestep=\"([^\"]+)\"[^>]*file=\"([^\"]+)\"");
  std::vector<std::pair<double, std::string>> frames;
  for (auto it = std::sregex_iterator(s.begin(), s.end(), item); it != std::sregex_iterator(); ++it)
    frames.push_back({std::stod((*it)[1]), (*it)[2]});
  return frames;
}

// `isopound-post ARGS [--damping D] -o DIR/D` for every way of writing a 5 % damping ratio, and
// without --damping (the default): each exits 0 and writes the same `file`, byte for byte (checked
// here); returns its text. The run with 0.05 writes into DIR/0.05.
inline std::string same_text_for_every_five_percent(const std::string& args,
                                                    const std::filesystem::path& dir,
                                                    const std::string& file) {
  std::string first;
  int k = 0;
  for (const char* damping : {"0.05", "'5 %'", "5%", ""}) {
    const std::filesystem::path out =
        dir / (k++ == 0 ? std::string("0.05") : "5-" + std::to_string(k));
    const auto r = run_post(args + (*damping ? std::string(" --damping ") + damping : "") +
                            " -o '" + out.string() + "'");
    EXPECT_EQ(r.exit_code, 0) << damping << ": " << r.output;
    const std::string text = file_text(out / file);
    if (first.empty())
      first = text;
    else
      EXPECT_EQ(text, first) << "--damping " << damping << " against 0.05";
  }
  EXPECT_FALSE(first.empty());
  return first;
}

// Every placed peak text (PanelFrame::label_boxes) inside its plot area, off the legend and off
// every other peak text.
inline bool inside_plot(const PanelFrame& f, const Box& b) {
  constexpr double kPx = 1e-9;
  return b.x0 >= f.left - kPx && b.x1 <= f.left + f.width + kPx && b.y0 >= f.bottom - kPx &&
         b.y1 <= f.bottom + f.height + kPx;
}

inline void expect_labels_clear(const NamedFigure& figure) {
  for (std::size_t p = 0; p < figure.frames.size(); ++p) {
    const PanelFrame& f = figure.frames[p];
    for (std::size_t i = 0; i < f.label_boxes.size(); ++i) {
      const Box& b = f.label_boxes[i];
      if (b.empty()) continue;
      EXPECT_TRUE(inside_plot(f, b)) << figure.file << " panel " << p << " text " << i;
      EXPECT_EQ(b.overlap(f.legend_box), 0.0) << figure.file << " panel " << p << " text " << i;
      for (std::size_t j = 0; j < i; ++j)
        EXPECT_EQ(b.overlap(f.label_boxes[j]), 0.0)
            << figure.file << " panel " << p << " texts " << j << ", " << i;
    }
  }
}

using ::isopound::test::Image;
using ::isopound::test::read_png;

}  // namespace isopound::post::test
