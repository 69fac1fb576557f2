// `isopound sweep study.yaml` and `isopound export study.db` (see study_cli.h); under mpirun/srun
// the sweep spreads over the ranks, and only rank 0 prints.
#include "solver/study/study_cli.h"

#include "solver/study/cli_contract.h"

#include <cstdio>
#include <filesystem>
#include <iostream>

#include "solver/study/study_export.h"
#include "solver/study/study_runner.h"

namespace isopound {

struct StudyCommandOptions {
  std::string study_path;
  SweepOptions sweep;
  std::string export_after;  // sweep --export DIR
  std::string db_path;       // export
  std::string output_dir;
  std::string table;  // export --table NAME: that table on stdout
  bool timing = false;
};

namespace {

enum ExitCode { kOk = 0, kFailure = 1, kBadInput = 2 };

int export_command(const StudyCommandOptions& o) {
  const StudyStore store = StudyStore::open(o.db_path, true);
  const ExportOptions options{o.timing};
  if (!o.table.empty()) {
    const ExportTables tables = export_tables(store, options);
    const std::string* text = o.table == "runs"     ? &tables.runs
                              : o.table == "ratios" ? &tables.ratios
                                                    : &tables.statistics;
    if (text->empty()) {
      std::cerr << "isopound: error: " << o.db_path << ": the study defines no " << o.table << '\n';
      return kBadInput;
    }
    std::cout << *text;
    return kOk;
  }
  std::string dir = o.output_dir;
  if (dir.empty()) {
    const std::filesystem::path db(o.db_path);
    dir = (db.parent_path() / (db.stem().string() + "-csv")).string();
  }
  for (const std::string& path : write_export(store, dir, options))
    std::cout << "Wrote " << path << '\n';
  return kOk;
}

int sweep_command(const StudyCommandOptions& o) {
  const RankSession ranks;
  const bool root = ranks.rank() == 0;
  try {
    const int code = run_sweep(o.study_path, o.sweep, ranks);
    if (code == kOk && root && !o.export_after.empty() && !o.sweep.dry_run) {
      const std::string db = o.sweep.db_path.empty()
                                 ? std::filesystem::path(o.study_path).stem().string() + ".db"
                                 : o.sweep.db_path;
      const StudyStore store = StudyStore::open(db, true);
      for (const std::string& path : write_export(store, o.export_after, ExportOptions{o.timing}))
        if (!o.sweep.quiet) std::cout << "Wrote " << path << '\n';
    }
    return code;
  } catch (const InputError& e) {
    if (root) std::cerr << "isopound: error: " << e.what() << '\n';
    return kBadInput;
  } catch (const std::exception& e) {
    if (root) std::cerr << "isopound: error: " << e.what() << '\n';
    return kFailure;
  }
}

}  // namespace

StudyCommands add_study_commands(CLI::App& app) {
  StudyCommands commands;
  commands.options = std::make_shared<StudyCommandOptions>();
  StudyCommandOptions& o = *commands.options;

  CLI::App* sweep = app.add_subcommand("sweep",
                                       "Run a parametric study (all cores; under mpirun over all "
                                       "ranks); results go to an SQLite database");
  sweep->add_option("study", o.study_path, "Study file (YAML)")->required();
  sweep->add_option("-j,--jobs", o.sweep.jobs, "Worker threads per rank (default: all cores)")
      ->check(at_least(0));
  sweep->add_option("--db", o.sweep.db_path,
                    "Results database (default: <study>.db in the current directory)");
  sweep->add_flag("--resume", o.sweep.resume,
                  "Continue an existing database: compute only its unfinished runs");
  sweep->add_flag("--overwrite", o.sweep.overwrite, "Delete an existing database and start again");
  sweep->add_flag("-q,--quiet", o.sweep.quiet, "No progress and no summary");
  sweep->add_flag("--strict", o.sweep.strict,
                  "A case's implausible value (a warning) is an error: nothing is run");
  sweep->add_flag("--dry-run", o.sweep.dry_run,
                  "Validate every case and describe the study; run nothing");
  sweep->add_option("--export", o.export_after,
                    "After the sweep, write the CSV tables into this directory");
  sweep->add_flag("--timing", o.timing, "With --export: add wall_seconds to runs.csv");
  sweep->get_option("--resume")->excludes(sweep->get_option("--overwrite"));

  CLI::App* exporter = app.add_subcommand(
      "export", "Write a study database's tables as CSV: runs.csv, ratios.csv, statistics.csv");
  exporter->add_option("database", o.db_path, "Study database (.db)")->required();
  exporter->add_option("-o,--output", o.output_dir,
                       "Output directory (default: <database stem>-csv beside it)");
  exporter->add_option("--table", o.table, "Print one table to stdout instead")
      ->check(CLI::IsMember({"runs", "ratios", "statistics"}));
  exporter->add_flag("--timing", o.timing,
                     "Add wall_seconds (differs between runs of the same study)");

  commands.sweep = sweep;
  commands.export_tables = exporter;
  return commands;
}

std::optional<int> run_study_command(const StudyCommands& commands) {
  const StudyCommandOptions& o = *commands.options;
  if (commands.sweep && commands.sweep->parsed()) return sweep_command(o);
  if (commands.export_tables && commands.export_tables->parsed()) {
    try {
      return export_command(o);
    } catch (const std::exception& e) {
      std::cerr << "isopound: error: " << e.what() << '\n';
      return kFailure;
    }
  }
  return std::nullopt;
}

}  // namespace isopound
