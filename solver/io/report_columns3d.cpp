// Yielding 3D columns in summary.json and on the console: column elements are labelled
// "<building>/story <k>/column <label>" (column_element.h), storey shears are the plan probes
// "<building>/storey shear/story <k>" (building3d.h), column drifts the probes
// "<building>/story <k>/<label>" with the storey height as length.
#include "solver/io/report_columns3d.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "solver/io/report.h"
#include "solver/structures/building3d.h"

namespace isopound {

namespace {

int output_index(const Element& e, const char* name) {
  for (int k = 0; k < e.output_count(); ++k)
    if (e.output_name(k) == name) return k;
  return -1;
}

// The resultant at the end of a plan probe, from its terms and the final displacements.
double final_resultant(const PlanProbe& p, const std::vector<double>& u) {
  const auto sum = [&](const std::vector<std::pair<int, double>>& terms) {
    double x = 0.0;
    for (const auto& [dof, c] : terms) x += c * u[dof];
    return x;
  };
  return std::hypot(sum(p.x_terms), sum(p.y_terms));
}

// A storey of a structure with struck_columns: its columns are hinged lines (yielding at M_y)
// or struck columns in their place, not the elastic storey the over-drift warning is about.
bool has_hinged_columns(const Model& model, const std::string& structure,
                        const std::string& storey) {
  const std::string hinged = structure + "/" + storey + "/hinged column ";
  const std::string struck = " on " + structure + " " + storey;
  for (const auto& e : model.elements)
    if (e->label().starts_with(hinged) || e->label().ends_with(struck)) return true;
  return false;
}

}  // namespace

void add_column_yield_json(const JobResult& job, const StructureInfo& s, nlohmann::json& jb) {
  using nlohmann::json;
  const Model& model = job.model;
  const AnalysisResult& r = job.analysis;
  const double limit = s.elastic_limit_drift_ratio;
  bool exceeded = false;
  double column_energy = 0.0;
  bool inelastic = false;
  for (const PlanProbe& p : model.probes)
    inelastic = inelastic || p.label.starts_with(s.name + "/" + kStoreyShearPart + "/");
  for (json& st : jb["storeys"]) {
    const std::string storey = st["label"];
    const std::string column_prefix = s.name + "/" + storey + "/column ";
    json columns = json::array();
    double peak_ductility = 0.0, energy = 0.0, first_yield = -1.0;
    int yielded = 0;
    for (std::size_t e = 0; e < model.elements.size(); ++e) {
      const Element& el = *model.elements[e];
      if (!el.label().starts_with(column_prefix)) continue;
      const std::vector<Peak>& pk = r.element_outputs[e];
      json jc = {{"label", el.label().substr(column_prefix.size())}};
      for (const char* name :
           {"shear", "drift", "ductility", "shear_x", "shear_y", "hysteretic_energy"}) {
        const int k = output_index(el, name);
        jc[name] = peak_json(pk[k], el.output_unit(k));
      }
      const Peak& y = pk[output_index(el, "yielded")];
      jc["first_yield_time_s"] = y.value > 0 ? json(y.time) : json(nullptr);
      if (y.value > 0) {
        ++yielded;
        if (first_yield < 0 || y.time < first_yield) first_yield = y.time;
      }
      peak_ductility = std::max(peak_ductility, pk[output_index(el, "ductility")].value);
      energy += el.output(output_index(el, "hysteretic_energy"));  // at the end
      columns.push_back(jc);
    }
    column_energy += energy;
    if (inelastic) {
      for (std::size_t p = 0; p < model.probes.size(); ++p)
        if (model.probes[p].label == s.name + "/" + kStoreyShearPart + "/" + storey)
          st["shear"] = {{"x", peak_json(r.probes[p].x, "N")},
                         {"y", peak_json(r.probes[p].y, "N")},
                         {"resultant", peak_json(r.probes[p].resultant, "N")}};
      double residual = 0.0;
      for (const PlanProbe& p : model.probes)
        if (p.label.starts_with(s.name + "/" + storey + "/") && p.length > 0)
          residual = std::max(residual, final_resultant(p, r.final_displacement) / p.length);
      st["residual_drift_ratio"] = residual;
    }
    if (!columns.empty()) {
      st["yielding"] = {
          {"columns", columns},
          {"column_count", columns.size()},
          {"yielded_columns", yielded},
          {"peak_ductility", peak_ductility},
          {"first_yield_time_s", first_yield >= 0 ? json(first_yield) : json(nullptr)},
          {"hysteretic_energy_J", energy}};
    } else if (!has_hinged_columns(model, s.name, storey) &&
               st["envelope_over_columns"]["drift_ratio"]["value"].get<double>() > limit) {
      st["elastic_limit_exceeded"] = true;
      exceeded = true;
    }
  }
  if (inelastic) jb["column_hysteretic_energy_J"] = column_energy;
  jb["elastic_limit_drift_ratio"] = limit;
  jb["elastic_limit_exceeded"] = exceeded;
}

void print_column_yield(std::ostream& out, const nlohmann::json& b) {
  char line[320];
  std::string over;
  for (const auto& st : b["storeys"]) {
    const std::string label = st["label"];
    if (st.contains("elastic_limit_exceeded")) {
      std::snprintf(line, sizeof line, "%s%s %.2f %%", over.empty() ? "" : ", ", label.c_str(),
                    100 * st["envelope_over_columns"]["drift_ratio"]["value"].get<double>());
      over += line;
    }
    if (!st.contains("yielding")) continue;
    const auto& y = st["yielding"];
    const std::string first =
        y["first_yield_time_s"].is_null()
            ? std::string("none")
            : std::to_string(y["first_yield_time_s"].get<double>()).substr(0, 6) + " s";
    std::snprintf(line, sizeof line,
                  "  %-8s yielding columns: %d of %d yielded (first at %s), peak ductility %.2f, "
                  "residual drift ratio %.3f %%, shear x %.0f y %.0f resultant %.0f kN, "
                  "hysteretic energy %.1f kJ\n",
                  label.c_str(), y["yielded_columns"].get<int>(), y["column_count"].get<int>(),
                  first.c_str(), y["peak_ductility"].get<double>(),
                  100 * st["residual_drift_ratio"].get<double>(),
                  st["shear"]["x"]["value"].get<double>() / 1e3,
                  st["shear"]["y"]["value"].get<double>() / 1e3,
                  st["shear"]["resultant"]["value"].get<double>() / 1e3,
                  y["hysteretic_energy_J"].get<double>() / 1e3);
    out << line;
  }
  if (!over.empty()) {
    std::snprintf(line, sizeof line,
                  "  warning: elastic storeys beyond elastic_limit_drift_ratio %.2f %% (%s): the "
                  "elastic model is outside its range; model the columns as yielding "
                  "(columns: {hysteresis: ...})\n",
                  100 * b["elastic_limit_drift_ratio"].get<double>(), over.c_str());
    out << line;
  }
}

}  // namespace isopound
