// Ensembles in studies (`ensemble: N`): each case runs N members (ensemble.h) one after another;
// columns per peak: member 0's value, then the members' min, mean, max, sample std; the horizon.
#pragma once

#include <string>
#include <vector>

#include "solver/excitation/ground_motion.h"
#include "solver/structures/config.h"
#include "solver/study/study_outputs.h"

namespace isopound {

// The extra peak columns of a study with `ensemble: N` (N >= 2), after its own columns: for each
// output column c, "c_ens_min", "c_ens_mean", "c_ens_max", "c_ens_std" (unit of c), then
// "ens_horizon_s" (s: the predictability horizon of the case, ensemble.h).
std::vector<std::string> ensemble_column_names(const std::vector<std::string>& output_columns);
std::vector<std::string> ensemble_column_units(const std::vector<std::string>& output_units);

// Runs the N members of one case (member 0 = the case as given) and returns its row of peak
// values: member 0's value of each selector, then the columns above. A selector that does not
// resolve in this case's model gives NaN (as for one run). `steps`: member 0's accepted steps.
// Throws what run_analysis throws.
std::vector<double> ensemble_case_values(const ModelConfig& config, const GroundMotion& motion,
                                         const GroundMotionPeaks& motion_peaks,
                                         const std::vector<OutputSelector>& selectors, int members,
                                         long& steps);

}  // namespace isopound
