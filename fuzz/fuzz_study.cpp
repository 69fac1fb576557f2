// libFuzzer target: a study file through load_study_file (what `isopound sweep` reads before it
// runs anything). The study sits in a scratch directory beside model.yaml and model3d.yaml
// (copies of two configs, the 2D and 3D models the seed studies use), so `model:` resolves;
// records named by the study do not exist there. Only InputError (exit 2) may escape the reader;
// anything else is a finding.
#include <cstdint>
#include <string>

#include "fuzz/fuzz_support.h"
#include "solver/study/study_spec.h"

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  namespace fs = std::filesystem;
  const fs::path configs = fs::path(ISOPOUND_SOURCE_DIR) / "configs";
  const auto copy = fs::copy_options::overwrite_existing;
  fs::copy_file(configs / "thesis-3storey-bw.yaml", isopound::fuzz::scratch_dir() / "model.yaml",
                copy);
  fs::copy_file(configs / "3d-xy5.yaml", isopound::fuzz::scratch_dir() / "model3d.yaml", copy);
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace isopound;
  const std::string path =
      fuzz::write_scratch("study.yaml", reinterpret_cast<const char*>(data), size);
  try {
    const Study study = load_study_file(path);
    (void)study.case_count();
  } catch (const InputError&) {
  }
  fuzz::check_key_registry();
  return 0;
}
