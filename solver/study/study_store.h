// The results database of a study (embedded SQLite, WAL journal): one row per run, created
// 'pending' up front and completed in batched transactions, so a killed study resumes where it was.
//
// Tables: meta(key, value); runs(case_id, <axis columns>, status, steps, wall_seconds, session,
// <peak columns>, error); sessions(session, started_utc, jobs, ranks, resumed, runs_to_do);
// computations(id, case_id, session, rank): one row per analysis actually computed.
#pragma once

#include <sqlite3.h>

#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "solver/study/study_spec.h"

namespace isopound {

class StoreError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// What the tables hold, stored in meta as JSON so that export needs only the database.
struct StoreLayout {
  std::vector<std::string> axes;     // axis columns, in enumeration order
  std::vector<std::string> outputs;  // peak columns
  // Units of the axis and peak columns: outputs in SI ("m", "N", "-"); numeric axes hold SI
  // values ("SI"), label axes "label". Empty in databases written before units were stored.
  std::vector<std::string> axis_units;
  std::vector<std::string> output_units;
  std::vector<RatioSpec> ratios;
  std::vector<StatisticsSpec> statistics;

  std::string to_json() const;
  static StoreLayout from_json(const std::string& text);
  static StoreLayout of(const Study& study);
};

// A value of an axis column: a number (SI) or a label.
struct Cell {
  bool numeric = false;
  double number = 0.0;
  std::string text;
};

// A finished run as the workers report it. Duplicates of a computed run carry its values with
// computed = false (they are written but not counted as computations).
struct RunRecord {
  std::int64_t case_id = 0;
  bool ok = false;
  bool computed = true;
  int rank = 0;  // MPI rank that computed it
  std::string error;
  std::int64_t steps = 0;
  double wall_seconds = 0.0;
  std::vector<double> values;  // per peak column
};

// A row of `runs` as read back for export.
struct RunRow {
  std::int64_t case_id = 0;
  std::vector<Cell> axes;
  std::string status;       // pending | done | failed
  std::int64_t steps = -1;  // -1: NULL
  double wall_seconds = 0.0;
  std::vector<double> values;  // NaN for NULL
  std::string error;
};

class StudyStore {
 public:
  // A new database at `path` (which must not exist) holding every case as pending; `labels`
  // gives the axis cells of a case.
  static StudyStore create(const std::string& path, const StoreLayout& layout,
                           const std::map<std::string, std::string>& meta, std::int64_t case_count,
                           const std::function<std::vector<Cell>(std::int64_t)>& labels);
  // An existing database (read-only for export).
  static StudyStore open(const std::string& path, bool read_only);
  // False for a file SQLite reads but that holds no table yet (a sweep killed while creating it).
  static bool has_schema(const std::string& path);

  StudyStore(StudyStore&&) noexcept = default;
  StudyStore& operator=(StudyStore&&) noexcept = default;
  ~StudyStore();

  std::string meta(const std::string& key) const;  // "" when absent
  const StoreLayout& layout() const { return layout_; }
  std::int64_t case_count() const;
  std::vector<std::int64_t> unfinished_cases() const;
  std::int64_t count_with_status(const std::string& status) const;

  std::int64_t begin_session(int jobs, int ranks, bool resumed, std::int64_t runs_to_do);
  // Writes the runs (rows and computation log) in one transaction.
  void commit(const std::vector<RunRecord>& runs, std::int64_t session);

  std::vector<RunRow> read_runs() const;

 private:
  struct Closer {
    void operator()(sqlite3* db) const { sqlite3_close_v2(db); }
  };
  StudyStore(std::unique_ptr<sqlite3, Closer> db, std::string path);
  void execute(const std::string& sql) const;
  [[noreturn]] void fail(const std::string& what) const;

  std::unique_ptr<sqlite3, Closer> db_;
  std::string path_;
  StoreLayout layout_;
};

}  // namespace isopound
