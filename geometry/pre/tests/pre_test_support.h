// Helpers of the isopound-pre tests: scratch directories, model files written from text, the
// check tests' models, running the tool, reading a PNG (pre_png_test.cpp).
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

// Models of the check tests (pre_checks_test.cpp, pre_site_agreement_test.cpp).
// A one-storey 6 x 6 m building "a" (lines 1-14), isolated on bearings under its columns.
inline const std::string kColumns = R"(          - {at: [-3 m, -3 m]}
          - {at: [3 m, -3 m]}
          - {at: [3 m, 3 m]}
          - {at: [-3 m, 3 m]}
)";
inline std::string building_a(const std::string& columns = kColumns, const std::string& tail = "") {
  return R"(structures:
  - name: a
    plan: {rectangle: [6 m, 6 m]}
    columns: {section: [40 cm, 40 cm], E: 30 GPa, nu: 0.2}
    storeys:
      - height: 3 m
        mass: 100 t
        columns:
)" + columns +
         R"(    base: {mass: 100 t}
    bearing: {model: linear, Tb: 2 s}
)" + tail;
}

// A fixed-base one-storey building "b" at `position`, storey height `height`.
inline std::string building_b(const std::string& position, const std::string& height,
                              const std::string& plan = "{rectangle: [6 m, 6 m]}") {
  return R"(  - name: b
    isolated: false
    position: )" +
         position + R"(
    plan: )" +
         plan + R"(
    columns: {section: [40 cm, 40 cm], E: 30 GPa, nu: 0.2}
    damping: {type: none}
    storeys:
      - height: )" +
         height + R"(
        mass: 100 t
        columns: [{at: [-2 m, -2 m]}, {at: [2 m, -2 m]}, {at: [2 m, 2 m]}, {at: [-2 m, 2 m]}]
)";
}

using ::isopound::test::Image;
using ::isopound::test::read_png;

}  // namespace isopound::pre::test
