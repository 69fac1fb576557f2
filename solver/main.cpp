// isopound command line: run a model, show its modes, check it, or run the built-in demo.
// Errors are printed as "file:line:col: key: what" and give a non-zero exit code.
#include <CLI/CLI.hpp>
#include <cstdio>
#include <filesystem>
#include <iostream>

#include "solver/core/modes.h"
#include "solver/io/model_input.h"
#include "solver/io/report.h"
#include "solver/io/report3d.h"
#include "solver/structures/building2d.h"
#include "solver/structures/config3d.h"
#include "solver/structures/isolator.h"
#include "solver/structures/job.h"
#include "solver/study/study_cli.h"  // study commands (sweep, export)

namespace fs = std::filesystem;
using namespace isopound;

namespace {

enum ExitCode { kOk = 0, kFailure = 1, kBadInput = 2, kDiverged = 3 };

// The thesis's 3-storey building (THEORY section 1) with Bouc-Wen isolators, T_b = 2 s,
// Q/W = 5 %, u_y = 1 cm, under the built-in near-fault pulse.
ModelConfig demo_config() {
  ModelConfig c;
  c.source = "(built-in demo)";
  c.building.name = "3-storey";
  c.building.base_mass = 340e3;
  c.building.floors = {{340e3, 600e6, 3.2}, {340e3, 600e6, 3.2}, {250e3, 600e6, 3.2}};
  c.ground_motion.use_pulse = true;
  return c;
}

int run_and_write(const ModelConfig& config, const std::string& out_dir, bool quiet,
                  bool compare_unobstructed = false) {
  const JobResult job = run_job(config);
  JobResult free_job;
  if (compare_unobstructed) {
    ModelConfig free_config = config;
    free_config.building.walls.clear();
    free_config.neighbours.clear();
    free_config.output.histories = false;
    free_job = run_job(free_config);
  }
  fs::create_directories(out_dir);
  const std::string summary = (fs::path(out_dir) / "summary.json").string();
  write_summary(summary, config, job, compare_unobstructed ? &free_job : nullptr);
  std::string histories;
  if (config.output.histories) {
    histories = (fs::path(out_dir) / "histories.csv").string();
    write_histories(histories, job.analysis.history);
  }
  if (!quiet) {
    print_summary(std::cout, config, job);
    std::cout << "Wrote " << summary;
    if (!histories.empty()) std::cout << " and " << histories;
    std::cout << '\n';
  }
  return kOk;
}

void print_modes(const ModelConfig& config) {
  if (!config.structures3d.empty()) return print_modes3d(std::cout, config);  // report3d.cpp
  const BuildingConfig& b = config.building;
  const auto show = [](const char* title, const Modes& m, const std::vector<std::string>& labels) {
    std::printf("%s\n  mode  period [s]  eff. mass [%%]  shape (%s ... %s, max = 1)\n", title,
                labels.front().c_str(), labels.back().c_str());
    for (int j = 0; j < m.period.size(); ++j) {
      std::printf("  %4d  %10.4f  %13.1f  ", j + 1, m.period[j], 100 * m.effective_mass_ratio[j]);
      const double scale = m.shape.col(j).cwiseAbs().maxCoeff();
      for (int i = 0; i < m.shape.rows(); ++i) std::printf(" %+.3f", m.shape(i, j) / scale);
      std::printf("\n");
    }
  };
  std::vector<std::string> floor_labels;
  for (std::size_t i = 0; i < b.floors.size(); ++i)
    floor_labels.push_back("floor " + std::to_string(i + 1));
  const ShearStick fixed = fixed_base_superstructure(b);
  show("Fixed-base superstructure",
       compute_modes(fixed.stiffness, fixed.mass, Eigen::VectorXd::Ones(fixed.mass.rows())),
       floor_labels);
  if (!b.isolated) return;
  Model model = make_model(b);
  std::vector<std::string> labels{"base"};
  labels.insert(labels.end(), floor_labels.begin(), floor_labels.end());
  const IsolatorProperties p = isolator_properties(b.isolator, model.total_mass());
  for (const auto& [name, k] : {std::pair{"post-yield stiffness K_post", p.post_yield_stiffness},
                                std::pair{"initial stiffness K_el", p.elastic_stiffness}}) {
    if (b.isolator.model == IsolatorConfig::Model::kLinear && k != p.post_yield_stiffness) continue;
    Eigen::MatrixXd K = model.stiffness;
    K(0, 0) += k;
    const std::string title = std::string("Isolated, isolators at their ") + name + " = " +
                              std::to_string(k / 1e6) + " MN/m";
    show(title.c_str(), compute_modes(K, model.mass, model.influence), labels);
  }
  std::printf("Isolators: K_post %.4g N/m, F_y %.4g N, K_el %.4g N/m, alpha %.4f, Q %.4g N\n",
              p.post_yield_stiffness, p.yield_force, p.elastic_stiffness, p.alpha,
              p.characteristic_strength);
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"isopound: nonlinear time-history analysis of base-isolated buildings"};
  app.require_subcommand(1);
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

  CLI::App* demo = app.add_subcommand(
      "demo", "3-storey Bouc-Wen isolated building under the built-in near-fault pulse");
  demo->add_option("-o,--output", out_dir, "Output directory")->capture_default_str();

  CLI::App* modes = app.add_subcommand("modes", "Periods and mode shapes of a model");
  modes->add_option("model", model_path, "Model file (YAML)")->required();

  CLI::App* check = app.add_subcommand("check", "Read and validate a model, run nothing");
  check->add_option("model", model_path, "Model file (YAML)")->required();

  const StudyCommands study_commands = add_study_commands(app);  // study commands (sweep, export)

  CLI11_PARSE(app, argc, argv);
  if (const auto code = run_study_command(study_commands))
    return *code;  // study commands (sweep, export)

  try {
    if (*demo) return run_and_write(demo_config(), out_dir, false);
    ModelConfig config = load_model_file(model_path);
    if (!record_path.empty()) {
      config.ground_motion.use_pulse = false;
      config.ground_motion.record_path = record_path;
    }
    if (no_histories) config.output.histories = false;
    if (*run) return run_and_write(config, out_dir, quiet, compare_unobstructed);
    if (*modes) {
      print_modes(config);
      return kOk;
    }
    if (*check) {
      const GroundMotion motion =
          load_ground_motion(config.ground_motion, !config.structures3d.empty());
      Model model = build_model(config);
      std::printf("%s: ok (%d DOFs, %zu ground-motion samples at %g s)\n", model_path.c_str(),
                  model.size(), motion.acceleration.size(), motion.dt);
      return kOk;
    }
  } catch (const InputError& e) {
    std::cerr << "isopound: error: " << e.what() << '\n';
    return kBadInput;
  } catch (const RecordError& e) {
    std::cerr << "isopound: error: " << e.what() << '\n';
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
