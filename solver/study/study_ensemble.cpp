// Ensembles in studies: the members of a case run in turn on the case's worker thread (cases
// already run in parallel), so a case's values do not depend on -j.
#include "solver/study/study_ensemble.h"

#include <cmath>
#include <limits>
#include <stdexcept>

#include "solver/study/ensemble.h"

namespace isopound {

namespace {
constexpr const char* kSuffixes[] = {"_ens_min", "_ens_mean", "_ens_max", "_ens_std"};
}  // namespace

std::vector<std::string> ensemble_column_names(const std::vector<std::string>& output_columns) {
  std::vector<std::string> names;
  for (const std::string& c : output_columns)
    for (const char* suffix : kSuffixes) names.push_back(c + suffix);
  names.push_back("ens_horizon_s");
  return names;
}

std::vector<std::string> ensemble_column_units(const std::vector<std::string>& output_units) {
  std::vector<std::string> units;
  for (const std::string& u : output_units)
    for (std::size_t k = 0; k < std::size(kSuffixes); ++k) units.push_back(u);
  units.push_back("s");
  return units;
}

std::vector<double> ensemble_case_values(const ModelConfig& config, const GroundMotion& motion,
                                         const GroundMotionPeaks& motion_peaks,
                                         const std::vector<OutputSelector>& selectors, int members,
                                         long& steps) {
  EnsembleOptions options;
  options.members = members;
  options.jobs = 1;
  ModelConfig quiet = config;
  quiet.output.histories = false;  // nothing on disk; the tracker still sees every row
  const std::size_t s_count = selectors.size();
  std::vector<std::vector<double>> per_selector(s_count, std::vector<double>(members));
  std::vector<EnsembleTrack> tracks(members);
  double analysed = 0.0;
  for (int m = 0; m < members; ++m) {
    EnsembleMember run = run_ensemble_member(quiet, motion, m, options);
    for (std::size_t s = 0; s < s_count; ++s) {
      try {
        per_selector[s][m] =
            evaluate_output(resolve_output(selectors[s], run.model), run.analysis, motion_peaks);
      } catch (const std::invalid_argument&) {  // an element this case does not have
        per_selector[s][m] = std::numeric_limits<double>::quiet_NaN();
      }
    }
    if (m == 0) {
      steps = run.analysis.stats.steps;
      analysed = run.analysis.stats.duration;
    }
    tracks[m] = std::move(run.track);
  }
  std::vector<double> values;
  for (std::size_t s = 0; s < s_count; ++s) values.push_back(per_selector[s][0]);
  for (std::size_t s = 0; s < s_count; ++s) {
    bool missing = false;
    for (const double x : per_selector[s]) missing = missing || std::isnan(x);
    const MemberStatistics st = member_statistics(per_selector[s]);
    for (const double x : {st.min, st.mean, st.max, st.stddev})
      values.push_back(missing ? std::numeric_limits<double>::quiet_NaN() : x);
  }
  std::vector<const EnsembleTrack*> pointers;
  for (const EnsembleTrack& t : tracks) pointers.push_back(&t);
  values.push_back(predictability_horizon(pointers, analysed, options.horizon_distance).time);
  return values;
}

}  // namespace isopound
