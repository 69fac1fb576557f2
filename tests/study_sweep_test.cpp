// End-to-end tests of `isopound sweep` / `isopound export` with the real binary: identical tables
// for any -j, a SIGKILLed study resumed without recomputing finished runs, MPI ranks, bad input.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <regex>
#include <string>
#include <thread>

#include "tests/study_test_support.h"

extern char** environ;

namespace isopound {
namespace {

namespace fs = std::filesystem;
using test::query_int;
using test::read_file;
using test::run_isopound;

// 3 pulse periods x 3 Q/W x 4 u_y x 2 buildings x 3 isolator variants = 216 runs of an 8 s pulse.
std::string determinism_study() {
  return "name: determinism\nmodel: " + test::thesis_model() + R"(
set:
  ground_motion.pulse: {amplitude: 0.8 m/s, period: 2 s, duration: 8 s, dt: 0.01 s}
axes:
  - {name: Tp, path: ground_motion.pulse.period, values: [1.5 s, 2 s, 3 s]}
  - {path: building.isolator.QW, values: [5 %, 7.5 %, 10 %]}
  - {path: building.isolator.uy, range: {from: 1 cm, to: 2.5 cm, step: 0.5 cm}}
  - {name: storeys, path: building.floors.count, values: [3, 5]}
variants:
  BL: {building.isolator.model: bilinear, building.isolator.n: ~, building.isolator.A: ~, building.isolator.beta: ~, building.isolator.gamma: ~}
  BW: {building.isolator.model: bouc_wen}
  BW_n1: {building.isolator.model: bouc_wen, building.isolator.n: 1}
outputs: [base.displacement, stories.drift_ratio, floors.absolute_acceleration, isolator.force, energy.hysteretic]
derived:
  BL_over_BW: {ratio: [BL, BW]}
statistics:
  - {over: [Tp]}
  - {over: [Tp, uy], std: population}
)";
}

// 9 u_y x 5 Q/W x 5 T_b = 225 bilinear runs of a 4 s pulse: long enough to be stopped mid-way (once
// the test sees 40 done: 64 here, the store writes runs in batches; a run takes ~1 ms in Release,
// 30 ms under the sanitizers), short enough for the sanitizer tree (1025 runs of 6 s: 60-98 s).
std::string resumable_study() {
  return "name: resumable\nmodel: " + test::thesis_model() + R"(
set:
  ground_motion.pulse: {amplitude: 0.8 m/s, period: 2 s, duration: 4 s, dt: 0.01 s}
  building.isolator: {model: bilinear, Tb: 2 s, QW: 5 %, uy: 1 cm}
axes:
  - {path: building.isolator.Tb, values: [2 s, 2.25 s, 2.5 s, 2.75 s, 3 s]}
  - {path: building.isolator.QW, range: {from: 5 %, to: 10 %, step: 1.25 %}}
  - {path: building.isolator.uy, range: {from: 1 cm, to: 3 cm, step: 0.25 cm}}
outputs: [base.displacement, stories.drift_ratio]
)";
}

void expect_same_tables(const fs::path& a, const fs::path& b) {
  for (const char* table : {"runs.csv", "ratios.csv", "statistics.csv"}) {
    if (!fs::exists(a / table) && !fs::exists(b / table)) continue;
    const std::string left = read_file(a / table), right = read_file(b / table);
    EXPECT_FALSE(left.empty()) << a / table;
    EXPECT_TRUE(left == right) << table << " differs between " << a << " and " << b;
  }
}

TEST(StudySweep, TablesAreByteIdenticalForOneAndTwoThreads) {
  const fs::path dir = test::study_scratch("determinism");
  test::write_file(dir / "study.yaml", determinism_study());
  for (const char* jobs : {"1", "2"}) {
    const auto r =
        run_isopound("sweep '" + (dir / "study.yaml").string() + "' -q -j " + jobs + " --db '" +
                     (dir / ("j" + std::string(jobs) + ".db")).string() + "'");
    ASSERT_EQ(r.exit_code, 0) << r.output;
    const auto e = run_isopound("export '" + (dir / ("j" + std::string(jobs) + ".db")).string() +
                                "' -o '" + (dir / ("j" + std::string(jobs))).string() + "'");
    ASSERT_EQ(e.exit_code, 0) << e.output;
  }
  expect_same_tables(dir / "j1", dir / "j2");
  const std::string runs = read_file(dir / "j1" / "runs.csv");
  EXPECT_EQ(std::count(runs.begin(), runs.end(), '\n'), 217);
  EXPECT_EQ(runs.find(",failed,"), std::string::npos) << runs;
  EXPECT_EQ(runs.substr(0, runs.find('\n')),
            "case_id,Tp,QW,uy,storeys,variant,status,steps,base_displacement,stories_drift_ratio,"
            "floors_absolute_acceleration,isolator_force,energy_hysteretic,error");
  EXPECT_EQ(query_int(dir / "j2.db", "SELECT COUNT(*) FROM runs WHERE status = 'done'"), 216);
  EXPECT_EQ(query_int(dir / "j2.db", "SELECT COUNT(DISTINCT case_id) FROM computations"), 216);

  // --timing adds the one column that differs from run to run.
  const auto timed =
      run_isopound("export '" + (dir / "j1.db").string() + "' --table runs --timing");
  ASSERT_EQ(timed.exit_code, 0);
  EXPECT_NE(timed.output.find(",wall_seconds,error\n"), std::string::npos);
  fs::remove_all(dir);  // kept when an assertion failed above
}

// Issue 37: the README's recipes write to out/studies/x.db; a missing folder is made (as run -o
// makes its output folder), not refused with "cannot create the lock file".
TEST(StudySweep, DatabaseInAFolderThatDoesNotExistIsMade) {
  const fs::path dir = test::study_scratch("db-folder");
  test::write_file(dir / "study.yaml", "name: folder\nmodel: " + test::thesis_model() + R"(
set:
  ground_motion.pulse: {amplitude: 0.8 m/s, period: 2 s, duration: 4 s, dt: 0.01 s}
axes:
  - {path: building.isolator.QW, values: [5 %, 10 %]}
outputs: [base.displacement]
)");
  const fs::path db = dir / "out" / "studies" / "x.db";
  ASSERT_FALSE(fs::exists(db.parent_path()));
  const auto r =
      run_isopound("sweep '" + (dir / "study.yaml").string() + "' -q --db '" + db.string() + "'");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(query_int(db, "SELECT COUNT(*) FROM runs WHERE status = 'done'"), 2);
  fs::remove_all(dir);
}

pid_t spawn_isopound(const std::vector<std::string>& args) {
  std::vector<std::string> all{ISOPOUND_BINARY};
  all.insert(all.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (std::string& a : all) argv.push_back(a.data());
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 1, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_addopen(&actions, 2, "/dev/null", O_WRONLY, 0);
  pid_t pid = -1;
  if (posix_spawn(&pid, ISOPOUND_BINARY, &actions, nullptr, argv.data(), environ) != 0) pid = -1;
  posix_spawn_file_actions_destroy(&actions);
  return pid;
}

TEST(StudySweep, KilledStudyResumesWithoutRecomputingFinishedRuns) {
  const fs::path dir = test::study_scratch("resume");
  const fs::path study = dir / "study.yaml", db = dir / "killed.db";
  test::write_file(study, resumable_study());
  constexpr long long kTotal = 225;

  const pid_t pid = spawn_isopound({"sweep", study.string(), "-j", "1", "--db", db.string()});
  ASSERT_GT(pid, 0);
  long long done = 0;
  int status = 0;
  bool exited = false;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(120);
  while (std::chrono::steady_clock::now() < deadline) {
    if (waitpid(pid, &status, WNOHANG) == pid) {
      exited = true;
      break;
    }
    done = query_int(db, "SELECT COUNT(*) FROM runs WHERE status = 'done'");
    if (done >= 40) break;
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  ASSERT_FALSE(exited) << "the study finished before it could be killed";
  // Stopped (SIGSTOP: it keeps its database and lock) so that it cannot finish while the second
  // sweep starts; while it is there, a second sweep on the same database is refused.
  ASSERT_EQ(kill(pid, SIGSTOP), 0);
  const auto second =
      run_isopound("sweep '" + study.string() + "' -q --resume --db '" + db.string() + "'");
  EXPECT_EQ(second.exit_code, 2) << second.output;
  EXPECT_NE(second.output.find("another isopound sweep is writing this database"),
            std::string::npos)
      << second.output;
  ASSERT_EQ(kill(pid, SIGKILL), 0);
  ASSERT_EQ(waitpid(pid, &status, 0), pid);
  ASSERT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGKILL);

  const long long before = query_int(db, "SELECT COUNT(*) FROM runs WHERE status = 'done'");
  ASSERT_GE(before, 40);
  ASSERT_LT(before, kTotal) << "killed too late to test a resume";
  std::printf("killed after %lld of %lld runs\n", before, kTotal);
  EXPECT_EQ(query_int(db, "SELECT COUNT(*) FROM runs WHERE status = 'pending'"), kTotal - before);
  EXPECT_EQ(query_int(db, "SELECT COUNT(*) FROM computations"), before);

  // Without --resume an existing database is refused; with it only the unfinished runs are
  // computed.
  const auto refused = run_isopound("sweep '" + study.string() + "' -q --db '" + db.string() + "'");
  EXPECT_EQ(refused.exit_code, 2) << refused.output;
  EXPECT_NE(refused.output.find("already exists: add --resume"), std::string::npos)
      << refused.output;
  const auto resumed =
      run_isopound("sweep '" + study.string() + "' -q -j 2 --resume --db '" + db.string() + "'");
  ASSERT_EQ(resumed.exit_code, 0) << resumed.output;

  EXPECT_EQ(query_int(db, "SELECT COUNT(*) FROM runs WHERE status = 'done'"), kTotal);
  EXPECT_EQ(query_int(db, "SELECT COUNT(*) FROM computations"), kTotal)
      << "a run was computed twice";
  EXPECT_EQ(query_int(db, "SELECT COUNT(DISTINCT case_id) FROM computations"), kTotal);
  EXPECT_EQ(query_int(db, "SELECT COUNT(*) FROM computations WHERE session = 1"), before);
  EXPECT_EQ(query_int(db, "SELECT COUNT(*) FROM runs WHERE session = 1"), before);
  EXPECT_EQ(query_int(db, "SELECT runs_to_do FROM sessions WHERE session = 2"), kTotal - before);
  EXPECT_EQ(query_int(db, "SELECT resumed FROM sessions WHERE session = 2"), 1);

  // The resumed table equals an uninterrupted run's.
  const fs::path clean = dir / "clean.db";
  const auto full = run_isopound("sweep '" + study.string() + "' -q -j 2 --db '" + clean.string() +
                                 "' --export '" + (dir / "clean").string() + "'");
  ASSERT_EQ(full.exit_code, 0) << full.output;
  ASSERT_EQ(
      run_isopound("export '" + db.string() + "' -o '" + (dir / "killed").string() + "'").exit_code,
      0);
  expect_same_tables(dir / "killed", dir / "clean");

  // A resume of a finished study computes nothing.
  ASSERT_EQ(run_isopound("sweep '" + study.string() + "' -q --resume --db '" + db.string() + "'")
                .exit_code,
            0);
  EXPECT_EQ(query_int(db, "SELECT COUNT(*) FROM computations"), kTotal);
  fs::remove_all(dir);  // kept when an assertion failed above
}

// A user watching a study start (a read-only query while the sweep creates its database) must not
// fail it: the sweep waits for the reader's lock. Before the fix about half of such starts failed
// with "database is locked"; 20 starts, each watched from the first instant, would all pass by
// chance with probability ~1e-6.
TEST(StudySweep, AReaderWatchingTheStartDoesNotFailIt) {
  const fs::path dir = test::study_scratch("watched");
  const fs::path study = dir / "study.yaml";
  test::write_file(study, "name: watched\nmodel: " + test::thesis_model() + R"(
set:
  ground_motion.pulse: {amplitude: 0.8 m/s, period: 2 s, duration: 2 s, dt: 0.01 s}
  building.isolator: {model: bilinear, Tb: 2 s, QW: 5 %, uy: 1 cm}
axes:
  - {path: building.isolator.Tb, values: [2 s, 2.5 s]}
outputs: [base.displacement]
)");
  for (int start = 0; start < 20; ++start) {
    const fs::path db = dir / ("watched" + std::to_string(start) + ".db");
    const pid_t pid = spawn_isopound({"sweep", study.string(), "-j", "1", "--db", db.string()});
    ASSERT_GT(pid, 0);
    int status = 0;
    while (waitpid(pid, &status, WNOHANG) != pid) query_int(db, "SELECT COUNT(*) FROM runs");
    ASSERT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << "start " << start;
    EXPECT_EQ(query_int(db, "SELECT COUNT(*) FROM runs WHERE status = 'done'"), 2);
  }
  fs::remove_all(dir);  // kept when an assertion failed above
}

TEST(StudySweep, RunsWithIdenticalModelsAreComputedOnce) {
  const fs::path dir = test::study_scratch("shared");
  test::write_file(dir / "study.yaml", "model: " + test::thesis_model() + R"(
set: {ground_motion.pulse: {duration: 4 s, dt: 0.01 s}}
axes: [{path: building.isolator.uy, values: [1 cm, 2 cm, 3 cm]}]
variants:
  own: {}
  fixed: {building.isolator.uy: 1.5 cm}   # the same model whatever the axis says
outputs: [base.displacement]
)");
  const fs::path db = dir / "s.db";
  const auto r =
      run_isopound("sweep '" + (dir / "study.yaml").string() + "' -q --db '" + db.string() + "'");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(query_int(db, "SELECT COUNT(*) FROM runs WHERE status = 'done'"), 6);
  EXPECT_EQ(query_int(db, "SELECT COUNT(*) FROM computations"), 4);
  EXPECT_EQ(
      query_int(db, "SELECT COUNT(DISTINCT base_displacement) FROM runs WHERE variant = 'fixed'"),
      1);
  EXPECT_EQ(
      query_int(db, "SELECT COUNT(DISTINCT base_displacement) FROM runs WHERE variant = 'own'"), 3);
  fs::remove_all(dir);  // kept when an assertion failed above
}

TEST(StudySweep, ResumeRefusesAChangedStudy) {
  const fs::path dir = test::study_scratch("changed");
  const std::string base = "model: " + test::thesis_model() +
                           "\nset: {ground_motion.pulse: {duration: 4 s, dt: 0.01 s}}\n"
                           "axes: [{path: building.isolator.uy, values: [1 cm, 2 cm]}]\n";
  test::write_file(dir / "study.yaml", base);
  const std::string db = (dir / "s.db").string();
  ASSERT_EQ(
      run_isopound("sweep '" + (dir / "study.yaml").string() + "' -q --db '" + db + "'").exit_code,
      0);
  test::write_file(dir / "study.yaml", base + "outputs: [base.displacement]\n");
  const auto r =
      run_isopound("sweep '" + (dir / "study.yaml").string() + "' -q --resume --db '" + db + "'");
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("was made from a different study"), std::string::npos) << r.output;
  const auto again = run_isopound("sweep '" + (dir / "study.yaml").string() +
                                  "' -q --overwrite --db '" + db + "'");
  EXPECT_EQ(again.exit_code, 0) << again.output;

  // A database file without tables (a sweep killed while creating it) is simply started again.
  const fs::path empty = dir / "empty.db";
  test::write_file(empty, "");
  const auto fresh = run_isopound("sweep '" + (dir / "study.yaml").string() +
                                  "' -q --resume --db '" + empty.string() + "'");
  EXPECT_EQ(fresh.exit_code, 0) << fresh.output;
  EXPECT_EQ(query_int(empty, "SELECT COUNT(*) FROM runs WHERE status = 'done'"), 2);
  fs::remove_all(dir);  // kept when an assertion failed above
}

// A case's implausible value (a bare base-slab mass: 340 kg) is warned of as `isopound run` warns,
// located at the axis value that wrote it, once with its case count, kept in the database's meta
// table; --strict refuses the study before any run.
TEST(StudySweep, ImplausibleCaseValuesAreWarnedAtTheirAxisValueAndRefusedWithStrict) {
  const fs::path dir = test::study_scratch("warned");
  test::write_file(dir / "study.yaml",
                   "model: " + test::thesis_model() +
                       "\nset: {ground_motion.pulse: {duration: 2 s, dt: 0.01 s}}\n"
                       "axes:\n"
                       "  - {path: building.base.mass, values: [340 t, 340]}\n"
                       "  - {path: building.isolator.uy, values: [1 cm, 2 cm]}\n"
                       "outputs: [base.displacement]\n");
  const std::string db = (dir / "s.db").string();
  const auto r = run_isopound("sweep '" + (dir / "study.yaml").string() + "' --db '" + db + "'");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const std::regex warning(
      R"(isopound sweep: warning: [^\n]*study\.yaml:4:\d+: axes\[0\]\.values\[1\]: )"
      R"(building\.base\.mass: '340' [^\n]*did you mean '340 t'\?[^\n]*\(case 2: [^\n]*; 2 cases\))");
  EXPECT_TRUE(std::regex_search(r.output, warning)) << r.output;
  std::size_t warnings = 0;
  for (std::size_t at = r.output.find("warning:"); at != std::string::npos;
       at = r.output.find("warning:", at + 1))
    ++warnings;
  EXPECT_EQ(warnings, 1u) << r.output;  // once, not per case
  EXPECT_EQ(query_int(db,
                      "SELECT COUNT(*) FROM meta WHERE key = 'warnings' AND "
                      "value LIKE '%building.base.mass: ''340''%'"),
            1);

  const std::string strict_db = (dir / "strict.db").string();
  const auto strict = run_isopound("sweep '" + (dir / "study.yaml").string() + "' --strict --db '" +
                                   strict_db + "'");
  EXPECT_EQ(strict.exit_code, 2) << strict.output;
  EXPECT_NE(strict.output.find("isopound sweep: error: "), std::string::npos) << strict.output;
  EXPECT_NE(strict.output.find("refused by --strict"), std::string::npos) << strict.output;
  EXPECT_FALSE(fs::exists(strict_db));  // nothing run, no database
  fs::remove_all(dir);
}

TEST(StudySweep, MalformedStudiesExitWithCode2BeforeAnyRun) {
  const fs::path data = test::source_dir() / "tests" / "data" / "bad_studies";
  const fs::path dir = test::study_scratch("bad");
  int count = 0;
  for (const auto& entry : fs::directory_iterator(data)) {
    if (entry.path().extension() != ".yaml") continue;
    ++count;
    const std::string name = entry.path().filename().string();
    const fs::path db = dir / (entry.path().stem().string() + ".db");
    const auto r = run_isopound("sweep '" + entry.path().string() + "' --db '" + db.string() + "'");
    EXPECT_EQ(r.exit_code, 2) << name << ": " << r.output;
    const std::string escaped = std::regex_replace(name, std::regex(R"(\.)"), R"(\.)");
    const std::regex located(escaped +
                             R"(:[1-9][0-9]*:[1-9][0-9]*: [A-Za-z_][A-Za-z_0-9.\[\]]*: )");
    EXPECT_TRUE(std::regex_search(r.output, located)) << name << ": " << r.output;
    EXPECT_FALSE(fs::exists(db)) << name << ": a database was created";
  }
  EXPECT_GE(count, 8);
  fs::remove_all(dir);  // kept when an assertion failed above
}

#ifdef ISOPOUND_HAVE_MPI
TEST(StudySweep, MpiRanksGiveTheSameTableAsOneThread) {
  const fs::path dir = test::study_scratch("mpi");
  test::write_file(dir / "study.yaml", determinism_study());
  setenv("OMPI_ALLOW_RUN_AS_ROOT", "1", 1);  // CI runs as root
  setenv("OMPI_ALLOW_RUN_AS_ROOT_CONFIRM", "1", 1);
  const auto mpi = test::run_command(std::string(ISOPOUND_MPIEXEC) + " -np 2 --oversubscribe " +
                                     ISOPOUND_BINARY + " sweep '" + (dir / "study.yaml").string() +
                                     "' -q -j 1 --db '" + (dir / "mpi.db").string() +
                                     "' --export '" + (dir / "mpi").string() + "'");
  ASSERT_EQ(mpi.exit_code, 0) << mpi.output;
  const auto one =
      run_isopound("sweep '" + (dir / "study.yaml").string() + "' -q -j 1 --db '" +
                   (dir / "one.db").string() + "' --export '" + (dir / "one").string() + "'");
  ASSERT_EQ(one.exit_code, 0) << one.output;
  expect_same_tables(dir / "mpi", dir / "one");
  EXPECT_EQ(query_int(dir / "mpi.db", "SELECT ranks FROM sessions"), 2);
  EXPECT_GT(query_int(dir / "mpi.db", "SELECT COUNT(*) FROM computations WHERE rank = 1"), 0)
      << "rank 1 did nothing";
  EXPECT_EQ(query_int(dir / "mpi.db", "SELECT COUNT(*) FROM computations"), 216);
  fs::remove_all(dir);  // kept when an assertion failed above
}
#endif

TEST(StudyConfigs, Chapter2StudyValidates) {
  ISOPOUND_REQUIRE_RECORDS();
  const auto r = run_isopound(
      "sweep '" + (test::source_dir() / "configs" / "studies" / "chapter2.yaml").string() +
      "' --dry-run");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("8856 runs (8856 distinct models, 2 ground motions)"), std::string::npos)
      << r.output;
  // A large study says what it is doing while it checks every case, and that nothing runs.
  EXPECT_NE(r.output.find("8856 cases; checking that every case builds"), std::string::npos)
      << r.output;
  EXPECT_NE(r.output.find("dry run: nothing is computed"), std::string::npos) << r.output;
}

}  // namespace
}  // namespace isopound
