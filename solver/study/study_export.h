// Tidy CSV tables of a study database, for pandas and R: runs.csv (one row per run), ratios.csv
// (variant ratios, the other axes equal) and statistics.csv (long form: one row per group and
// peak).
#pragma once

#include <string>
#include <vector>

#include "solver/study/study_store.h"

namespace isopound {

struct ExportOptions {
  bool timing = false;  // add wall_seconds to runs.csv (it differs from run to run)
};

// CSV texts; ratios / statistics are empty when the study defines none.
struct ExportTables {
  std::string units;  // table,column,unit for every column of the other tables
  std::string runs;
  std::string ratios;
  std::string statistics;
};

// Sorted by case id, numbers in shortest round-trip form: the same results give the same bytes.
ExportTables export_tables(const StudyStore& store, const ExportOptions& options);

// Writes runs.csv, ratios.csv, statistics.csv (those not empty) into `dir` (created if needed);
// returns the paths written.
std::vector<std::string> write_export(const StudyStore& store, const std::string& dir,
                                      const ExportOptions& options);

}  // namespace isopound
