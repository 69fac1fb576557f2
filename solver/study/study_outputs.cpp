// Peak selectors of a study (grammar in study_outputs.h): parse once, resolve per model (DOF,
// story and element indices), evaluate per run as the max (or sum) of the selected peaks.
#include "solver/study/study_outputs.h"

#include <fnmatch.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <stdexcept>

namespace isopound {
namespace {

constexpr std::string_view kLevelQuantities[] = {"displacement", "velocity",
                                                 "absolute_acceleration", "residual_displacement"};
constexpr std::string_view kStoryQuantities[] = {"drift", "drift_ratio", "shear"};
constexpr std::string_view kEnergyTerms[] = {"input",          "kinetic",           "elastic",
                                             "viscous",        "hysteretic",        "error",
                                             "relative_error", "max_relative_error"};
constexpr std::string_view kGroundPeaks[] = {"pga", "pgv", "pgd"};

template <std::size_t N>
int index_in(const std::string_view (&names)[N], std::string_view name) {
  for (std::size_t i = 0; i < N; ++i)
    if (names[i] == name) return static_cast<int>(i);
  return -1;
}

template <std::size_t N>
std::string joined(const std::string_view (&names)[N]) {
  std::string out;
  for (const auto& name : names) out += (out.empty() ? "" : ", ") + std::string(name);
  return out;
}

// "floor12" with prefix "floor" -> 12; -1 if `where` is not prefix + a number >= 1.
int numbered(std::string_view where, std::string_view prefix) {
  if (!where.starts_with(prefix) || where.size() == prefix.size()) return -1;
  int n = -1;
  const auto [ptr, ec] =
      std::from_chars(where.data() + prefix.size(), where.data() + where.size(), n);
  if (ec != std::errc() || ptr != where.data() + where.size() || n < 1) return -1;
  return n;
}

bool is_level_place(std::string_view w) {
  return w == "base" || w == "roof" || w == "floors" || w == "levels" || numbered(w, "floor") > 0;
}
bool is_story_place(std::string_view w) {
  return w == "stories" || numbered(w, "story") > 0;
}

bool matches(const std::string& pattern, const std::string& label) {
  const std::size_t slash = label.find_last_of('/');
  const std::string short_label = slash == std::string::npos ? label : label.substr(slash + 1);
  return fnmatch(pattern.c_str(), short_label.c_str(), 0) == 0 ||
         fnmatch(pattern.c_str(), label.c_str(), 0) == 0;
}

}  // namespace

OutputSelector parse_output_selector(std::string_view text) {
  OutputSelector s;
  s.text = std::string(text);
  const auto fail = [&](const std::string& what) -> void {
    throw std::invalid_argument("peak '" + std::string(text) + "': " + what);
  };
  std::string_view rest = text;
  if (rest.starts_with("sum:")) {
    s.sum = true;
    rest.remove_prefix(4);
  } else if (rest.starts_with("max:")) {
    rest.remove_prefix(4);
  }
  const std::size_t dot = rest.find_last_of('.');
  if (dot == std::string_view::npos || dot == 0 || dot + 1 == rest.size())
    fail(
        "expected <where>.<quantity>, e.g. base.displacement, stories.drift_ratio, isolator.force");
  s.where = std::string(rest.substr(0, dot));
  s.quantity = std::string(rest.substr(dot + 1));
  if (s.where == "energy") {
    s.kind = OutputSelector::Kind::kEnergy;
    if (index_in(kEnergyTerms, s.quantity) < 0) fail("energy terms are " + joined(kEnergyTerms));
  } else if (s.where == "ground") {
    s.kind = OutputSelector::Kind::kGround;
    if (index_in(kGroundPeaks, s.quantity) < 0) fail("ground peaks are " + joined(kGroundPeaks));
  } else if (is_level_place(s.where)) {
    s.kind = OutputSelector::Kind::kLevel;
    if (index_in(kLevelQuantities, s.quantity) < 0)
      fail("peaks of a level are " + joined(kLevelQuantities) +
           (index_in(kStoryQuantities, s.quantity) >= 0
                ? " (drifts belong to stories: story<N> or stories)"
                : ""));
  } else if (is_story_place(s.where)) {
    s.kind = OutputSelector::Kind::kStory;
    if (index_in(kStoryQuantities, s.quantity) < 0)
      fail("peaks of a story are " + joined(kStoryQuantities));
  } else {
    s.kind = OutputSelector::Kind::kElement;
  }
  if (s.sum && s.kind != OutputSelector::Kind::kElement) fail("'sum:' applies to elements only");
  return s;
}

std::string output_unit(const OutputSelector& s) {
  static const std::pair<std::string_view, const char*> kUnits[] = {
      {"displacement", "m"},
      {"velocity", "m/s"},
      {"absolute_acceleration", "m/s2"},
      {"residual_displacement", "m"},
      {"drift", "m"},
      {"drift_ratio", "-"},
      {"shear", "N"},
      {"pga", "m/s2"},
      {"pgv", "m/s"},
      {"pgd", "m"},
      {"force", "N"},
      {"deformation", "m"},
      {"z", "-"},
      {"penetration", "m"},
      {"impacts", "-"},
      {"impact_velocity", "m/s"},
      {"indentation", "m"},
      {"dissipated_energy", "J"}};
  if (s.kind == OutputSelector::Kind::kEnergy)
    return s.quantity == "relative_error" || s.quantity == "max_relative_error" ? "-" : "J";
  for (const auto& [name, unit] : kUnits)
    if (name == s.quantity) return unit;
  return "SI";
}

ResolvedOutput resolve_output(const OutputSelector& s, const Model& model) {
  ResolvedOutput r;
  r.kind = s.kind;
  r.sum = s.sum;
  const auto fail = [&](const std::string& what) -> void {
    throw std::invalid_argument("peak '" + s.text + "': " + what);
  };
  switch (s.kind) {
    case OutputSelector::Kind::kEnergy:
      r.quantity = index_in(kEnergyTerms, s.quantity);
      return r;
    case OutputSelector::Kind::kGround:
      r.quantity = index_in(kGroundPeaks, s.quantity);
      return r;
    case OutputSelector::Kind::kLevel: {
      r.quantity = index_in(kLevelQuantities, s.quantity);
      if (model.structures.empty()) fail("the model has no building");
      const StructureInfo& b = model.structures.front();
      const int first_floor = b.has_base ? 1 : 0;
      const int levels = static_cast<int>(b.level_dofs.size());
      if (s.where == "base") {
        if (!b.has_base) fail("the building has a fixed base (no base slab)");
        r.indices = {b.level_dofs[0]};
      } else if (s.where == "roof") {
        r.indices = {b.level_dofs.back()};
      } else if (s.where == "floors" || s.where == "levels") {
        const int from = s.where == "floors" ? first_floor : 0;
        r.indices.assign(b.level_dofs.begin() + from, b.level_dofs.end());
      } else {
        const int floor = numbered(s.where, "floor");
        if (first_floor + floor - 1 >= levels)
          fail("the building has " + std::to_string(levels - first_floor) + " floors");
        r.indices = {b.level_dofs[first_floor + floor - 1]};
      }
      return r;
    }
    case OutputSelector::Kind::kStory: {
      r.quantity = index_in(kStoryQuantities, s.quantity);
      if (model.structures.empty()) fail("the model has no building");
      const StructureInfo& b = model.structures.front();  // its stories come first (stories_of)
      const int count = static_cast<int>(b.level_dofs.size()) - (b.has_base ? 1 : 0);
      if (s.where == "stories") {
        for (int k = 0; k < count; ++k) r.indices.push_back(k);
      } else {
        const int story = numbered(s.where, "story");
        if (story > count) fail("the building has " + std::to_string(count) + " stories");
        r.indices = {story - 1};
      }
      return r;
    }
    case OutputSelector::Kind::kElement: {
      std::vector<std::string> seen_outputs;
      for (std::size_t e = 0; e < model.elements.size(); ++e) {
        const Element& element = *model.elements[e];
        if (!matches(s.where, element.label())) continue;
        int found = -1;
        for (int k = 0; k < element.output_count(); ++k) {
          if (element.output_name(k) == s.quantity) found = k;
          seen_outputs.push_back(element.output_name(k));
        }
        if (found < 0) continue;
        r.indices.push_back(static_cast<int>(e));
        r.element_outputs.push_back(found);
      }
      if (r.indices.empty()) {
        std::string labels;
        for (const auto& element : model.elements)
          labels += (labels.empty() ? "" : ", ") + element->label();
        if (seen_outputs.empty())
          fail("no element matches '" + s.where +
               "' (elements: " + (labels.empty() ? "none" : labels) +
               "; or use base, roof, floor<N>, floors, levels, story<N>, stories, energy, ground)");
        std::sort(seen_outputs.begin(), seen_outputs.end());
        seen_outputs.erase(std::unique(seen_outputs.begin(), seen_outputs.end()),
                           seen_outputs.end());
        std::string names;
        for (const auto& name : seen_outputs) names += (names.empty() ? "" : ", ") + name;
        fail("elements matching '" + s.where + "' have no output '" + s.quantity +
             "' (they have: " + names + ")");
      }
      return r;
    }
  }
  return r;
}

double evaluate_output(const ResolvedOutput& r, const AnalysisResult& result,
                       const GroundMotionPeaks& ground) {
  switch (r.kind) {
    case OutputSelector::Kind::kEnergy: {
      const EnergyBalance& e = result.energy;
      const double terms[] = {e.input,      e.kinetic, e.elastic,        e.viscous,
                              e.hysteretic, e.error,   e.relative_error, e.max_relative_error};
      return terms[r.quantity];
    }
    case OutputSelector::Kind::kGround: {
      const double peaks[] = {ground.pga, ground.pgv, ground.pgd};
      return peaks[r.quantity];
    }
    case OutputSelector::Kind::kLevel:
    case OutputSelector::Kind::kStory: {
      double value = 0.0;
      if (r.kind == OutputSelector::Kind::kLevel && r.quantity == 3) {  // |u| at the end
        for (const int i : r.indices)
          value = std::max(value, std::abs(result.final_displacement[i]));
        return value;
      }
      const std::vector<Peak>* families[] = {&result.displacement, &result.velocity,
                                             &result.absolute_acceleration};
      const std::vector<Peak>* stories[] = {&result.drift, &result.drift_ratio,
                                            &result.story_shear};
      const std::vector<Peak>& peaks =
          r.kind == OutputSelector::Kind::kLevel ? *families[r.quantity] : *stories[r.quantity];
      for (const int i : r.indices) value = std::max(value, peaks[i].value);
      return value;
    }
    case OutputSelector::Kind::kElement: {
      double value = r.sum ? 0.0 : -1e300;
      for (std::size_t j = 0; j < r.indices.size(); ++j) {
        const double peak = result.element_outputs[r.indices[j]][r.element_outputs[j]].value;
        value = r.sum ? value + peak : std::max(value, peak);
      }
      return value;
    }
  }
  return 0.0;
}

}  // namespace isopound
