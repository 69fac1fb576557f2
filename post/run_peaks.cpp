// Peaks of summary.json (see run_peaks.h). Keys: solver/io/report.cpp (2D: structures[].levels,
// stories, elements; peak shape {value, time_s, ...}) and solver/io/report3d.cpp (buildings_3d[],
// contacts_3d[]).
#include "post/run_peaks.h"

#include <algorithm>
#include <vector>

namespace isopound::post {
namespace {

using nlohmann::json;

// A peak object {value, time_s, ...} at j[key], or nothing.
std::optional<ReportedPeak> peak_at(const json& j, const std::string& key, std::string where) {
  if (!j.is_object() || !j.contains(key) || !j.at(key).is_object()) return std::nullopt;
  const json& p = j.at(key);
  if (!p.contains("value") || !p.at("value").is_number()) return std::nullopt;
  ReportedPeak r;
  r.value = p.at("value").get<double>();
  r.signed_value = r.value;
  if (p.contains("negative") && p.at("negative").is_number() &&
      -p.at("negative").get<double>() >= r.value)
    r.signed_value = -r.value;
  if (p.contains("time_s") && p.at("time_s").is_number()) r.time = p.at("time_s").get<double>();
  r.key = std::move(where) + "." + key;
  return r;
}

const json* array_at(const json& j, const char* key) {
  if (!j.is_object() || !j.contains(key) || !j.at(key).is_array()) return nullptr;
  return &j.at(key);
}

// The element of array j[key] whose "label" is `label`, and its index.
const json* labelled(const json& j, const char* key, const std::string& label, std::size_t& index) {
  const json* a = array_at(j, key);
  if (!a) return nullptr;
  for (index = 0; index < a->size(); ++index) {
    const json& e = (*a)[index];
    if (e.is_object() && e.contains("label") && e.at("label").is_string() &&
        e.at("label").get<std::string>() == label)
      return &e;
  }
  return nullptr;
}

// 3D: building `name` of buildings_3d and its index.
const json* building(const RunData& run, const std::string& name, std::size_t& index) {
  const json* a = array_at(run.summary, "buildings_3d");
  if (!a) return nullptr;
  for (index = 0; index < a->size(); ++index)
    if ((*a)[index].value("name", "") == name) return &(*a)[index];
  return nullptr;
}

std::string at_index(const std::string& key, std::size_t i) {
  return key + "[" + std::to_string(i) + "]";
}

}  // namespace

double history_interval(const RunData& run) {
  if (run.rows() < 2) return 0.0;
  const std::vector<double>& t = run.time();
  std::vector<double> dt;
  for (std::size_t i = 1; i < t.size(); ++i) dt.push_back(t[i] - t[i - 1]);
  std::nth_element(dt.begin(), dt.begin() + dt.size() / 2, dt.end());
  return dt[dt.size() / 2];
}

std::optional<ReportedPeak> reported_level_peak(const RunData& run, const std::string& level,
                                                const std::string& quantity,
                                                const std::string& component) {
  const auto slash = level.find('/');
  if (run.three_d) {
    std::size_t b = 0, l = 0;
    const json* jb = building(run, level.substr(0, slash), b);
    if (!jb || slash == std::string::npos) return std::nullopt;
    const json* jl = labelled(*jb, "levels", level.substr(slash + 1), l);
    if (!jl || !jl->contains("centre_of_mass")) return std::nullopt;
    const std::string where =
        at_index("buildings_3d", b) + at_index(".levels", l) + ".centre_of_mass." + quantity;
    const json& cm = jl->at("centre_of_mass");
    if (!cm.contains(quantity)) return std::nullopt;
    return peak_at(cm.at(quantity), component, where);
  }
  const json* structures = array_at(run.summary, "structures");
  if (!structures) return std::nullopt;
  for (std::size_t s = 0; s < structures->size(); ++s) {
    std::size_t l = 0;
    if (const json* jl = labelled((*structures)[s], "levels", level, l))
      return peak_at(*jl, quantity, at_index("structures", s) + at_index(".levels", l));
  }
  return std::nullopt;
}

std::optional<ReportedPeak> reported_drift_ratio_peak(const RunData& run,
                                                      const std::string& structure, int story) {
  if (run.three_d) {
    std::size_t b = 0, k = 0;
    const json* jb = building(run, structure, b);
    if (!jb) return std::nullopt;
    const json* js = labelled(*jb, "storeys", "story " + std::to_string(story), k);
    if (!js || !js->contains("corner_columns") || !js->at("corner_columns").is_object())
      return std::nullopt;
    std::optional<ReportedPeak> best;
    for (const auto& [label, column] : js->at("corner_columns").items()) {
      const auto p = peak_at(
          column, "drift_ratio",
          at_index("buildings_3d", b) + at_index(".storeys", k) + ".corner_columns." + label);
      if (p && (!best || p->value > best->value)) best = p;
    }
    return best;
  }
  const json* structures = array_at(run.summary, "structures");
  if (!structures) return std::nullopt;
  for (std::size_t s = 0; s < structures->size(); ++s) {
    std::size_t k = 0;
    if (const json* js =
            labelled((*structures)[s], "stories", structure + "/story " + std::to_string(story), k))
      return peak_at(*js, "drift_ratio", at_index("structures", s) + at_index(".stories", k));
  }
  return std::nullopt;
}

std::optional<ReportedPeak> reported_element_peak(const RunData& run, const std::string& label,
                                                  const std::string& output) {
  std::size_t e = 0;
  if (run.three_d) {
    const json* jc = labelled(run.summary, "contacts_3d", label, e);
    return jc ? peak_at(*jc, output, at_index("contacts_3d", e)) : std::nullopt;
  }
  const json* je = labelled(run.summary, "elements", label, e);
  return je ? peak_at(*je, "peak_" + output, at_index("elements", e)) : std::nullopt;
}

std::optional<ReportedPeak> reported_ground_peak(const RunData& run, const std::string& key) {
  const json& s = run.summary;
  if (!s.is_object() || !s.contains("ground_motion") || !s.at("ground_motion").contains(key) ||
      !s.at("ground_motion").at(key).is_number())
    return std::nullopt;
  const double v = s.at("ground_motion").at(key).get<double>();
  return ReportedPeak{v, v, std::nullopt, "ground_motion." + key};
}

}  // namespace isopound::post
