// The hot loop allocates nothing: between the 100th accepted step and the end of an analysis
// (stepper, elements, contacts, events, peaks, energy), malloc is never called. This binary
// interposes malloc with a counter (glibc's __libc_malloc does the work), so it is built apart
// from the suite and not under AddressSanitizer (which interposes malloc itself).
#include <gtest/gtest.h>

#include <atomic>
#include <cstdlib>

#include "solver/core/analysis.h"
#include "solver/io/model_input.h"
#include "solver/structures/job.h"
#include "test_support.h"

namespace {
std::atomic<long> g_mallocs{0};
}  // namespace

extern "C" {
void* __libc_malloc(std::size_t size);
void* __libc_calloc(std::size_t count, std::size_t size);
void* __libc_realloc(void* p, std::size_t size);
void* malloc(std::size_t size) {
  g_mallocs.fetch_add(1, std::memory_order_relaxed);
  return __libc_malloc(size);
}
void* calloc(std::size_t count, std::size_t size) {
  g_mallocs.fetch_add(1, std::memory_order_relaxed);
  return __libc_calloc(count, size);
}
void* realloc(void* p, std::size_t size) {
  g_mallocs.fetch_add(1, std::memory_order_relaxed);
  return __libc_realloc(p, size);
}
}

namespace isopound {
namespace {

// Counts the allocations from the 100th accepted step on (allocates nothing itself).
class AllocationWatch final : public StepObserver {
 public:
  void after_step(double, const Model&) override {
    if (++steps_ == 100) at_100_ = g_mallocs.load();
    last_ = g_mallocs.load();
  }
  long steps() const { return steps_; }
  long allocations() const { return last_ - at_100_; }

 private:
  long steps_ = 0, at_100_ = 0, last_ = 0;
};

void expect_no_allocation(const char* config_file) {
  ModelConfig config = load_model_file((test::source_dir() / "configs" / config_file).string());
  config.output.histories = false;
  const GroundMotion motion = load_ground_motion(config.ground_motion, true);
  Model model = build_model(config);
  RunOptions options = run_options(config);
  AllocationWatch watch;
  options.observer = &watch;
  const AnalysisResult result = run_analysis(model, motion, options);
  ASSERT_GT(watch.steps(), 1000) << config_file;
  EXPECT_EQ(watch.allocations(), 0)
      << config_file << ": allocations in the hot loop over " << watch.steps() - 100 << " steps";
}

TEST(HotLoop, CountsAnAllocation) {
  // The counter sees a heap allocation (else the tests below would prove nothing).
  const long before = g_mallocs.load();
  std::vector<double>* v = new std::vector<double>(1000, 1.0);
  EXPECT_GT(g_mallocs.load(), before);
  delete v;
}

TEST(HotLoop, ThreeDPoundingAgainstWallsAllocatesNothing) {
  expect_no_allocation("tutorial-3d.yaml");
}

TEST(HotLoop, TwoDBuildingAllocatesNothing) {
  expect_no_allocation("tutorial.yaml");
}

// Rubber bumpers on the walls (issue 27): the bumper law and its outputs allocate nothing.
TEST(HotLoop, TwoDBumpersAllocateNothing) {
  ISOPOUND_REQUIRE_RECORDS();
  expect_no_allocation("2d-bumpers.yaml");
}

// Rubber bumpers on 3D moat walls (issue 27), bottoming out: the length law allocates nothing.
TEST(HotLoop, ThreeDBumpersAllocateNothing) {
  ISOPOUND_REQUIRE_RECORDS();
  expect_no_allocation("xy5-bumpers-5cm.yaml");
}

TEST(HotLoop, EccentricBuildingAllocatesNothing) {
  ISOPOUND_REQUIRE_RECORDS();
  expect_no_allocation("3d-eccentric-v30.yaml");
}

TEST(HotLoop, YieldingColumnsAllocateNothing) {  // 48 coupled Bouc-Wen columns, walls
  ISOPOUND_REQUIRE_RECORDS();
  expect_no_allocation("3d-xy5-yielding.yaml");
}

TEST(HotLoop, TwoDWallsAllocateNothing) {
  ISOPOUND_REQUIRE_RECORDS();
  expect_no_allocation("chapter4-3storey-kelvin_voigt.yaml");
}

}  // namespace
}  // namespace isopound

namespace isopound {
namespace {

// Yielding storeys (Bouc-Wen; peak-oriented with P-Delta) against moat walls (issue 23).
TEST(HotLoop, YieldingStoreysAllocateNothing) {
  ISOPOUND_REQUIRE_RECORDS();
  expect_no_allocation("thesis-3storey-bw-yielding.yaml");
  expect_no_allocation("thesis-3storey-peak-oriented-pdelta.yaml");
}

}  // namespace
}  // namespace isopound
