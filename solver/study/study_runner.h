// Running a study: validate every case, then compute the unfinished ones on worker threads (and
// MPI ranks), committing results to the database in batches; deterministic for any -j and -np.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "solver/study/study_cases.h"
#include "solver/study/study_mpi.h"
#include "solver/study/study_outputs.h"
#include "solver/study/study_spec.h"
#include "solver/study/study_store.h"

namespace isopound {

struct SweepOptions {
  std::string db_path;     // "" -> "<study file stem>.db" in the current directory
  int jobs = 0;            // worker threads per rank; 0 = the cores of the node shared by its ranks
  bool resume = false;     // continue an existing database (only its unfinished runs)
  bool overwrite = false;  // delete an existing database first
  bool quiet = false;      // no progress, no summary
  bool dry_run = false;    // validate and describe the study, run nothing
  bool strict = false;     // a case's plausibility warning is an error (exit 2, nothing run)
};

// One case computed from its validated inputs: histories off, ground motion from the cache.
class CaseRunner {
 public:
  CaseRunner(const Study& study, const ValidatedStudy& validated);
  // Never throws: a failed analysis (or any error) is returned with ok = false and its message.
  RunRecord run(std::int64_t case_id) const;

 private:
  CaseBuilder builder_;
  const ValidatedStudy& validated_;
  std::vector<OutputSelector> selectors_;
  int ensemble_ = 0;  // Study::ensemble
};

// The study's fingerprint stored in its database: study text, model text, record files, layout.
std::string study_fingerprint(const Study& study);

// Runs or resumes the study in `study_path`. Returns the exit code: 0 when every run finished
// (some may have failed: they are recorded), 130 when interrupted (SIGINT/SIGTERM; the finished
// runs are committed). Throws InputError for a malformed study or a database that does not fit
// (exists without --resume, made from another study), StoreError for database failures.
// Only rank 0 prints. A rank other than 0 returns rank 0's exit code for database problems.
int run_sweep(const std::string& study_path, const SweepOptions& options, const RankSession& ranks);

}  // namespace isopound
