// The cases of a study as models: base tree + `set` + each axis's overrides in order, read by the
// normal model loader; errors point at the study-file line of the override that caused them.
#pragma once

#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "solver/excitation/ground_motion.h"
#include "solver/structures/config.h"
#include "solver/study/study_spec.h"

namespace isopound {

struct CaseInput {
  ModelConfig config;  // output.histories is off
  std::string
      motion_key;  // equal keys <=> the same ground motion (canonical ground_motion subtree)
};

// Builds case models from a Study; const and safe to use from several threads at once.
class CaseBuilder {
 public:
  explicit CaseBuilder(const Study& study) : study_(study) {}

  // Throws InputError: at the override that set the offending key (study file), else at the key
  // in the base model; the message names the case.
  CaseInput input_of(std::int64_t case_id) const;

  // "record=RSN1084_NORTHR_SCS052, QW=0.05, variant=BL"
  std::string describe(std::int64_t case_id) const;

  // Canonical text of the overrides that shape the case's model (those not replaced by a later
  // one): two cases with equal identities have identical models.
  std::string identity(std::int64_t case_id) const;

  // The override that set the node at `path` (or its parent) in this case, nullptr if none.
  const Override* override_for(std::int64_t case_id, const ParameterPath& path) const;

  const Study& study() const { return study_; }

 private:
  std::vector<const Override*> overrides_of(std::int64_t case_id) const;
  const Study& study_;
};

// A ground motion loaded once for all the cases that use it.
struct PreparedMotion {
  GroundMotion motion;
  GroundMotionPeaks peaks;
};

// What validation learns about every case before any run starts.
struct ValidatedStudy {
  std::vector<std::int64_t> representative;  // per case: the lowest case id with the same model
  std::map<std::string, std::shared_ptr<const PreparedMotion>> motions;  // by CaseInput::motion_key
  std::int64_t distinct_models = 0;
  // The plausibility warnings of the cases' models (config.warnings), each once, with the first
  // case that gives it and how many do: "<warning> (case 3: gap=0.15; 4 cases)".
  std::vector<std::string> warnings;
  // Per case, its input as validation read it, which the run takes instead of reading it again
  // (a YAML clone and a model load, ~2 % of a small 2D run); kept for studies of up to
  // kKeptInputs cases (about 5 kB each for a 2D building: 50 MB at most), else empty.
  static constexpr std::int64_t kKeptInputs = 10000;
  std::vector<std::shared_ptr<const CaseInput>> inputs;
};

// Builds every case's model (in `threads` threads), resolves the peaks on it and loads each
// distinct ground motion once. Throws the InputError of the lowest failing case id.
ValidatedStudy validate_study(const Study& study, int threads);

}  // namespace isopound
