// Output of a run: summary.json (peaks, energy, settings, statistics; SI, unit in each key),
// histories.csv (one row per output time), and a short human-readable summary for the console.
#pragma once

#include <nlohmann/json.hpp>
#include <ostream>
#include <string>

#include "solver/structures/config.h"
#include "solver/structures/job.h"

namespace isopound {

// `unobstructed`: the same run without walls and neighbours (or null); adds its peaks and the
// amplification of each peak of the main building (with pounding / without).
nlohmann::json summary_json(const ModelConfig& config, const JobResult& job,
                            const JobResult* unobstructed = nullptr);
void write_summary(const std::string& path, const ModelConfig& config, const JobResult& job,
                   const JobResult* unobstructed = nullptr);
void write_histories(const std::string& path, const History& history);
void print_summary(std::ostream& out, const ModelConfig& config, const JobResult& job);

}  // namespace isopound
