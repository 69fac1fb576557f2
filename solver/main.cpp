// isopound command line: run a model, show its modes, check it, run the built-in demo, or
// compute the overlap of convex polygons (geometry overlap).
// Errors are printed as "file:line:col: key: what" and give a non-zero exit code.
#include <unistd.h>
#include <CLI/CLI.hpp>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <memory>
#include <numbers>
#include <optional>
#include <sstream>
#include <thread>

#include "geometry/overlap.h"
#include "solver/core/constants.h"
#include "solver/core/modes.h"
#include "solver/io/child_process.h"
#include "solver/io/computed_defaults.h"
#include "solver/io/demo_model.h"
#include "solver/io/model_input.h"
#include "solver/io/overlap_report.h"
#include "solver/io/plausibility.h"
#include "solver/io/polygon_input.h"
#include "solver/io/progress_estimate.h"
#include "solver/io/pushover_report.h"
#include "solver/io/report.h"
#include "solver/io/report3d.h"
#include "solver/io/report_modes2d.h"
#include "solver/io/step_accelerations.h"
#include "solver/structures/building2d.h"
#include "solver/structures/config3d.h"
#include "solver/structures/isolator.h"
#include "solver/structures/job.h"
#include "solver/structures/pushover2d.h"
#include "solver/structures/pushover3d.h"
#include "solver/study/cli_contract.h"
#include "solver/study/ensemble.h"   // run --ensemble N
#include "solver/study/study_cli.h"  // study commands (sweep, export)

namespace fs = std::filesystem;
using namespace isopound;

namespace {

enum ExitCode { kOk = 0, kFailure = 1, kBadInput = 2, kDiverged = 3 };

// A progress line on stderr for runs longer than a few seconds (rewritten in place), with the
// time left of ProgressEstimate.
class ProgressLine {
 public:
  explicit ProgressLine(bool enabled) : enabled_(enabled), start_(Clock::now()) {}
  ~ProgressLine() {
    if (shown_) std::fputc('\n', stderr);
  }
  void operator()(double t, double total) {
    if (!enabled_) return;
    const auto now = Clock::now();
    if (now - start_ < std::chrono::seconds(3) || now - last_ < std::chrono::milliseconds(500))
      return;
    last_ = now;
    shown_ = true;
    const std::string left =
        estimate_.sample(std::chrono::duration<double>(now - start_).count(), t, total);
    std::fprintf(stderr, "\r  analysed %.4g of %.4g s (%.0f %%), %s   ", t, total, 100 * t / total,
                 left.c_str());
    std::fflush(stderr);
  }

 private:
  using Clock = std::chrono::steady_clock;
  bool enabled_;
  bool shown_ = false;
  Clock::time_point start_, last_{};
  ProgressEstimate estimate_;
};

void create_output_directory(const std::string& out_dir) {
  std::error_code ec;
  fs::create_directories(out_dir, ec);
  if (ec || !fs::is_directory(out_dir))
    throw std::runtime_error("cannot create the output directory '" + out_dir +
                             "': " + (ec ? ec.message() : "a file of that name exists"));
}

int run_and_write(const ModelConfig& config, const std::string& out_dir, bool quiet,
                  bool compare_unobstructed = false,
                  const EnsembleOptions* ensemble_options = nullptr,
                  std::optional<GroundMotion> motion = std::nullopt) {
  create_output_directory(out_dir);
  const std::string summary = (fs::path(out_dir) / "summary.json").string();
  std::string histories;
  std::unique_ptr<CsvHistoryWriter> writer;
  if (config.output.histories) {
    histories = (fs::path(out_dir) / "histories.csv").string();
    writer = std::make_unique<CsvHistoryWriter>(histories);  // rows stream while it runs
  }
  const std::string events = (fs::path(out_dir) / "contact_events.csv").string();
  fs::remove(events);  // a stale log of an earlier run would be read as this run's
  // Exact floor spectra (output.floor_spectra): every step's accelerations; a stale file would be
  // read as this run's.
  const std::string steps = (fs::path(out_dir) / StepAccelerationWriter::kFileName).string();
  fs::remove(steps);
  std::unique_ptr<StepAccelerationWriter> step_writer;
  if (config.output.floor_spectra && !ensemble_options)
    step_writer = std::make_unique<StepAccelerationWriter>(steps);
  JobResult job;
  std::optional<EnsembleResult> ensemble;
  try {
    ProgressLine progress(!quiet);
    if (ensemble_options) {
      ensemble = run_ensemble(config, *ensemble_options, writer.get(), std::ref(progress), events);
      job = std::move(ensemble->member0);
    } else {
      job = run_job(config, writer.get(), std::ref(progress), events, step_writer.get(),
                    std::move(motion));
    }
  } catch (...) {
    // No partial histories.csv from a run that failed (it would look like a result); the event
    // log is kept: it shows the contacts up to the failure.
    writer.reset();
    if (!histories.empty()) fs::remove(histories);
    step_writer.reset();
    fs::remove(steps);
    throw;
  }
  if (writer) writer->close();
  if (step_writer) step_writer->close();
  std::optional<UnobstructedResult> free_run;
  if (compare_unobstructed) free_run = run_unobstructed(config, job);
  if (ensemble) {
    write_summary_with_ensemble(summary, config, job, free_run ? &*free_run : nullptr, *ensemble,
                                *ensemble_options);
    write_ensemble_csv((fs::path(out_dir) / "ensemble.csv").string(), *ensemble);
  } else {
    write_summary(summary, config, job, free_run ? &*free_run : nullptr);
  }
  if (!quiet) {
    print_summary(std::cout, config, job);
    if (free_run) print_unobstructed(std::cout, config, job, *free_run);
    if (ensemble) print_ensemble(std::cout, *ensemble, *ensemble_options);
    std::cout << "Wrote " << summary;
    if (!histories.empty()) std::cout << ", " << histories;
    if (fs::exists(events)) std::cout << ", " << events;
    if (step_writer) std::cout << ", " << steps << " (" << step_writer->steps() << " steps)";
    if (ensemble) std::cout << ", " << (fs::path(out_dir) / "ensemble.csv").string();
    std::cout << '\n';
    if (config.output.floor_spectra && ensemble)
      std::cout << "note: output.floor_spectra is not written for an ensemble; floor-spectra "
                   "uses the histories' rows\n";
  } else if (ensemble) {
    const std::string warning = ensemble_warning(*ensemble, *ensemble_options);
    if (!warning.empty()) std::cerr << "isopound: " << warning << '\n';
  }
  return kOk;
}

// `isopound geometry overlap FILE [--exact]`: a JSON array, one object per pair, on stdout.
int print_overlaps(const std::string& path, bool exact) {
  const std::vector<PolygonPair> pairs = load_polygon_pairs_file(path);
  std::vector<nlohmann::ordered_json> out;
  for (std::size_t k = 0; k < pairs.size(); ++k) {
    const PolygonPair& p = pairs[k];
    const OverlapMethod method = exact ? OverlapMethod::kExact : OverlapMethod::kFast;
    if (!p.a.convex() || !p.b.convex()) {
      out.push_back(plan_overlap_json(int(k), p.name, plan_overlap(p.a, p.b, method),
                                      plan_separation(p.a, p.b)));
      continue;
    }
    const ConvexPolygon& a = p.a.pieces()[0];
    const ConvexPolygon& b = p.b.pieces()[0];
    out.push_back(overlap_json(int(k), p.name, overlap_of(a, b, method), separation_of(a, b)));
  }
  std::cout << overlaps_text(out);
  return kOk;
}

void print_modes(const ModelConfig& config) {
  if (!config.structures3d.empty()) return print_modes3d(std::cout, config);  // report3d.cpp
  print_modes2d(std::cout, config.building);  // report_modes2d.cpp, shared with isopound-pre
  for (const NeighbourConfig& n : config.neighbours) {
    std::cout << '\n';
    print_modes2d(std::cout, n.building);
  }
}

// A command-line option that does not apply to the model is an error naming what to use.
void check_options_apply(const ModelConfig& config, const std::string& record_path,
                         const EnsembleOptions& ensemble, bool jobs_given) {
  if (!record_path.empty() && config.ground_motion.components.size() == 2)
    throw CLI::ValidationError(
        "--record",
        "does not apply to this model: its ground motion is a record pair (ground_motion.L and "
        "ground_motion.T at ground_motion.angle); change L and T in the model file, or run "
        "several pairs with a study (isopound sweep, records: [{L: ..., T: ...}])");
  if (jobs_given && ensemble.members == 0)
    throw CLI::ValidationError("-j", "only applies with --ensemble N (threads for its members)");
}

// The record's peak against the plausibility table (row "pga"): a unit slip (a cm/s^2 file
// read as g) gives a peak of hundreds of g.
void check_record_peak(ModelConfig& config, const GroundMotion& motion,
                       const std::string& record_path) {
  const GroundMotionConfig& g = config.ground_motion;
  const bool any_record =
      !g.use_pulse ||
      (g.components.size() == 2 && !(g.components[0].use_pulse && g.components[1].use_pulse));
  if (!any_record) return;  // the built-in pulse has no unit to slip (its amplitude is m/s)
  double pga = 0.0;
  for (double a : motion.acceleration) pga = std::max(pga, std::abs(a));
  for (double a : motion.acceleration_y) pga = std::max(pga, std::abs(a));
  const std::string text = readable_number(pga / kGravity) + " g";
  const PlausibilityVerdict v =
      check_plausible("ground_motion.pga", dim::kAcceleration, pga, text, true);
  if (v.level == Plausibility::kOk) return;
  const std::string where = record_path.empty()
                                ? "ground_motion (peak ground acceleration of the record as read)"
                                : "--record (peak ground acceleration of the record as read)";
  const std::string hint =
      "; check the record's unit: values in cm/s^2 read as g give 981 times the peak, in "
      "m/s^2 read as g 9.81 times (columns: ground_motion.unit; PEER: the header line)";
  if (v.level == Plausibility::kError)
    throw InputError(config.source, 0, 0, where, v.message + hint);
  config.warnings.push_back(InputError(config.source, 0, 0, where, v.message + hint).what());
}

void print_defaults(const ModelConfig& config, double record_dt) {
  if (config.defaults.empty()) return;
  std::printf("Defaults used (keys not in the file):\n");
  for (const auto& [key, value] : defaults_with_values(config, record_dt, nullptr))
    std::printf("  %s = %s\n", key.c_str(), value.c_str());
}

// isopound-post beside this program (the build tree, an install), else on PATH; "" when absent.
// The demo calls it as a program: the solver links nothing of post/.
std::string find_post_program() {
  std::error_code ec;
  const fs::path beside = fs::read_symlink("/proc/self/exe", ec).parent_path() / "isopound-post";
  if (!ec && access(beside.c_str(), X_OK) == 0) return beside.string();
  return find_on_path("isopound-post");
}

// `isopound demo`: the 3D pounding demo, then its pictures and animation through isopound-post.
int run_demo(const std::string& out_dir, bool quiet, bool pictures) {
  create_output_directory(out_dir);
  const fs::path model = fs::path(out_dir) / "model.yaml";
  {
    std::ofstream file(model);
    file << demo_model_3d_yaml();
    if (!file) throw std::runtime_error("cannot write " + model.string());
  }
  const int code = run_and_write(load_model_file(model.string()), out_dir, quiet);
  if (code != kOk || !pictures) return code;
  const std::string post = find_post_program();
  if (post.empty()) {
    std::fprintf(stderr,
                 "isopound: isopound-post is neither beside isopound nor on PATH: no pictures "
                 "(build or install it, or run with --no-pictures)\n");
    return kFailure;
  }
  if (!quiet) std::printf("\nDrawing the run (isopound-post, headless)...\n");
  std::fflush(stdout);
  ChildOptions quiet_child;
  quiet_child.output_file = "/dev/null";  // its "Wrote ..." lines: the summary below says it all
  for (const std::vector<std::string>& args :
       {std::vector<std::string>{"plot", out_dir}, std::vector<std::string>{"animate", out_dir},
        std::vector<std::string>{"floor-spectra", out_dir}})
    if (run_child(post, args, quiet_child).exit_code != 0) {
      std::fprintf(stderr, "isopound: error: isopound-post %s %s failed\n", args[0].c_str(),
                   out_dir.c_str());
      return kFailure;
    }
  if (!quiet) {
    const fs::path dir(out_dir);
    std::printf(
        "Results:    %s  (summary.json, histories.csv, step-accelerations.csv, "
        "contact_events.csv, model.yaml)\n",
        dir.string().c_str());
    std::printf(
        "Pictures:   %s  (time_histories, trajectory, contacts, hysteresis, floor-spectra .png)\n",
        dir.string().c_str());
    std::printf("Animation:  %s  (animation.pvd: slowed down at every impact; view.py)\n",
                (dir / "animation").string().c_str());
    std::printf("Watch it in ParaView:  paraview --script=%s\n",
                (dir / "animation" / "view.py").string().c_str());
  }
  return kOk;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"isopound: nonlinear time-history analysis of base-isolated buildings"};
  app.require_subcommand(1);
  app.set_version_flag("--version", std::string("isopound ") + kIsopoundVersion);
  std::string model_path, record_path, out_dir = "isopound-out";
  bool quiet = false, no_histories = false, compare_unobstructed = false;

  CLI::App* run = app.add_subcommand("run", "Run a model: writes summary.json and histories.csv");
  run->add_option("model", model_path, "Model file (YAML)")->required();
  run->add_option("--record", record_path, "Ground-motion file; overrides the model's");
  run->add_option("-o,--output", out_dir, "Output directory")->capture_default_str();
  run->add_flag("-q,--quiet", quiet, "Print nothing on success");
  run->add_flag("--no-histories", no_histories, "Skip histories.csv");
  run->add_flag("--compare-unobstructed", compare_unobstructed,
                "Also run without walls and neighbours; report each peak's amplification");
  CliWarnings cli_warnings;  // implausible quantity options, listed with the model's warnings
  double until = 0.0;
  quantity_option(
      run->add_option("--until", until,
                      "Stop the analysis at this time, e.g. '5 s' (a bare number is s; the rule "
                      "of analysis.t_end)"),
      {dim::kTime, "analysis.t_end", true}, &cli_warnings);
  bool strict = false;
  run->add_flag("--strict", strict, "Implausible values (warnings) are errors: exit 2");
  EnsembleOptions ensemble;
  ensemble.members = 0;
  ensemble.jobs = 0;  // all cores, as in sweep
  run->add_option("--ensemble", ensemble.members,
                  "Run N members, each but the first with its base slab offset by 1 um; report "
                  "every peak's spread and the predictability horizon")
      ->check(CLI::Range(2, 100000));
  run->add_option("-j,--jobs", ensemble.jobs,
                  "Threads for --ensemble; 0 = all cores (default), as in sweep")
      ->check(at_least(0));

  bool demo_2d = false, no_pictures = false;
  CLI::App* demo = app.add_subcommand(
      "demo",
      "An isolated building pounding its moat walls (3D, built-in pulse pair), with its pictures "
      "and a ParaView animation");
  demo->add_option("-o,--output", out_dir, "Output directory")->capture_default_str();
  demo->add_flag("-q,--quiet", quiet, "Print nothing on success");
  demo->add_flag("--2d", demo_2d,
                 "the 2D demo instead: the 3-storey shear building on Bouc-Wen isolators under "
                 "the built-in pulse, no walls, no pictures; into isopound-out-2d unless -o");
  demo->add_flag("--no-pictures", no_pictures, "run only: no isopound-post pictures or animation");

  CLI::App* modes =
      app.add_subcommand("modes", "Periods and mode shapes of every structure of a model");
  modes->add_option("model", model_path, "Model file (YAML)")->required();
  modes->add_flag("-q,--quiet", quiet, "Check the model, print nothing");
  modes->add_flag("--strict", strict, "Implausible values (warnings) are errors: exit 2");

  CLI::App* check = app.add_subcommand("check", "Read and validate a model, run nothing");
  check->add_option("model", model_path, "Model file (YAML)")->required();
  check->add_flag("-q,--quiet", quiet, "Print nothing when the model is valid");
  check->add_flag("--strict", strict, "Implausible values (warnings) are errors: exit 2");

  CLI::App* geometry = app.add_subcommand("geometry", "Geometry of plans (convex or any simple outline)");
  geometry->require_subcommand(1);
  CLI::App* overlap = geometry->add_subcommand(
      "overlap",
      "Overlap of polygon pairs (area, centroid, crossings, normal, indentation) as JSON; a "
      "non-convex pair: one such object per connected component (contact)");
  std::string pairs_path;
  bool exact = false;
  overlap->add_option("file", pairs_path, "YAML file with pairs: [{a: [[x, y], ...], b: ...}]")
      ->required();
  overlap->add_flag("--exact", exact, "Use exact rational arithmetic (slower reference path)");

  CLI::App* pushover = app.add_subcommand(
      "pushover",
      "Static pushover of a building (2D in x, 3D along --angle) to a target roof drift: "
      "pushover.csv (capacity curve) and pushover.json");
  pushover->add_option("model", model_path, "Model file (YAML)")->required();
  pushover->add_option("-o,--output", out_dir, "Output directory")->capture_default_str();
  std::string pattern = "first_mode";
  double target_drift = 0.02, push_angle = 0.0;
  int pushover_steps = 200;
  quantity_option(pushover->add_option("--target-drift", target_drift,
                                       "Roof drift ratio to reach, e.g. '2 %' (default 2 %; a "
                                       "bare number is a ratio: 0.02)"),
                  {dim::kNone, "pushover.target_drift_ratio", true}, &cli_warnings);
  pushover->add_option("--pattern", pattern, "Lateral load pattern")
      ->check(CLI::IsMember({"first_mode", "uniform"}))
      ->capture_default_str();
  angle_option(pushover->add_option("--angle", push_angle,
                                    "3D: direction of the push in plan from x, counter-clockwise, "
                                    "with its unit, e.g. '30 deg' (default 0 deg)"));
  pushover->add_option("--steps", pushover_steps, "Displacement steps")
      ->check(CLI::Range(1, 1000000))
      ->capture_default_str();
  pushover->add_flag("-q,--quiet", quiet, "Print nothing on success");

  const StudyCommands study_commands = add_study_commands(app);  // study commands (sweep, export)

  // Usage errors are bad input (exit 2) like any other; --help and --version exit 0.
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return code == 0 ? kOk : kBadInput;
  }
  if (const auto code = run_study_command(study_commands))
    return *code;  // study commands (sweep, export)

  try {
    if (*demo)
      // The 2D demo's own default folder: it must not overwrite half of the 3D demo's results
      // and leave the 3D pictures beside them.
      return demo_2d ? run_and_write(demo_model_2d(),
                                     demo->count("--output") ? out_dir : "isopound-out-2d", quiet)
                     : run_demo(out_dir, quiet, !no_pictures);
    if (*overlap) return print_overlaps(pairs_path, exact);
    ModelConfig config = load_model_file(model_path);
    check_options_apply(config, record_path, ensemble, run->count("--jobs") > 0);
    if (!record_path.empty()) {
      config.ground_motion.use_pulse = false;
      config.ground_motion.record_path = record_path;
    }
    // Implausible quantity options are warned like the model's values (refused under --strict).
    const bool has_strict = *run || *modes || *check;
    for (const std::string& w : cli_warnings)
      config.warnings.push_back(w + (has_strict ? " (--strict makes this an error)" : ""));
    if (no_histories) config.output.histories = false;
    if (until > 0) config.analysis.t_end = until;
    if (ensemble.jobs == 0)
      ensemble.jobs = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
    // The record is read before anything runs: its unit is stated and its peak checked.
    std::optional<GroundMotion> motion;
    if (*run || *check) {
      if (*check && !quiet) std::printf("%s: reading the ground motion...\n", model_path.c_str());
      motion = load_ground_motion(config.ground_motion, !config.structures3d.empty());
      check_record_peak(config, *motion, record_path);
      if (!quiet && !motion->unit_note.empty()) std::printf("%s\n", motion->unit_note.c_str());
    }
    if (!config.warnings.empty()) {
      for (const std::string& w : config.warnings)
        std::cerr << "isopound: " << (strict ? "error: " : "warning: ") << w << '\n';
      if (strict) {
        std::cerr << "isopound: error: " << config.warnings.size()
                  << " implausible value(s) refused by --strict\n";
        return kBadInput;
      }
    }
    if (*run)
      return run_and_write(config, out_dir, quiet, compare_unobstructed,
                           ensemble.members > 0 ? &ensemble : nullptr, std::move(motion));
    if (*pushover) {
      BuildingPushoverOptions options;
      options.target_drift_ratio = target_drift;
      if (!(target_drift < 1))
        throw std::invalid_argument("--target-drift must be in (0, 100 %), got " +
                                    readable_number(100 * target_drift) +
                                    " % (a bare number is a ratio)");
      options.pattern = pattern == "uniform" ? BuildingPushoverOptions::Pattern::kUniform
                                             : BuildingPushoverOptions::Pattern::kFirstMode;
      options.steps = pushover_steps;
      const bool plan = !config.structures3d.empty();
      if (pushover->count("--angle") > 0) {
        if (!plan)
          throw std::invalid_argument("--angle is for 3D models: a 2D building is pushed in x");
        options.angle = push_angle;
      }
      const BuildingPushoverResult result =
          plan ? run_pushover3d(config, options) : run_pushover2d(config, options);
      create_output_directory(out_dir);
      const std::string csv = (fs::path(out_dir) / "pushover.csv").string();
      write_pushover_csv(csv, result);
      write_pushover_json((fs::path(out_dir) / "pushover.json").string(), model_path, options,
                          result);
      if (!quiet) {
        const auto& last = result.rows.back();
        char direction[64] = "";
        if (plan)
          std::snprintf(direction, sizeof direction, " pushed at %g deg",
                        options.angle * 180 / std::numbers::pi);
        std::printf(
            "%s: building '%s'%s: roof %.2f cm (drift %.3f %%), base shear %.1f kN; "
            "wrote %s\n",
            model_path.c_str(), result.building.c_str(), direction, 100 * last[0], 100 * last[1],
            last[2] / 1e3, csv.c_str());
        if (result.first_yield_row >= 0)
          std::printf("  first yield at roof %.2f cm, base shear %.1f kN\n",
                      100 * result.rows[result.first_yield_row][0],
                      result.rows[result.first_yield_row][2] / 1e3);
        if (result.capping_row >= 0)
          std::printf("  capping (peak base shear) at roof %.2f cm, %.1f kN\n",
                      100 * result.rows[result.capping_row][0],
                      result.rows[result.capping_row][2] / 1e3);
      }
      return kOk;
    }
    if (*modes) {
      if (!quiet) print_modes(config);
      return kOk;
    }
    if (*check) {
      check_step_against_record(config.analysis, *motion);
      Model model = build_model(config);
      if (!quiet) {
        std::printf("%s: ok (%d DOFs, %zu ground-motion samples at %g s)\n", model_path.c_str(),
                    model.size(), motion->acceleration.size(), motion->dt);
        print_defaults(config, motion->dt);
      }
      return kOk;
    }
  } catch (const InputError& e) {
    // One line per error (the site checks report all of theirs at once: InputErrors).
    std::istringstream lines(e.what());
    for (std::string line; std::getline(lines, line);)
      std::cerr << "isopound: error: " << line << '\n';
    return kBadInput;
  } catch (const CLI::ValidationError& e) {
    std::cerr << "isopound: error: " << e.what() << '\n';
    return kBadInput;
  } catch (const RecordError& e) {
    // Name what pointed at the file: the model key or the command-line option.
    std::cerr << "isopound: error: " << e.what() << " (the record given by "
              << (record_path.empty() ? model_path + ": ground_motion.record" : "--record")
              << ")\n";
    return kBadInput;
  } catch (const AnalysisError& e) {
    std::cerr << "isopound: error: " << e.what() << '\n';
    return kDiverged;
  } catch (const std::invalid_argument& e) {
    std::cerr << "isopound: error: " << (model_path.empty() ? "" : model_path + ": ") << e.what()
              << '\n';
    return kBadInput;
  } catch (const std::exception& e) {
    std::cerr << "isopound: error: " << e.what() << '\n';
    return kFailure;
  }
  return kOk;
}
