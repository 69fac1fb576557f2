// 3D outputs from the model's plan probes (labels "building/level/point", "building/story k/
// column") and the bearing elements. Every peak has the 2D summary's shape (report.h, peak_json).
#include "solver/io/report3d.h"

#include <cstdio>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include "solver/core/constants.h"
#include "solver/core/modes.h"
#include "solver/elements/polygon_contact.h"
#include "solver/io/report.h"
#include "solver/io/report_columns3d.h"
#include "solver/structures/building3d.h"
#include "solver/structures/levels3d.h"
#include "solver/structures/pounding3d.h"

namespace isopound {
namespace {

struct Label {
  std::string building, part, point;
};

Label split(const std::string& label) {
  const auto a = label.find('/');
  const auto b = label.rfind('/');
  return {label.substr(0, a), label.substr(a + 1, b - a - 1), label.substr(b + 1)};
}

// x, y and the resultant sqrt(x^2 + y^2) of a plan point, each a peak of the common shape.
nlohmann::json peaks(const ProbePeaks& p, const char* unit) {
  return {{"x", peak_json(p.x, unit)},
          {"y", peak_json(p.y, unit)},
          {"resultant", peak_json(p.resultant, unit)}};
}

}  // namespace

// Grid corner columns: the extreme letters and numbers among labels like "A1", "D4".
std::vector<std::string> corner_column_labels(const std::vector<std::string>& labels) {
  char lo = 'Z' + 1, hi = 'A' - 1;
  int nlo = 1 << 30, nhi = -1;
  for (const std::string& l : labels) {
    if (l.size() < 2 || l[0] < 'A' || l[0] > 'Z') return {};
    const int n = std::atoi(l.c_str() + 1);
    lo = std::min(lo, l[0]);
    hi = std::max(hi, l[0]);
    nlo = std::min(nlo, n);
    nhi = std::max(nhi, n);
  }
  if (labels.empty()) return {};
  return {lo + std::to_string(nlo), hi + std::to_string(nlo), lo + std::to_string(nhi),
          hi + std::to_string(nhi)};
}

nlohmann::json summary3d_json(const JobResult& job) {
  using nlohmann::json;
  const Model& model = job.model;
  const AnalysisResult& r = job.analysis;
  json buildings = json::array();
  for (const StructureInfo& s : model.structures) {
    json jb;
    jb["name"] = s.name;
    // Levels: DOF peaks and the plan points.
    std::map<std::string, json> levels;
    std::vector<std::string> level_order;
    for (std::size_t l = 0; l < s.level_dofs.size(); ++l) {
      const int d = s.level_dofs[l];
      const std::string name = split(model.dofs[d].label + "/x").part;
      const std::string level = name.substr(0, name.rfind(' '));
      level_order.push_back(level);
      levels[level] = {{"label", level},
                       {"u", peak_json(r.displacement[d], "m")},
                       {"v", peak_json(r.displacement[d + 1], "m")},
                       {"theta", peak_json(r.displacement[d + 2], "rad")}};
    }
    std::map<std::string, json> stories;
    std::vector<std::string> story_order;
    for (std::size_t p = 0; p < model.probes.size(); ++p) {
      const PlanProbe& probe = model.probes[p];
      const Label l = split(probe.label);
      if (l.building != s.name) continue;
      const ProbePeaks& pk = r.probes[p];
      if (l.part == kStoreyShearPart) continue;  // report_columns3d.cpp
      if (levels.count(l.part)) {
        json& lev = levels[l.part];
        const bool acc = probe.quantity == PlanProbe::Quantity::kAbsoluteAcceleration;
        json& point = lev[l.point == "CM" ? "centre_of_mass" : "corners"];
        if (l.point == "CM") {
          point[acc ? "absolute_acceleration" : "displacement"] = peaks(pk, acc ? "m/s2" : "m");
        } else {
          if (!point.is_array()) point = json::array();
          if (!acc)
            point.push_back({{"label", l.point}, {"displacement", peaks(pk, "m")}});
          else
            point.back()["absolute_acceleration"] = peaks(pk, "m/s2");
        }
        continue;
      }
      if (!stories.count(l.part)) {
        story_order.push_back(l.part);
        stories[l.part] = {
            {"label", l.part}, {"height_m", probe.length}, {"columns", json::array()}};
      }
      json col = peaks(pk, "m");
      col["label"] = l.point;
      col["drift_ratio"] = peak_json(pk.ratio, "-");
      stories[l.part]["columns"].push_back(col);
    }
    json jl = json::array();
    for (const std::string& l : level_order) jl.push_back(levels[l]);
    jb["levels"] = jl;
    json js = json::array();
    for (const std::string& name : story_order) {
      json& st = stories[name];
      // Envelope over columns: for each quantity the peak of the column where it is largest.
      json env = json::object();
      std::vector<std::string> labels;
      for (const json& c : st["columns"]) {
        labels.push_back(c["label"]);
        for (const char* k : {"x", "y", "resultant", "drift_ratio"})
          if (!env.contains(k) || c[k]["value"].get<double>() > env[k]["value"].get<double>()) {
            env[k] = c[k];
            env[k]["column"] = c["label"];
          }
      }
      st["envelope_over_columns"] = env;
      json corners = json::object();
      for (const std::string& label : corner_column_labels(labels))
        for (const json& c : st["columns"])
          if (c["label"] == label) corners[label] = c;
      st["corner_columns"] = corners;
      js.push_back(st);
    }
    jb["storeys"] = js;
    add_column_yield_json(job, s, jb);  // report_columns3d.h
    json bearings = json::array();
    for (std::size_t e = 0; e < model.elements.size(); ++e) {
      const Element& el = *model.elements[e];
      if (el.label().rfind(s.name + "/bearing ", 0) != 0) continue;
      json je = {{"label", el.label()}};
      for (int k = 0; k < el.output_count(); ++k)
        je[el.output_name(k)] = peak_json(r.element_outputs[e][k], el.output_unit(k));
      bearings.push_back(je);
    }
    jb["bearings"] = bearings;
    // Isolated above a storey (levels3d.h): the bearings' deformation is relative to floor k.
    if (s.has_base && s.base_level > 0) {
      jb["isolation_level"] = s.base_level;
      jb["isolation_height_m"] = s.isolation_height;
    }
    if (s.has_base) {  // everything reaching the foundation (analysis.h), in x, y and resultant
      const std::size_t si = static_cast<std::size_t>(&s - model.structures.data());
      jb["base_shear"] = {{"x", peak_json(r.base_shear[si], "N")},
                          {"y", peak_json(r.base_shear_y[si], "N")},
                          {"resultant", peak_json(r.base_shear_resultant[si], "N")}};
    }
    buildings.push_back(jb);
  }
  return buildings;
}

namespace {

// A rubber bumper's contact (element e) and its bottomed strip's, the next element
// (pounding3d.h): bottomings are that one's impacts.
nlohmann::json bumper_json(const JobResult& job, std::size_t e, const BumperLaw& rubber) {
  using nlohmann::json;
  const auto& elements = job.model.elements;
  const auto* bottomed = e + 1 < elements.size()
                             ? dynamic_cast<const PolygonContact*>(elements[e + 1].get())
                             : nullptr;
  // (a non-convex slab's slots: "... bumper #2" is followed by "... bumper bottomed #2")
  if (!bottomed || !without_slot(bottomed->label()).ends_with(kBottomedLabel))
    throw std::logic_error("bumper contact " + elements[e]->label() +
                           " without its bottomed strip");
  const double first = e + 1 < job.first_impact_time.size() ? job.first_impact_time[e + 1] : -1.0;
  return {{"thickness_m", rubber.thickness()},
          {"peak_compression_m", job.analysis.element_outputs[e][3].value},
          {"bottomings", bottomed->impacts()},
          {"first_bottoming_s", first >= 0 ? json(first) : json(nullptr)},
          {"dissipated_J", elements[e]->output(10)}};
}

}  // namespace

nlohmann::json contacts3d_json(const JobResult& job) {
  using nlohmann::json;
  const Model& model = job.model;
  const AnalysisResult& r = job.analysis;
  json out = json::array();
  for (std::size_t e = 0; e < model.elements.size(); ++e) {
    const auto* c = dynamic_cast<const PolygonContact*>(model.elements[e].get());
    if (!c) continue;
    const std::string& label = c->label();
    const auto bar = label.find('|');
    json jc = {{"label", label}, {"a", label.substr(0, bar)}, {"b", label.substr(bar + 1)}};
    const std::vector<Peak>& p = r.element_outputs[e];
    jc["impacts"] = c->impacts();
    jc["impacts_above_1mm_s"] = c->impacts_above_1mm_s();
    const double first = e < job.first_impact_time.size() ? job.first_impact_time[e] : -1.0;
    jc["first_impact_time_s"] = first >= 0 ? json(first) : json(nullptr);
    jc["normal_force"] = peak_json(p[0], "N");
    jc["tangential_force"] = peak_json(p[1], "N");
    jc["area"] = peak_json(p[2], "m2");
    jc["indentation"] = peak_json(p[3], "m");
    jc["impact_velocity"] = peak_json(p[5], "m/s");
    jc["time_in_stick_s"] = c->output(7);
    jc["time_in_slip_s"] = c->output(8);
    jc["friction_dissipated_J"] = c->output(9);
    jc["impact_dissipated_J"] = c->output(10);
    // Passivity: completed contact episodes (onset to separation) and the largest net work the
    // contact forces did on the structures over one of them (<= 0 up to round-off; null: none).
    jc["episodes"] = c->episodes();
    const bool any = c->episodes() > 0;
    jc["max_episode_net_work_J"] = any ? json(c->max_episode_net_work()) : json(nullptr);
    jc["max_episode_net_work_relative"] =
        any ? json(c->max_episode_net_work_relative()) : json(nullptr);
    if (const auto* rubber = dynamic_cast<const BumperLaw*>(c->length_law()))
      jc["bumper"] = bumper_json(job, e, *rubber);
    out.push_back(jc);
  }
  return out;
}

nlohmann::json unobstructed3d_json(const JobResult& job, const UnobstructedResult& free_run) {
  using nlohmann::json;
  const json with = summary3d_json(job);
  const json without = summary3d_json(free_run.job);
  const auto ratio = [](double x, double y) { return y > 0 ? x / y : 0.0; };
  const auto value = [](const json& peak) { return peak["value"].get<double>(); };
  json buildings = json::array();
  for (std::size_t b = 0; b < with.size() && b < without.size(); ++b) {
    json levels = json::array();
    for (std::size_t l = 0; l < with[b]["levels"].size(); ++l) {
      const json& lw = with[b]["levels"][l];
      const json& lo = without[b]["levels"][l];
      const auto corner = [&](const json& level) {
        double m = 0.0;
        for (const json& c : level["corners"])
          m = std::max(m, c["displacement"]["resultant"]["value"].get<double>());
        return m;
      };
      const double u_w = value(lw["centre_of_mass"]["displacement"]["resultant"]);
      const double u_o = value(lo["centre_of_mass"]["displacement"]["resultant"]);
      const double a_w = value(lw["centre_of_mass"]["absolute_acceleration"]["resultant"]);
      const double a_o = value(lo["centre_of_mass"]["absolute_acceleration"]["resultant"]);
      levels.push_back(
          {{"label", lw["label"]},
           {"unobstructed_displacement_m", u_o},
           {"displacement_amplification", ratio(u_w, u_o)},
           {"unobstructed_corner_displacement_m", corner(lo)},
           {"corner_displacement_amplification", ratio(corner(lw), corner(lo))},
           {"unobstructed_theta_rad", value(lo["theta"])},
           // A symmetric building does not twist without contacts (round-off only):
           // no ratio to a rotation below 1e-9 rad.
           {"theta_amplification", value(lo["theta"]) > 1e-9
                                       ? json(ratio(value(lw["theta"]), value(lo["theta"])))
                                       : json(nullptr)},
           {"unobstructed_absolute_acceleration_m_s2", a_o},
           {"acceleration_amplification", ratio(a_w, a_o)}});
    }
    json storeys = json::array();
    for (std::size_t s = 0; s < with[b]["storeys"].size(); ++s) {
      const double d_w = value(with[b]["storeys"][s]["envelope_over_columns"]["drift_ratio"]);
      const double d_o = value(without[b]["storeys"][s]["envelope_over_columns"]["drift_ratio"]);
      storeys.push_back({{"label", with[b]["storeys"][s]["label"]},
                         {"unobstructed_drift_ratio", d_o},
                         {"drift_ratio_amplification", ratio(d_w, d_o)}});
    }
    buildings.push_back({{"name", with[b]["name"]}, {"levels", levels}, {"storeys", storeys}});
  }
  json gaps = json::array();
  for (const ContactGap& c : free_run.gaps)
    gaps.push_back({{"label", c.label},
                    {"gap_m", c.gap},
                    {"critical_gap_m", c.critical_gap},
                    {"pounds_without_obstruction", c.critical_gap > c.gap}});
  return {{"note",
           "the same analysis without contact elements; amplification = peak with pounding / "
           "peak without (centre of mass resultant, largest corner resultant, rotation, centre "
           "of mass absolute acceleration, storey drift ratio enveloped over columns); "
           "critical_gap_m per moat wall = the largest distance any slab vertex moves past the "
           "wall face's rest position towards the wall (a smaller gap pounds under this record "
           "at this angle)"},
          {"buildings", buildings},
          {"walls", gaps}};
}

void print_unobstructed3d(std::ostream& out, const JobResult& job,
                          const UnobstructedResult& free_run) {
  const nlohmann::json j = unobstructed3d_json(job, free_run);
  char line[256];
  out << "Without contacts (amplification = with / without):\n";
  for (const auto& b : j["buildings"]) {
    for (const auto& l : b["levels"]) {
      const nlohmann::json& theta_amp = l["theta_amplification"];
      char theta[32] = "-";
      if (!theta_amp.is_null()) std::snprintf(theta, sizeof theta, "%.2f", theta_amp.get<double>());
      std::snprintf(
          line, sizeof line,
          "  %s/%-8s CM %7.2f cm (x%.2f)  corners %7.2f cm (x%.2f)  theta %.2e rad (x%s)  "
          "CM abs. acc. %.3f g (x%.2f)\n",
          b["name"].get<std::string>().c_str(), l["label"].get<std::string>().c_str(),
          100 * l["unobstructed_displacement_m"].get<double>(),
          l["displacement_amplification"].get<double>(),
          100 * l["unobstructed_corner_displacement_m"].get<double>(),
          l["corner_displacement_amplification"].get<double>(),
          l["unobstructed_theta_rad"].get<double>(), theta,
          l["unobstructed_absolute_acceleration_m_s2"].get<double>() / kGravity,
          l["acceleration_amplification"].get<double>());
      out << line;
    }
    for (const auto& s : b["storeys"]) {
      std::snprintf(line, sizeof line, "  %s/%-8s drift ratio %.3f %% (x%.2f)\n",
                    b["name"].get<std::string>().c_str(), s["label"].get<std::string>().c_str(),
                    100 * s["unobstructed_drift_ratio"].get<double>(),
                    s["drift_ratio_amplification"].get<double>());
      out << line;
    }
  }
  if (j["walls"].empty()) return;
  out << "Critical gap per moat wall (a gap below this pounds under this record and angle):\n";
  for (const auto& w : j["walls"]) {
    std::snprintf(line, sizeof line, "  %-34s gap %7.2f cm   critical gap %7.2f cm%s\n",
                  w["label"].get<std::string>().c_str(), 100 * w["gap_m"].get<double>(),
                  100 * w["critical_gap_m"].get<double>(),
                  w["pounds_without_obstruction"].get<bool>() ? "   (pounds)" : "");
    out << line;
  }
}

void print_contacts3d(std::ostream& out, const JobResult& job) {
  const nlohmann::json j = contacts3d_json(job);
  if (j.empty()) return;
  out << "Contacts (3D pounding)\n";
  char line[320];
  for (const auto& c : j) {
    if (c["impacts"].get<int>() == 0 && c["normal_force"]["value"].get<double>() == 0.0) {
      std::snprintf(line, sizeof line, "  %-34s no contact\n",
                    c["label"].get<std::string>().c_str());
      out << line;
      continue;
    }
    std::snprintf(
        line, sizeof line,
        "  %-34s %3d impacts, first at %.3f s, F_N %.4g kN, F_T %.4g kN, area %.3g m2, "
        "delta_N %.2f mm, v_imp %.3f m/s, stick %.3f s, slip %.3f s, friction %.4g kJ\n",
        c["label"].get<std::string>().c_str(), c["impacts"].get<int>(),
        c["first_impact_time_s"].is_null() ? -1.0 : c["first_impact_time_s"].get<double>(),
        c["normal_force"]["value"].get<double>() / 1e3,
        c["tangential_force"]["value"].get<double>() / 1e3, c["area"]["value"].get<double>(),
        1e3 * c["indentation"]["value"].get<double>(), c["impact_velocity"]["value"].get<double>(),
        c["time_in_stick_s"].get<double>(), c["time_in_slip_s"].get<double>(),
        c["friction_dissipated_J"].get<double>() / 1e3);
    out << line;
  }
}

void print_summary3d(std::ostream& out, const JobResult& job) {
  const nlohmann::json j = summary3d_json(job);
  char line[256];
  for (const auto& b : j) {
    out << "Building " << b["name"].get<std::string>() << " (3D)\n";
    for (const auto& l : b["levels"]) {
      const auto& cm = l["centre_of_mass"];
      double corner = 0.0;
      for (const auto& c : l["corners"])
        corner = std::max(corner, c["displacement"]["resultant"]["value"].get<double>());
      std::snprintf(line, sizeof line,
                    "  %-8s CM u %6.2f v %6.2f resultant %6.2f cm, corners %6.2f cm, theta %.2e "
                    "rad, CM abs. acc. %.3f g\n",
                    l["label"].get<std::string>().c_str(),
                    100 * cm["displacement"]["x"]["value"].get<double>(),
                    100 * cm["displacement"]["y"]["value"].get<double>(),
                    100 * cm["displacement"]["resultant"]["value"].get<double>(), 100 * corner,
                    l["theta"]["value"].get<double>(),
                    cm["absolute_acceleration"]["resultant"]["value"].get<double>() / kGravity);
      out << line;
    }
    for (const auto& s : b["storeys"]) {
      std::snprintf(line, sizeof line,
                    "  %-8s drift (envelope over columns) %6.3f cm, ratio %.3f %%",
                    s["label"].get<std::string>().c_str(),
                    100 * s["envelope_over_columns"]["resultant"]["value"].get<double>(),
                    100 * s["envelope_over_columns"]["drift_ratio"]["value"].get<double>());
      out << line;
      for (const auto& [name, c] : s["corner_columns"].items()) {
        std::snprintf(line, sizeof line, "  %s %.3f", name.c_str(),
                      100 * c["resultant"]["value"].get<double>());
        out << line;
      }
      out << '\n';
    }
    print_column_yield(out, b);
    double d = 0.0, f = 0.0;
    for (const auto& br : b["bearings"]) {
      if (br.contains("deformation")) d = std::max(d, br["deformation"]["value"].get<double>());
      if (br.contains("force")) f = std::max(f, br["force"]["value"].get<double>());
    }
    if (b["bearings"].empty()) continue;  // a fixed-base building
    const std::string on =
        b.contains("isolation_level")
            ? " (on floor " + std::to_string(b["isolation_level"].get<int>()) + ")"
            : std::string();
    std::snprintf(line, sizeof line,
                  "  bearings (%zu)%s: peak resultant deformation %.2f cm, force %.1f kN\n",
                  b["bearings"].size(), on.c_str(), 100 * d, f / 1e3);
    out << line;
    if (b.contains("base_shear")) {
      const auto& v = b["base_shear"];
      std::snprintf(line, sizeof line,
                    "  base shear x %.1f kN, y %.1f kN, resultant %.1f kN (bearings, damping and "
                    "base contacts)\n",
                    v["x"]["value"].get<double>() / 1e3, v["y"]["value"].get<double>() / 1e3,
                    v["resultant"]["value"].get<double>() / 1e3);
      out << line;
    }
  }
  print_contacts3d(out, job);
}

}  // namespace isopound

namespace isopound {

void print_modes3d(std::ostream& out, const ModelConfig& config) {
  char line[256];
  for (const Building3DConfig& b : config.structures3d) {
    const auto show = [&](const std::string& title, const LinearModel3D& m) {
      const Modes modes = compute_modes(m.stiffness, m.mass, m.influence.col(0));
      const Modes modes_y = compute_modes(m.stiffness, m.mass, m.influence.col(1));
      out << "Building " << b.name << ": " << title << "\n"
          << "  mode  period [s]  eff. mass x [%]  eff. mass y [%]  torsional [%]\n";
      for (int j = 0; j < modes.period.size(); ++j) {
        // Torsional share: the part of phi^T M phi = 1 on the rotation DOFs.
        const Eigen::VectorXd phi = modes.shape.col(j), mphi = m.mass * phi;
        double torsion = 0.0;
        for (int i = 0; i < phi.size(); ++i)
          if (m.dofs[i].kind == DofKind::kRotation) torsion += phi[i] * mphi[i];
        std::snprintf(line, sizeof line, "  %4d  %10.4f  %15.1f  %15.1f  %13.1f\n", j + 1,
                      modes.period[j], 100 * modes.effective_mass_ratio[j],
                      100 * modes_y.effective_mass_ratio[j], 100 * torsion);
        out << line;
      }
    };
    if (b.isolated && b.isolation_level > 0) {
      // Isolated above storey k: the superstructure fixed at the base slab, the substructure
      // fixed at the ground, and the whole building with its bearings between floor k and base.
      const std::string k = std::to_string(b.isolation_level);
      show("fixed-base superstructure (storeys " + std::to_string(b.isolation_level + 1) + ".." +
               std::to_string(b.storeys.size()) + ", fixed at the base slab)",
           linear_model3d(b, false, true));
      show("fixed-base substructure (" + (k == "1" ? "storey 1" : "storeys 1.." + k) + ")",
           linear_model3d(substructure3d(b), false, true));
    } else {
      show("fixed-base superstructure", linear_model3d(b, false, true));
    }
    if (b.isolated) {
      show("isolated, bearings at their post-yield stiffness", linear_model3d(b, false, false));
      show("isolated, bearings at their initial stiffness", linear_model3d(b, true, false));
    }
  }
}

}  // namespace isopound
