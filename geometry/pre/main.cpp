// isopound-pre: a model file checked and drawn before any analysis (issue 12). Checks (all
// problems in one run), section and stiffness properties (DIR/properties.json), periods, Gmsh
// files per level and of the site, plan.png. Exit codes: 0 fine (warnings allowed unless
// --strict), 2 the model has errors (each printed as "file:line:col: key: what"), 1 anything else.
#include <CLI/CLI.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

#include "geometry/pre/checks.h"
#include "geometry/pre/gmsh_files.h"
#include "geometry/pre/model_scan.h"
#include "geometry/pre/plan_figure.h"
#include "geometry/pre/properties.h"
#include "post/headless.h"
#include "post/render_png.h"
#include "solver/core/modes.h"
#include "solver/io/report.h"
#include "solver/io/report3d.h"
#include "solver/io/report_modes2d.h"
#include "solver/io/units.h"
#include "solver/structures/building3d.h"
#include "solver/structures/config3d.h"
#include "solver/structures/site_plan.h"

namespace fs = std::filesystem;
using namespace isopound;
using namespace isopound::pre;

namespace {

enum ExitCode { kOk = 0, kFailure = 1, kBadInput = 2 };

// Periods as `isopound modes` computes them, for properties.json.
nlohmann::ordered_json periods_json(const ModelConfig& config) {
  nlohmann::ordered_json out = nlohmann::ordered_json::array();
  for (const Building3DConfig& b : config.structures3d) {
    nlohmann::ordered_json s;
    s["name"] = b.name;
    const auto table = [&](const LinearModel3D& m) {
      const Modes mx = compute_modes(m.stiffness, m.mass, m.influence.col(0));
      const Modes my = compute_modes(m.stiffness, m.mass, m.influence.col(1));
      nlohmann::ordered_json rows = nlohmann::ordered_json::array();
      for (int j = 0; j < mx.period.size(); ++j) {
        const Eigen::VectorXd phi = mx.shape.col(j), mphi = m.mass * phi;
        double torsion = 0.0;
        for (int i = 0; i < phi.size(); ++i)
          if (m.dofs[i].kind == DofKind::kRotation) torsion += phi[i] * mphi[i];
        rows.push_back({{"mode", j + 1},
                        {"period_s", mx.period[j]},
                        {"effective_mass_x", mx.effective_mass_ratio[j]},
                        {"effective_mass_y", my.effective_mass_ratio[j]},
                        {"torsional_share", torsion}});
      }
      return rows;
    };
    s["fixed_base"] = table(linear_model3d(b, false, true));
    if (b.isolated) s["isolated_post_yield"] = table(linear_model3d(b, false, false));
    out.push_back(s);
  }
  return out;
}

void write_text(const fs::path& path, const std::string& text) {
  std::ofstream out(path);
  out << text;
  if (!out) throw std::runtime_error("cannot write " + path.string());
}

std::string clearances_text(const std::vector<Clearance>& clearances) {
  std::string out =
      "Clearances at rest (measured between plan outlines: floors at equal levels, else the "
      "nearest approach):\n";
  char line[400];
  for (const Clearance& c : clearances) {
    std::snprintf(line, sizeof line, "  %-28s %-6s of it: %-28s %9.4f m", c.a.c_str(),
                  c.side.c_str(), c.b.c_str(), c.measured);
    out += line;
    if (c.declared >= 0) {
      std::snprintf(line, sizeof line, "  (declared %.4f m)", c.declared);
      out += line;
    }
    out += "\n";
  }
  return out;
}

int run(const std::string& model_path, const std::string& out_dir,
        const std::optional<std::string>& angle_text, bool no_plan, bool strict) {
  ProblemList problems;
  ScannedModel model = scan_model(model_path, problems);
  std::optional<double> angle;
  if (angle_text) {
    try {
      angle = parse_angle(*angle_text);
    } catch (const std::exception& e) {
      std::cerr << "--angle: " << e.what() << '\n';
      return kBadInput;
    }
  }
  Site site;
  std::vector<StructureProperties> properties;
  std::vector<Clearance> clearances;
  CheckLimits limits;
  if (model.config) {
    if (model.is3d) {
      site = site_plan(*model.config);
      properties = structure_properties(*model.config);
      // The reader ran the site checks (their problems are in `problems`); run again, into a
      // list of their own, for the clearances they measure.
      ProblemList again;
      clearances =
          check_site3d(*model.config, model.structures, site, site_limits(*model.config), again);
      check_structures(model, site, properties, limits, problems);
    } else {
      check_model2d(model, limits, problems);
    }
  }
  std::cout << "Checks of " << model_path << ": " << problems.errors() << " error"
            << (problems.errors() == 1 ? "" : "s") << ", " << problems.warnings() << " warning"
            << (problems.warnings() == 1 ? "" : "s") << "\n";
  for (const Problem& p : problems.all())
    std::cout << (p.severity == Problem::Severity::kError ? "error: " : "warning: ") << p.message
              << "\n";
  if (!model.config) {
    std::cout << "The model could not be read to the end: the checks that need the whole model "
                 "did not run.\n";
    return kBadInput;
  }
  if (model.is3d && !clearances.empty()) std::cout << "\n" << clearances_text(clearances);

  std::error_code ec;
  fs::create_directories(out_dir, ec);
  if (!fs::is_directory(out_dir))
    throw std::runtime_error("cannot create the output directory '" + out_dir + "'");

  nlohmann::ordered_json json;
  json["model"] = model_path;
  json["problems"] = nlohmann::ordered_json::array();
  for (const Problem& p : problems.all())
    json["problems"].push_back(
        {{"severity", p.severity == Problem::Severity::kError ? "error" : "warning"},
         {"message", p.message}});
  if (model.is3d) {
    GmshSession gmsh;
    // Area integrals twice: polygon formulas and a Gmsh triangle mesh (Gauss points).
    for (std::size_t i = 0; i < properties.size(); ++i) {
      std::size_t level = 0;
      for (const PlanSlab& s : site.slabs) {
        if (s.structure != static_cast<int>(i)) continue;
        DiaphragmProperties& d = properties[i].diaphragms[level++];
        d.mesh = mesh_area_properties(s.plan_W, std::sqrt(d.exact.area) / 8.0, d.triangles);
        d.meshed = true;
        const double size = std::sqrt(d.exact.area);
        d.relative_difference = std::max(
            {std::abs(d.mesh.area - d.exact.area) / d.exact.area,
             std::hypot(d.mesh.p_WC.x - d.exact.p_WC.x, d.mesh.p_WC.y - d.exact.p_WC.y) / size,
             std::abs(d.mesh.polar_moment_c - d.exact.polar_moment_c) / d.exact.polar_moment_c});
      }
    }
    std::cout << "\nProperties (area integrals: polygon formulas; last column: largest relative "
                 "difference to a Gmsh triangle mesh)\n"
              << properties_text(properties);
    std::cout << "\nPeriods (as isopound modes prints them)\n";
    try {
      print_modes3d(std::cout, *model.config);
      json["periods"] = periods_json(*model.config);
    } catch (const std::exception& e) {
      std::cout << "  no periods: " << e.what() << "\n";
    }
    json["structures"] = properties_json(properties);
    json["clearances"] = nlohmann::ordered_json::array();
    for (const Clearance& c : clearances) {
      nlohmann::ordered_json j{{"a", c.a},
                               {"b", c.b},
                               {"side", c.side},
                               {"elevation_m", c.elevation},
                               {"measured_m", c.measured}};
      if (c.declared >= 0) j["declared_m"] = c.declared;
      json["clearances"].push_back(j);
    }
    json["gmsh_files"] = nlohmann::ordered_json::array();
    for (const GmshFile& f : write_gmsh_files(site, out_dir)) {
      nlohmann::ordered_json j{{"msh", f.stem + ".msh"}, {"geo", f.stem + ".geo_unrolled"}};
      if (f.elevation >= 0) j["elevation_m"] = f.elevation;
      j["physical_groups"] = f.groups;
      json["gmsh_files"].push_back(j);
    }
    std::cout << "\nWrote " << json["gmsh_files"].size() << " Gmsh models (.geo_unrolled, .msh) to "
              << out_dir << "\n";
    if (!no_plan) {
      if (!angle) angle = model.config->ground_motion.angle;
      PlanOptions options;
      options.title = "Site plan of " + fs::path(model_path).filename().string();
      options.angle = angle;
      const post::Figure figure =
          plan_figure(site, properties, clearances, struck_column_sites(*model.config), options);
      post::PrivateDisplay display(false);
      const std::string png = (fs::path(out_dir) / "plan.png").string();
      post::render_png(figure, png);
      std::cout << "Wrote " << png << "\n";
    }
  } else {
    std::cout << "\nPeriods (as isopound modes prints them)\n";
    std::ostringstream text;
    print_modes2d(text, model.config->building);
    for (const NeighbourConfig& n : model.config->neighbours) {
      text << "\n";
      print_modes2d(text, n.building);
    }
    std::cout << text.str();
  }
  write_text(fs::path(out_dir) / "properties.json", json.dump(2) + "\n");
  std::cout << "Wrote " << (fs::path(out_dir) / "properties.json").string() << "\n";
  return problems.errors() > 0 || (strict && problems.warnings() > 0) ? kBadInput : kOk;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{
      "isopound-pre: check a model, its section and stiffness properties, periods, Gmsh files and "
      "a plan picture, before any analysis"};
  std::string model_path, out_dir = "isopound-pre-out";
  std::optional<std::string> angle;
  bool no_plan = false, strict = false;
  app.add_option("model", model_path, "Model file (YAML)")->required();
  app.add_option("-o,--output", out_dir, "Output directory")->capture_default_str();
  app.add_option("--angle", angle,
                 "Direction of the record's L component in the plan, e.g. '30 deg' (default: the "
                 "model's ground_motion.angle)");
  app.add_flag("--no-plan", no_plan, "Skip plan.png (no X server needed)");
  app.add_flag("--strict", strict, "Warnings also give exit code 2");
  app.set_version_flag("--version", std::string("isopound-pre ") + kIsopoundVersion);
  // Usage errors are bad input (exit 2), as in isopound and isopound-post; --help exits 0.
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e) == 0 ? kOk : kBadInput;
  }
  try {
    return run(model_path, out_dir, angle, no_plan, strict);
  } catch (const InputError& e) {
    std::cerr << e.what() << '\n';
    return kBadInput;
  } catch (const std::exception& e) {
    std::cerr << "isopound-pre: " << e.what() << '\n';
    return kFailure;
  }
}
