// libFuzzer target: the polygon-pairs file of `isopound geometry overlap`, read and then
// measured as the command does (fast overlap, exact overlap, separation; convex or not). Only InputError
// (exit 2) may escape; anything else is a finding.
#include <cstdint>
#include <string>

#include "fuzz/fuzz_support.h"
#include "geometry/plan_overlap.h"
#include "solver/io/polygon_input.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace isopound;
  const std::string path =
      fuzz::write_scratch("pairs.yaml", reinterpret_cast<const char*>(data), size);
  try {
    for (const PolygonPair& p : load_polygon_pairs_file(path)) {
      (void)plan_overlap(p.a, p.b, OverlapMethod::kFast);
      (void)plan_overlap(p.a, p.b, OverlapMethod::kExact);
      (void)plan_separation(p.a, p.b);
    }
  } catch (const InputError&) {
  }
  return 0;
}
