// libFuzzer target: a model file (2D or 3D) through what `isopound check` runs: parse, read,
// load the ground motion, check the step against it, assemble the model. Bad input must end in
// the errors the CLI turns into exit 2 (InputError, RecordError, std::invalid_argument) or 3
// (AnalysisError); anything else escaping (another exception, a sanitizer report, a hang, memory
// above -rss_limit_mb) is a finding. Records named by the model are looked up beside a scratch
// path that holds none, so only the reader's own errors are reached for them.
#include <cstdint>
#include <string>

#include "fuzz/fuzz_support.h"
#include "solver/core/analysis.h"
#include "solver/io/model_input.h"
#include "solver/structures/job.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace isopound;
  const std::string text(reinterpret_cast<const char*>(data), size);
  const std::string path = (fuzz::scratch_dir() / "model.yaml").string();
  try {
    const YAML::Node root = parse_single_document(text, path, "a model file");
    const ModelConfig config = load_model(root, path, fuzz::scratch_dir().string());
    const GroundMotion motion =
        load_ground_motion(config.ground_motion, !config.structures3d.empty());
    check_step_against_record(config.analysis, motion);
    const Model model = build_model(config);
    (void)model;
  } catch (const InputError&) {
  } catch (const RecordError&) {
  } catch (const std::invalid_argument&) {
  } catch (const AnalysisError&) {
  }
  fuzz::check_key_registry();
  return 0;
}
