// Damage measures of 2D storeys in summary.json and on the console (definitions in the header).
#include "solver/io/report_damage2d.h"

#include <cstdio>

#include "solver/elements/story_link.h"

namespace isopound {

namespace {
constexpr int kYieldedOutput = 4;  // StoryLink outputs

double residual_drift(const AnalysisResult& r, std::size_t story_index) {
  const Story& st = r.stories[story_index];
  return r.final_displacement[st.upper] - (st.lower >= 0 ? r.final_displacement[st.lower] : 0.0);
}

bool beyond_elastic_limit(const AnalysisResult& r, const StructureInfo& s,
                          std::size_t story_index) {
  return s.elastic_limit_drift_ratio > 0 &&
         r.drift_ratio[story_index].value > s.elastic_limit_drift_ratio;
}

int element_index(const Model& model, const StoryLink* link) {
  for (std::size_t e = 0; e < model.elements.size(); ++e)
    if (model.elements[e].get() == link) return static_cast<int>(e);
  return -1;
}
}  // namespace

const StoryLink* story_link(const Model& model, const StructureInfo& s, std::size_t k) {
  if (k >= s.story_elements.size() || s.story_elements[k] < 0) return nullptr;
  return dynamic_cast<const StoryLink*>(model.elements[s.story_elements[k]].get());
}

void add_story_damage_json(nlohmann::json& story, const Model& model, const AnalysisResult& r,
                           const StructureInfo& s, std::size_t k, std::size_t story_index) {
  const StoryLink* link = story_link(model, s, k);
  const double height = r.stories[story_index].height;
  if (!link) {
    if (beyond_elastic_limit(r, s, story_index)) {
      story["elastic_limit_exceeded"] = true;
      story["elastic_limit_drift_ratio"] = s.elastic_limit_drift_ratio;
    }
    return;
  }
  const int e = element_index(model, link);
  const Peak& yielded = r.element_outputs[e][kYieldedOutput];
  const double residual = residual_drift(r, story_index);
  story["yield_drift_m"] = link->yield_drift();
  story["yield_drift_ratio"] = link->yield_drift() / height;
  story["ductility"] = r.drift[story_index].value / link->yield_drift();
  story["residual_drift_m"] = residual;
  story["residual_drift_ratio"] = residual / height;
  story["hysteretic_energy_J"] = link->hysteretic_energy();
  story["yielded"] = yielded.value > 0.5;
  story["first_yield_time_s"] =
      yielded.value > 0.5 ? nlohmann::json(yielded.time) : nlohmann::json(nullptr);
}

void print_story_damage(std::ostream& out, const Model& model, const AnalysisResult& r,
                        const StructureInfo& s, std::size_t k, std::size_t story_index) {
  char line[256];
  const StoryLink* link = story_link(model, s, k);
  const Story& st = r.stories[story_index];
  if (!link) {
    if (!beyond_elastic_limit(r, s, story_index)) return;
    std::snprintf(line, sizeof line,
                  "  warning: %s is elastic but its peak drift ratio %.3f %% exceeds %.3g %% "
                  "(elastic_limit_drift_ratio): outside the elastic model's range; model the "
                  "storeys as yielding (floors: hysteresis)\n",
                  st.label.c_str(), 100 * r.drift_ratio[story_index].value,
                  100 * s.elastic_limit_drift_ratio);
    out << line;
    return;
  }
  const int e = element_index(model, link);
  const Peak& yielded = r.element_outputs[e][kYieldedOutput];
  const double residual = residual_drift(r, story_index);
  if (yielded.value > 0.5) {
    std::snprintf(line, sizeof line,
                  "  %-22s ductility %6.2f   residual drift %.3f %%   hysteretic %.4g kJ   "
                  "first yield at %.3f s\n",
                  "", r.drift[story_index].value / link->yield_drift(), 100 * residual / st.height,
                  link->hysteretic_energy() / 1e3, yielded.time);
  } else {
    std::snprintf(line, sizeof line, "  %-22s ductility %6.2f   (did not yield)\n", "",
                  r.drift[story_index].value / link->yield_drift());
  }
  out << line;
}

double story_hysteretic_energy(const Model& model) {
  double sum = 0.0;
  for (const auto& el : model.elements)
    if (const auto* link = dynamic_cast<const StoryLink*>(el.get()))
      sum += link->hysteretic_energy();
  return sum;
}

bool has_yielding_stories(const Model& model) {
  for (const auto& el : model.elements)
    if (dynamic_cast<const StoryLink*>(el.get())) return true;
  return false;
}

}  // namespace isopound
