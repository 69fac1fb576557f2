// Struck-column damage measures from the element's peaks (StruckColumn outputs, by name).
#include "solver/io/report_struck_columns.h"

#include <cstdio>
#include <optional>
#include <string>

#include "solver/elements/struck_column.h"
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

}  // namespace

nlohmann::json struck_columns_json(const Model& model, const AnalysisResult& r) {
  using nlohmann::json;
  json list = json::array();
  for (std::size_t e = 0; e < model.elements.size(); ++e) {
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
  for (const auto& el : model.elements)
    if (const auto* c = dynamic_cast<const StruckColumn*>(el.get()))
      sum = sum.value_or(0.0) + c->hinge_dissipated_energy();
  return sum;
}

}  // namespace isopound
