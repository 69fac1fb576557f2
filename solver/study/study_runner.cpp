// Sweep orchestration (see study_runner.h): validate all cases, open or create the database, then
// compute the unfinished runs; the main thread of rank 0 commits every 0.5 s or 64 runs.
#include "solver/study/study_runner.h"

#include <fcntl.h>
#include <sched.h>
#include <signal.h>
#include <sys/file.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <map>
#include <optional>
#include <thread>
#include <unordered_map>

#include "solver/structures/contact_log.h"
#include "solver/structures/job.h"
#include "solver/study/study_ensemble.h"
#include "solver/study/study_hash.h"
#include "solver/study/study_pool.h"
#include "solver/study/study_progress.h"

namespace isopound {
namespace {

std::string join_lines(const std::vector<std::string>& lines) {
  std::string text;
  for (const std::string& line : lines) text += (text.empty() ? "" : "\n") + line;
  return text;
}

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

constexpr std::size_t kCommitRuns = 64;
constexpr double kCommitSeconds = 0.5;
constexpr std::chrono::milliseconds kLocalWait{100};
constexpr std::chrono::milliseconds kRankWait{2};  // MPI ranks poll their messages this often

std::atomic<bool> g_interrupted{false};
static_assert(std::atomic<bool>::is_always_lock_free, "set from a signal handler");

extern "C" void on_interrupt(int) {
  g_interrupted.store(true);
}

// SIGINT / SIGTERM set a flag for the duration of a sweep: stop handing out cases, commit, exit
// 130.
class InterruptGuard {
 public:
  InterruptGuard() {
    g_interrupted = false;
    struct sigaction action {};
    action.sa_handler = on_interrupt;
    sigemptyset(&action.sa_mask);
    sigaction(SIGINT, &action, &old_int_);
    sigaction(SIGTERM, &action, &old_term_);
  }
  ~InterruptGuard() {
    sigaction(SIGINT, &old_int_, nullptr);
    sigaction(SIGTERM, &old_term_, nullptr);
  }
  InterruptGuard(const InterruptGuard&) = delete;
  InterruptGuard& operator=(const InterruptGuard&) = delete;

 private:
  struct sigaction old_int_ {};
  struct sigaction old_term_ {};
};

// The unfinished runs of a session, one analysis per distinct model: `work` holds the
// representatives (lowest case id of each model), `duplicates` the other unfinished cases of
// models shared by several cases (rare; most cases are in no map at all).
struct WorkPlan {
  std::vector<std::int64_t> unfinished;  // sorted
  std::vector<std::int64_t> work;        // sorted
  std::unordered_map<std::int64_t, std::vector<std::int64_t>> duplicates;

  WorkPlan(std::vector<std::int64_t> unfinished_cases,
           const std::vector<std::int64_t>& representative)
      : unfinished(std::move(unfinished_cases)) {
    for (const std::int64_t c : unfinished) {
      const std::int64_t r = representative[static_cast<std::size_t>(c)];
      work.push_back(r);
      if (r != c) duplicates[r].push_back(c);
    }
    std::sort(work.begin(), work.end());
    work.erase(std::unique(work.begin(), work.end()), work.end());
  }

  // The unfinished cases an analysis of `representative` completes, itself first if unfinished.
  std::vector<std::int64_t> cases_of(std::int64_t representative) const {
    std::vector<std::int64_t> cases;
    if (std::binary_search(unfinished.begin(), unfinished.end(), representative))
      cases.push_back(representative);
    if (const auto d = duplicates.find(representative); d != duplicates.end())
      cases.insert(cases.end(), d->second.begin(), d->second.end());
    return cases;
  }
};

// Rank 0's side of the database: expands each computed run to the cases with the same model and
// commits in batches.
class Writer {
 public:
  Writer(StudyStore& store, const WorkPlan& plan, std::int64_t session)
      : store_(store), plan_(plan), session_(session), last_commit_(Clock::now()) {}

  void add(RunRecord run) {
    ++analyses_;
    const std::vector<std::int64_t> cases = plan_.cases_of(run.case_id);
    for (std::size_t i = 0; i < cases.size(); ++i) {
      RunRecord copy = run;
      copy.case_id = cases[i];
      copy.computed = i == 0;  // the computations log gets one row per analysis
      if (!copy.ok) ++failed_;
      ++finished_;
      pending_.push_back(std::move(copy));
    }
  }

  void commit_if_due(bool force) {
    const double since = std::chrono::duration<double>(Clock::now() - last_commit_).count();
    if (pending_.empty() || (!force && pending_.size() < kCommitRuns && since < kCommitSeconds))
      return;
    store_.commit(pending_, session_);
    pending_.clear();
    last_commit_ = Clock::now();
  }

  std::int64_t finished() const { return finished_; }  // runs (cases) received, committed or not
  std::int64_t failed() const { return failed_; }
  std::int64_t analyses() const { return analyses_; }

 private:
  StudyStore& store_;
  const WorkPlan& plan_;
  std::int64_t session_;
  std::vector<RunRecord> pending_;
  Clock::time_point last_commit_;
  std::int64_t finished_ = 0, failed_ = 0, analyses_ = 0;
};

// An exclusive flock on "<db>.lock" for the whole sweep: a second sweep on the same database is
// refused. The kernel drops the lock when the process dies, however it dies.
class DatabaseLock {
 public:
  explicit DatabaseLock(const std::string& db_path) : path_(db_path + ".lock") {
    const std::string& path = path_;
    // The database's folder is made as `run -o` makes its output folder (README's recipes write
    // to out/studies/...).
    const std::filesystem::path folder = std::filesystem::path(db_path).parent_path();
    std::error_code ec;
    if (!folder.empty()) std::filesystem::create_directories(folder, ec);
    if (ec)
      throw InputError(
          db_path, 0, 0, "",
          "cannot create the database's folder " + folder.string() + ": " + ec.message());
    fd_ = ::open(path.c_str(), O_CREAT | O_RDWR | O_CLOEXEC, 0644);
    if (fd_ < 0)
      throw InputError(path, 0, 0, "", "cannot create the lock file beside the database");
    if (flock(fd_, LOCK_EX | LOCK_NB) != 0) {
      ::close(fd_);
      throw InputError(db_path, 0, 0, "", "another isopound sweep is writing this database");
    }
  }
  // A clean finish leaves no lock file (removed while still held); a killed sweep leaves it,
  // unlocked, and the next sweep takes it over.
  ~DatabaseLock() {
    ::unlink(path_.c_str());
    ::close(fd_);
  }
  DatabaseLock(const DatabaseLock&) = delete;
  DatabaseLock& operator=(const DatabaseLock&) = delete;

 private:
  std::string path_;
  int fd_ = -1;
};

// Cores this process may use: its CPU affinity (set by Slurm, taskset or mpirun's binding), else
// the node's; shared among the node's ranks when they are not bound to their own cores.
int default_jobs(int ranks_on_node) {
  const int node = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  cpu_set_t set;
  CPU_ZERO(&set);
  const int mine = sched_getaffinity(0, sizeof set, &set) == 0 ? CPU_COUNT(&set) : node;
  if (mine > 0 && mine < node) return mine;  // bound by the launcher: these cores are ours
  return std::max(1, node / std::max(1, ranks_on_node));
}

void remove_database(const std::string& path) {
  std::error_code ec;
  for (const char* suffix : {"", "-wal", "-shm", "-journal"})
    fs::remove(path + suffix, ec);  // not ".lock": held
}

std::vector<Cell> cells_of(const Study& study, std::int64_t case_id) {
  const std::vector<int> levels = study.levels_of(case_id);
  std::vector<Cell> cells;
  for (std::size_t a = 0; a < study.axes.size(); ++a) {
    const Level& level = study.axes[a].levels[levels[a]];
    cells.push_back(level.numeric ? Cell{true, level.si, ""} : Cell{false, 0.0, level.label});
  }
  return cells;
}

void describe(const Study& study, const ValidatedStudy& validated, std::FILE* out) {
  std::fprintf(out, "%s: %lld runs (%lld distinct models, %zu ground motions)\n",
               study.file.c_str(), static_cast<long long>(study.case_count()),
               static_cast<long long>(validated.distinct_models), validated.motions.size());
  for (const Axis& axis : study.axes) {
    std::string labels;
    for (std::size_t i = 0; i < axis.levels.size() && i < 6; ++i)
      labels += (i ? ", " : "") + axis.levels[i].label;
    if (axis.levels.size() > 6) labels += ", ... " + axis.levels.back().label;
    std::fprintf(out, "  axis %-12s %4zu values (group %d): %s\n", axis.name.c_str(),
                 axis.levels.size(), axis.group, labels.c_str());
  }
  std::string peaks;
  for (const OutputSpec& o : study.outputs)
    peaks += (peaks.empty() ? "" : ", ") + o.column + " = " + o.selector;
  std::fprintf(out, "  peaks: %s\n", peaks.c_str());
}

}  // namespace

CaseRunner::CaseRunner(const Study& study, const ValidatedStudy& validated)
    : builder_(study), validated_(validated), ensemble_(study.ensemble) {
  for (const OutputSpec& o : study.outputs) selectors_.push_back(parse_output_selector(o.selector));
}

RunRecord CaseRunner::run(std::int64_t case_id) const {
  RunRecord record;
  record.case_id = case_id;
  const Clock::time_point start = Clock::now();
  try {
    // The input validation read, else (a large study) read again.
    const auto c = static_cast<std::size_t>(case_id);
    const std::shared_ptr<const CaseInput> input_kept =
        c < validated_.inputs.size() && validated_.inputs[c]
            ? validated_.inputs[c]
            : std::make_shared<const CaseInput>(builder_.input_of(case_id));
    const CaseInput& input = *input_kept;
    const PreparedMotion& motion = *validated_.motions.at(input.motion_key);
    if (ensemble_ >= 2) {  // study_ensemble.h
      long steps = 0;
      record.values = ensemble_case_values(input.config, motion.motion, motion.peaks, selectors_,
                                           ensemble_, steps);
      record.steps = steps;
      record.ok = true;
      record.wall_seconds = std::chrono::duration<double>(Clock::now() - start).count();
      return record;
    }
    // As run_job (job.h), with the ground motion loaded once for the whole study.
    check_step_against_record(input.config.analysis, motion.motion);
    Model model = build_model(input.config);
    RunOptions options = run_options(input.config);
    // The outputs resolved before the run, which then records only what they read.
    std::vector<ResolvedOutput> outputs;
    std::vector<char> resolved;
    for (const OutputSelector& selector : selectors_) {
      try {
        outputs.push_back(resolve_output(selector, model));
        resolved.push_back(1);
      } catch (const std::invalid_argument&) {  // an element this case does not have (validated)
        resolved.push_back(0);
      }
    }
    options.record = record_scope_of(outputs);
    ContactEventLog contacts(model, "");  // first-impact times, as summary.json (no file)
    if (!contacts.empty()) options.observer = &contacts;
    const AnalysisResult result = run_analysis(model, motion.motion, options);
    const std::vector<double> first_impacts = contacts.first_impact_times(model);
    for (std::size_t k = 0, next = 0; k < selectors_.size(); ++k)
      record.values.push_back(
          resolved[k] ? evaluate_output(outputs[next++], result, motion.peaks, &first_impacts)
                      : std::numeric_limits<double>::quiet_NaN());
    record.steps = result.stats.steps;
    record.ok = true;
  } catch (const std::exception& e) {
    record.ok = false;
    record.values.clear();
    record.error = e.what();
  }
  record.wall_seconds = std::chrono::duration<double>(Clock::now() - start).count();
  return record;
}

std::string study_fingerprint(const Study& study) {
  std::uint64_t h = fnv1a64("isopound-study-1");
  const auto add = [&](const std::string& text) {
    h = fnv1a64(text, h);
    h = fnv1a64(std::string_view("\0", 1), h);
  };
  add(study.text);
  add(study.model_text);
  for (const std::string& file : study.record_files) add(file);
  add(StoreLayout::of(study).to_json());
  add(std::to_string(study.case_count()));
  return hex64(h);
}

int run_sweep(const std::string& study_path, const SweepOptions& options,
              const RankSession& ranks) {
  const bool root = ranks.rank() == 0;
  const Study study = load_study_file(study_path);
  const int jobs = options.jobs > 0 ? options.jobs : default_jobs(ranks.local_size());
  // Validation builds every case's model once: say so, since a large study takes a while here.
  const bool tell = root && !options.quiet;
  const Clock::time_point checking = Clock::now();
  if (tell)
    std::fprintf(stderr,
                 "%s: %lld cases; checking that every case builds and every output exists "
                 "(%d threads)...\n",
                 study_path.c_str(), static_cast<long long>(study.case_count()), jobs);
  const ValidatedStudy validated = validate_study(study, jobs);
  if (tell)
    std::fprintf(stderr, "%s: checked in %.1f s%s\n", study_path.c_str(),
                 std::chrono::duration<double>(Clock::now() - checking).count(),
                 options.dry_run ? "; dry run: nothing is computed" : "");
  // Implausible values of the cases (as `isopound run` warns of them): said before anything runs,
  // kept in the database's meta table, refused with --strict.
  if (root)
    for (const std::string& w : validated.warnings)
      std::fprintf(stderr, "isopound sweep: %s: %s\n", options.strict ? "error" : "warning",
                   w.c_str());
  if (options.strict && !validated.warnings.empty()) {
    if (root)
      std::fprintf(stderr, "isopound sweep: error: %zu implausible value(s) refused by --strict\n",
                   validated.warnings.size());
    return 2;
  }
  if (options.dry_run) {
    if (root) describe(study, validated, stdout);
    return 0;
  }
  const std::string db_path =
      options.db_path.empty() ? fs::path(study_path).stem().string() + ".db" : options.db_path;

  // Rank 0: the database and the list of runs still to do, grouped by identical model.
  std::optional<DatabaseLock> lock;
  std::optional<StudyStore> store;
  std::optional<WorkPlan> plan;
  std::int64_t already = 0, to_finish = 0, session = 0;
  bool resumed = false;
  std::exception_ptr failure;
  if (root) {
    try {
      const std::string fingerprint = study_fingerprint(study);
      std::error_code ec;
      lock.emplace(db_path);
      bool exists = fs::exists(db_path, ec);
      if (exists && !StudyStore::has_schema(db_path)) {  // killed while it was being created
        remove_database(db_path);
        exists = false;
      }
      if (exists && options.overwrite) {
        remove_database(db_path);
        exists = false;
      }
      if (exists && !options.resume)
        throw InputError(db_path, 0, 0, "",
                         "already exists: add --resume to continue this study, or --overwrite to "
                         "start it again");
      if (exists) {
        store.emplace(StudyStore::open(db_path, false));
        if (store->meta("study_hash") != fingerprint)
          throw InputError(
              db_path, 0, 0, "",
              "was made from a different study (the study file '" + store->meta("study_file") +
                  "', its model or its records changed since); cannot resume it: use --overwrite "
                  "to start again, or --db for a new database");
        resumed = true;
      } else {
        if (options.resume && !options.quiet)
          std::fprintf(stderr, "isopound sweep: %s does not exist yet: starting the study\n",
                       db_path.c_str());
        std::error_code abs_ec;
        const std::map<std::string, std::string> meta{
            {"study_file", fs::absolute(study.file, abs_ec).lexically_normal().string()},
            {"study_name", study.name},
            {"study_hash", fingerprint},
            {"distinct_models", std::to_string(validated.distinct_models)},
            {"warnings", join_lines(validated.warnings)}};
        store.emplace(StudyStore::create(db_path, StoreLayout::of(study), meta, study.case_count(),
                                         [&](std::int64_t c) { return cells_of(study, c); }));
      }
      plan.emplace(store->unfinished_cases(), validated.representative);
      to_finish = static_cast<std::int64_t>(plan->unfinished.size());
      already = study.case_count() - to_finish;
      session = store->begin_session(jobs, ranks.size(), resumed, to_finish);
    } catch (...) {
      failure = std::current_exception();
    }
  }
  const int status = ranks.broadcast(failure ? 2 : 0);
  if (failure) std::rethrow_exception(failure);
  if (status != 0) return status;

  const CaseRunner runner(study, validated);
  const auto compute = [&runner, rank = ranks.rank()](std::int64_t c) {
    RunRecord record = runner.run(c);
    record.rank = rank;
    return record;
  };
  const InterruptGuard interrupts;
  CaseFeed feed;
  ResultQueue results;
  std::vector<RunRecord> batch;

  if (!root) {  // an MPI worker rank: ask rank 0 for chunks, send results back
    WorkerPool pool(jobs, feed, results, compute);
    bool closed = false, asked = false;
    for (;;) {
      if (!closed && !asked && feed.size() < static_cast<std::size_t>(jobs)) {
        ranks.send(0, RankMessage::kRequest, {});
        asked = true;
      }
      Incoming message;
      if (asked && ranks.try_receive(message, 0) && message.tag == RankMessage::kWork) {
        const std::vector<std::int64_t> cases = decode_cases(message.bytes);
        if (cases.empty()) {
          closed = true;
          feed.close();
        } else {
          feed.push(cases);
        }
        asked = false;
      }
      const bool done = closed && pool.finished();
      batch.clear();
      results.drain(batch, done ? std::chrono::milliseconds(0) : kRankWait);
      if (!batch.empty()) ranks.send(0, RankMessage::kResults, encode_runs(batch));
      if (done && results.empty()) break;
    }
    return 0;
  }

  const auto analyses_to_do = static_cast<std::int64_t>(plan->work.size());
  feed.push(plan->work);
  feed.close();
  Writer writer(*store, *plan, session);
  Progress progress(Progress::mode_for(stderr, options.quiet), to_finish, already);
  int open_ranks = ranks.size() - 1;
  const std::size_t chunk = static_cast<std::size_t>(std::max(1, 2 * jobs));
  bool interrupted = false;
  {
    WorkerPool pool(jobs, feed, results, compute);
    for (;;) {
      Incoming message;
      while (ranks.active() && ranks.try_receive(message)) {
        if (message.tag == RankMessage::kRequest) {
          const std::vector<std::int64_t> cases =
              g_interrupted ? std::vector<std::int64_t>{} : feed.take(chunk);
          ranks.send(message.source, RankMessage::kWork, encode_cases(cases));
          if (cases.empty()) --open_ranks;
        } else if (message.tag == RankMessage::kResults) {
          for (RunRecord& run : decode_runs(message.bytes)) writer.add(std::move(run));
        }
      }
      batch.clear();
      results.drain(batch, ranks.active() ? kRankWait : kLocalWait);
      for (RunRecord& run : batch) writer.add(std::move(run));
      writer.commit_if_due(false);
      progress.update(writer.finished(), writer.failed());
      if (writer.analyses() == analyses_to_do && open_ranks == 0) break;
      if (g_interrupted) {
        interrupted = true;
        feed.stop();
        if (ranks.active()) {  // other ranks may be mid-run: keep what is here and stop them all
          writer.commit_if_due(true);
          progress.finish(writer.finished(), writer.failed());
          std::fprintf(
              stderr,
              "isopound sweep: interrupted; %lld runs committed to %s (continue with --resume)\n",
              static_cast<long long>(already + writer.finished()), db_path.c_str());
          ranks.abort(130);
        }
        if (pool.finished()) {
          batch.clear();
          results.drain(batch, std::chrono::milliseconds(0));
          for (RunRecord& run : batch) writer.add(std::move(run));
          break;
        }
      }
    }
    writer.commit_if_due(true);
  }
  progress.finish(writer.finished(), writer.failed());
  const double seconds = progress.elapsed_seconds();
  if (interrupted) {
    std::fprintf(
        stderr,
        "isopound sweep: interrupted; %lld of %lld runs done in %s (continue with --resume)\n",
        static_cast<long long>(already + writer.finished()),
        static_cast<long long>(study.case_count()), db_path.c_str());
    return 130;
  }
  if (!options.quiet) {
    std::printf(
        "isopound sweep: %s: %lld runs in %.1f s (%.1f runs/s; %lld analyses, %lld runs shared an "
        "identical "
        "model), %lld failed%s\n",
        study.name.c_str(), static_cast<long long>(writer.finished()), seconds,
        seconds > 0 ? static_cast<double>(writer.finished()) / seconds : 0.0,
        static_cast<long long>(writer.analyses()),
        static_cast<long long>(writer.finished() - writer.analyses()),
        static_cast<long long>(writer.failed()),
        already > 0 ? (", " + std::to_string(already) + " were done before").c_str() : "");
    std::printf("Results in %s; tables: isopound export %s\n", db_path.c_str(), db_path.c_str());
  }
  // Failed runs make the sweep fail (exit 1), also under -q: say how many and where to look.
  if (writer.failed() > 0) {
    std::fprintf(stderr,
                 "isopound sweep: error: %lld of %lld runs failed; their messages are in the "
                 "'error' column of the runs table of %s (isopound export %s --table runs)\n",
                 static_cast<long long>(writer.failed()), static_cast<long long>(writer.finished()),
                 db_path.c_str(), db_path.c_str());
    return 1;
  }
  return 0;
}

}  // namespace isopound
