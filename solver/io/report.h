// Output of a run: summary.json (peaks, energy, settings, statistics; SI, unit in each key),
// histories.csv (one row per output time), and a short human-readable summary for the console.
#pragma once

#include <cstdio>
#include <nlohmann/json.hpp>
#include <ostream>
#include <string>

#include "solver/structures/config.h"
#include "solver/structures/job.h"

namespace isopound {

// Every peak in summary.json has this one shape: {value (max |x|), unit, time_s, positive,
// positive_time_s, negative, negative_time_s}, all in `unit` (SI).
nlohmann::json peak_json(const Peak& p, const std::string& unit);

// `unobstructed`: the same run without walls and neighbours (or null); adds its peaks and the
// amplification of each peak of the main building (with pounding / without).
inline constexpr const char* kIsopoundVersion = "0.1.0";

nlohmann::json summary_json(const ModelConfig& config, const JobResult& job,
                            const UnobstructedResult* unobstructed = nullptr);
void write_summary(const std::string& path, const ModelConfig& config, const JobResult& job,
                   const UnobstructedResult* unobstructed = nullptr);
// The unobstructed peaks, amplifications and the critical gap of every contact.
void print_unobstructed(std::ostream& out, const ModelConfig& config, const JobResult& job,
                        const UnobstructedResult& unobstructed);
void write_histories(const std::string& path, const History& history);

// histories.csv written row by row while the analysis runs (memory does not grow with the
// record). The constructor opens (throws std::runtime_error "cannot write PATH: reason");
// close() flushes and reports a write error.
class CsvHistoryWriter : public HistorySink {
 public:
  explicit CsvHistoryWriter(std::string path);
  ~CsvHistoryWriter() override;
  CsvHistoryWriter(const CsvHistoryWriter&) = delete;
  CsvHistoryWriter& operator=(const CsvHistoryWriter&) = delete;
  void begin(const std::vector<std::string>& columns) override;
  void row(const double* values, std::size_t count) override;
  void close();
  std::size_t rows() const { return rows_; }

 private:
  std::string path_;
  std::FILE* file_ = nullptr;
  std::size_t rows_ = 0;
};
void print_summary(std::ostream& out, const ModelConfig& config, const JobResult& job);

}  // namespace isopound
