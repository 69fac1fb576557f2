// Helpers of the isopound-post tests: temporary directories, running the tools, reading PNGs.
// PNG rows are read top to bottom; pixel(x, y_up) takes y from the bottom like Figure coordinates.
#pragma once

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "png_image.h"
#include "test_support.h"

namespace isopound::post::test {

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

using ::isopound::test::Image;
using ::isopound::test::read_png;

}  // namespace isopound::post::test
