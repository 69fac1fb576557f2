// Helpers of the isopound-pre tests: scratch directories, model files written from text, running
// the tool, reading a PNG (pre_png_test.cpp).
#pragma once

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "png_image.h"
#include "test_support.h"

namespace isopound::pre::test {

using ::isopound::test::CommandResult;
using ::isopound::test::source_dir;

inline std::filesystem::path scratch_dir(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() /
                   ("isopound-pre-test-" + std::to_string(::getpid()) + "-" + name);
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

inline std::string write_model(const std::filesystem::path& dir, const std::string& text) {
  const std::string path = (dir / "model.yaml").string();
  std::ofstream(path) << text;
  return path;
}

// Runs isopound-pre with DISPLAY unset (as in CI).
inline CommandResult run_pre(const std::string& args) {
  return ::isopound::test::run_command("env -u DISPLAY " + std::string(ISOPOUND_PRE_BINARY) + " " +
                                       args);
}

using ::isopound::test::Image;
using ::isopound::test::read_png;

}  // namespace isopound::pre::test
