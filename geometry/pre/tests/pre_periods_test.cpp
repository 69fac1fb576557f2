// isopound-pre prints the periods exactly as `isopound modes` does (2D and 3D models).
#include <gtest/gtest.h>

#include "pre_test_support.h"

namespace isopound::pre::test {
namespace {

TEST(PrePeriods, SameTableAsIsopoundModes) {
  for (const char* config : {"configs/neighbour-example.yaml", "configs/3d-eccentric-v30.yaml",
                             "configs/3d-mid-storey-isolation.yaml"}) {
    const std::string model = (source_dir() / config).string();
    const auto modes = ::isopound::test::run_isopound("modes " + model);
    ASSERT_EQ(modes.exit_code, 0) << modes.output;
    const auto dir = scratch_dir("periods");
    const auto pre = run_pre(model + " -o " + dir.string() + " --no-plan");
    ASSERT_EQ(pre.exit_code, 0) << pre.output;
    EXPECT_NE(pre.output.find("Periods (as isopound modes prints them)\n" + modes.output),
              std::string::npos)
        << config << "\n"
        << pre.output << "\n---\n"
        << modes.output;
    std::filesystem::remove_all(dir);
  }
}

}  // namespace
}  // namespace isopound::pre::test
