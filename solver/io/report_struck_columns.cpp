// Struck-column damage measures from the element's peaks (StruckColumn outputs, by name).
#include "solver/io/report_struck_columns.h"

#include <algorithm>
#include <cstdio>
#include <optional>
#include <string>

#include "solver/elements/struck_column.h"
#include "solver/elements/struck_column3d.h"
#include "solver/io/report.h"

namespace isopound {

namespace {

// The peak of output `name` of element e.
const Peak& peak_of(const Element& el, const AnalysisResult& r, std::size_t e,
                    const std::string& name) {
  for (int k = 0; k < el.output_count(); ++k)
    if (el.output_name(k) == name) return r.element_outputs[e][static_cast<std::size_t>(k)];
  static const Peak kNone;
  return kNone;
}

// A 3D struck column (StruckColumn3D): per principal axis its hinges; the resultant shear.
nlohmann::json struck_column3d_json(const StruckColumn3D& c, const AnalysisResult& r,
                                    std::size_t e) {
  using nlohmann::json;
  const StruckColumn3DSpec& s = c.spec();
  const Peak& failed = peak_of(c, r, e, "shear_failed");
  const HingedColumnSection& s1 = s.axis[0];
  json j = {
      {"label", c.label()},
      {"height_m", s1.length},
      {"struck_at_m", s1.node},
      {"position_m", {s.p_W.x, s.p_W.y}},
      {"orientation_deg", s.orientation * 180.0 / 3.14159265358979323846},
      {"contact_force", peak_json(peak_of(c, r, e, "normal_force"), "N")},
      {"impacts", peak_of(c, r, e, "impacts").value},
      // Passivity of the whole element per episode (StruckColumn3D::episodes: the contact's
      // own measure takes the node's rate behind the dashpot, not the physical work).
      {"episodes", c.episodes()},
      {"max_episode_net_work_J", c.episodes() > 0 ? json(c.max_episode_net_work()) : json(nullptr)},
      {"shear", peak_json(peak_of(c, r, e, "column_shear"), "N")},
      {"local_drift_x", peak_json(peak_of(c, r, e, "local_drift_x"), "m")},
      {"local_drift_y", peak_json(peak_of(c, r, e, "local_drift_y"), "m")},
      {"hinge_dissipated_J", c.hinge_dissipated_energy()}};
  if (s.shear_capacity > 0) {
    j["V_n_N"] = s.shear_capacity;
    j["shear_ratio"] = peak_of(c, r, e, "column_shear").value / s.shear_capacity;
    j["shear_failed"] = failed.value > 0.5;
    j["shear_failure_time_s"] = failed.value > 0.5 ? json(failed.time) : json(nullptr);
  }
  for (int i = 0; i < 2; ++i) {
    const HingedColumnSection& a = s.axis[static_cast<std::size_t>(i)];
    const std::string axis = "axis_" + std::to_string(i + 1);
    j["axes"][axis] = {{"I_m4", a.I},
                       {"yield_moment_Nm", a.yield_moment},
                       {"local_stiffness_N_per_m", HingedColumn(a).local_stiffness()}};
    for (const char* hinge : {"bottom", "node", "top"}) {
      const std::string tail = std::to_string(i + 1) + "_" + hinge;
      const Peak& m = peak_of(c, r, e, "moment_" + tail);
      j["axes"][axis]["hinges"][hinge] = {
          {"moment", peak_json(m, "N m")},
          {"moment_ratio", m.value / a.yield_moment},
          {"ductility", peak_of(c, r, e, "ductility_" + tail).value}};
    }
  }
  return j;
}

}  // namespace

nlohmann::json struck_columns_json(const Model& model, const AnalysisResult& r) {
  using nlohmann::json;
  json list = json::array();
  for (std::size_t e = 0; e < model.elements.size(); ++e) {
    if (const auto* c3 = dynamic_cast<const StruckColumn3D*>(model.elements[e].get()))
      list.push_back(struck_column3d_json(*c3, r, e));
    const auto* c = dynamic_cast<const StruckColumn*>(model.elements[e].get());
    if (!c) continue;
    const StruckColumnSpec& s = c->spec();
    const Peak& failed = peak_of(*c, r, e, "shear_failed");
    json j = {{"label", c->label()},
              {"count", s.count},
              {"height_m", s.column.length},
              {"struck_at_m", s.column.node},
              {"local_stiffness_N_per_m", s.count * c->column().local_stiffness()},
              {"contact_force", peak_json(peak_of(*c, r, e, "force"), "N")},
              {"impacts", peak_of(*c, r, e, "impacts").value},
              {"shear", peak_json(peak_of(*c, r, e, "column_shear"), "N")},
              {"local_drift", peak_json(peak_of(*c, r, e, "local_drift"), "m")},
              {"yield_moment_Nm", s.column.yield_moment},
              {"hinge_dissipated_J", c->hinge_dissipated_energy()}};
    if (s.shear_capacity > 0) {
      j["V_n_N"] = s.shear_capacity;
      j["shear_ratio"] = peak_of(*c, r, e, "column_shear").value / s.shear_capacity;
      j["shear_failed"] = failed.value > 0.5;
      j["shear_failure_time_s"] = failed.value > 0.5 ? json(failed.time) : json(nullptr);
    }
    for (const char* hinge : {"bottom", "node", "top"}) {
      const Peak& m = peak_of(*c, r, e, std::string("moment_") + hinge);
      j["hinges"][hinge] = {
          {"moment", peak_json(m, "N m")},
          {"moment_ratio", m.value / s.column.yield_moment},
          {"ductility", peak_of(*c, r, e, std::string("ductility_") + hinge).value}};
    }
    list.push_back(j);
  }
  return list;
}

void print_struck_columns(std::ostream& out, const Model& model, const AnalysisResult& r) {
  char line[320];
  for (std::size_t e = 0; e < model.elements.size(); ++e) {
    if (const auto* c3 = dynamic_cast<const StruckColumn3D*>(model.elements[e].get())) {
      const StruckColumn3DSpec& s = c3->spec();
      const Peak& shear = peak_of(*c3, r, e, "column_shear");
      const Peak& failed = peak_of(*c3, r, e, "shear_failed");
      std::snprintf(line, sizeof line,
                    "  %s, struck %.2f m above the floor: contact %.1f kN, %g impacts, shear "
                    "%.1f kN",
                    c3->label().c_str(), s.axis[0].node,
                    peak_of(*c3, r, e, "normal_force").value / 1e3,
                    peak_of(*c3, r, e, "impacts").value, shear.value / 1e3);
      out << line;
      if (s.shear_capacity > 0) {
        std::snprintf(line, sizeof line, " (%.0f %% of V_n%s", 100 * shear.value / s.shear_capacity,
                      failed.value > 0.5 ? ", SHEAR FAILURE" : ")");
        out << line;
        if (failed.value > 0.5) {
          std::snprintf(line, sizeof line, " at %.3f s)", failed.time);
          out << line;
        }
      }
      double ratio = 0.0, ductility = 1.0;
      for (int i = 0; i < 2; ++i)
        for (const char* hinge : {"bottom", "node", "top"}) {
          const std::string tail = std::to_string(i + 1) + "_" + hinge;
          ratio = std::max(ratio, peak_of(*c3, r, e, "moment_" + tail).value /
                                      s.axis[static_cast<std::size_t>(i)].yield_moment);
          ductility = std::max(ductility, peak_of(*c3, r, e, "ductility_" + tail).value);
        }
      std::snprintf(line, sizeof line,
                    "\n    largest moment / M_y %.2f, hinge ductility %.2f; local drift %.2f, "
                    "%.2f mm (x, y)\n",
                    ratio, ductility, 1e3 * peak_of(*c3, r, e, "local_drift_x").value,
                    1e3 * peak_of(*c3, r, e, "local_drift_y").value);
      out << line;
      continue;
    }
    const auto* c = dynamic_cast<const StruckColumn*>(model.elements[e].get());
    if (!c) continue;
    const StruckColumnSpec& s = c->spec();
    const Peak& shear = peak_of(*c, r, e, "column_shear");
    std::snprintf(line, sizeof line,
                  "  %s: %d columns struck %.2f m above the floor: contact %.1f kN, shear %.1f kN",
                  c->label().c_str(), s.count, s.column.node,
                  peak_of(*c, r, e, "force").value / 1e3, shear.value / 1e3);
    out << line;
    if (s.shear_capacity > 0) {
      const Peak& failed = peak_of(*c, r, e, "shear_failed");
      std::snprintf(line, sizeof line, " (%.0f %% of V_n%s", 100 * shear.value / s.shear_capacity,
                    failed.value > 0.5 ? ", SHEAR FAILURE" : ")");
      out << line;
      if (failed.value > 0.5) {
        std::snprintf(line, sizeof line, " at %.3f s)", failed.time);
        out << line;
      }
    }
    std::snprintf(
        line, sizeof line,
        "\n    moments / M_y: bottom %.2f, node %.2f, top %.2f; ductility %.2f, %.2f, "
        "%.2f; local drift %.2f mm\n",
        peak_of(*c, r, e, "moment_bottom").value / s.column.yield_moment,
        peak_of(*c, r, e, "moment_node").value / s.column.yield_moment,
        peak_of(*c, r, e, "moment_top").value / s.column.yield_moment,
        peak_of(*c, r, e, "ductility_bottom").value, peak_of(*c, r, e, "ductility_node").value,
        peak_of(*c, r, e, "ductility_top").value, 1e3 * peak_of(*c, r, e, "local_drift").value);
    out << line;
  }
}

std::optional<double> struck_column_energy(const Model& model) {
  std::optional<double> sum;
  for (const auto& el : model.elements) {
    if (const auto* c = dynamic_cast<const StruckColumn*>(el.get()))
      sum = sum.value_or(0.0) + c->hinge_dissipated_energy();
    if (const auto* c = dynamic_cast<const StruckColumn3D*>(el.get()))
      sum = sum.value_or(0.0) + c->hinge_dissipated_energy();
  }
  return sum;
}

}  // namespace isopound
