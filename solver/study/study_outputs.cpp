// Peak selectors of a study (grammar in study_outputs.h): parse once, resolve per model (DOF,
// story and element indices), evaluate per run as the max (or sum) of the selected peaks.
#include "solver/study/study_outputs.h"

#include <fnmatch.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "solver/elements/polygon_contact.h"
#include "solver/elements/story_link.h"
#include "solver/io/report3d.h"
#include "solver/structures/building3d.h"

namespace isopound {
namespace {

constexpr std::string_view kLevelQuantities[] = {"displacement", "velocity",
                                                 "absolute_acceleration", "residual_displacement"};
constexpr std::string_view kStoryQuantities[] = {"drift",
                                                 "drift_ratio",
                                                 "shear",
                                                 "ductility",
                                                 "residual_drift",
                                                 "residual_drift_ratio",
                                                 "hysteretic_energy"};
// Quantities of kStoryQuantities that only a yielding storey (a StoryLink) has.
constexpr int kStoryDuctility = 3, kStoryResidualDrift = 4, kStoryResidualDriftRatio = 5,
              kStoryHystereticEnergy = 6;
// 3D buildings: peaks at plan points (x, y, resultant) and of the diaphragm DOFs.
constexpr std::string_view kLevelQuantities3D[] = {"displacement",
                                                   "absolute_acceleration",
                                                   "displacement_x",
                                                   "displacement_y",
                                                   "absolute_acceleration_x",
                                                   "absolute_acceleration_y",
                                                   "residual_displacement",
                                                   "u",
                                                   "v",
                                                   "theta"};
constexpr std::string_view kStoryQuantities3D[] = {
    "drift",     "drift_x", "drift_y",           "drift_ratio",
    "ductility", "yielded", "hysteretic_energy", "residual_drift_ratio"};
// Of the yielding columns' elements (column_element.h): max of ductility, sum of the others.
constexpr std::string_view kColumnOutputs[] = {"ductility", "yielded", "hysteretic_energy"};
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

constexpr int kStoryLinkEnergyOutput = 3;  // StoryLink's hysteretic_energy output

[[noreturn]] void fail_selector(const OutputSelector& s, const std::string& what) {
  throw std::invalid_argument("peak '" + s.text + "': " + what);
}

// A 3D building: every level has the DOFs (u, v, theta).
bool is_3d(const Model& model, const StructureInfo& b) {
  if (b.level_dofs.empty()) return false;
  const int d = b.level_dofs.front();
  return d + 2 < model.size() && model.dofs[d + 2].kind == DofKind::kRotation;
}

// "building/floor 2" from the level's DOF label "building/floor 2 (x)".
std::string level_name(const Model& model, int dof) {
  const std::string& label = model.dofs[dof].label;
  const std::size_t paren = label.rfind(" (");
  return paren == std::string::npos ? label : label.substr(0, paren);
}

// The levels (indices into level_dofs) a level selector names.
std::vector<int> selected_levels(const OutputSelector& s, const StructureInfo& b) {
  const int levels = static_cast<int>(b.level_dofs.size());
  const int floors = levels - (b.has_base ? 1 : 0);
  if (s.where == "base") {
    if (!b.has_base) fail_selector(s, "the building has a fixed base (no base slab)");
    return {b.base_level};
  }
  if (s.where == "roof") return {levels - 1};
  std::vector<int> out;
  if (s.where == "floors" || s.where == "levels") {
    for (int l = 0; l < levels; ++l)
      if (s.where == "levels" || !b.has_base || l != b.base_level) out.push_back(l);
    return out;
  }
  const int floor = numbered(s.where, "floor");
  if (floor > floors) fail_selector(s, "the building has " + std::to_string(floors) + " floors");
  return {b.floor_level(floor)};
}

// The stories (1-based) a story selector names; `count` stories in the building.
std::vector<int> selected_stories(const OutputSelector& s, int count) {
  std::vector<int> out;
  if (s.where == "stories") {
    for (int k = 1; k <= count; ++k) out.push_back(k);
    return out;
  }
  const int story = numbered(s.where, "story");
  if (story > count) fail_selector(s, "the building has " + std::to_string(count) + " stories");
  return {story};
}

// 3D levels: the diaphragm DOFs (u, v, theta) or the plan probes at the chosen points.
void resolve_level3d(const OutputSelector& s, const Model& model, const StructureInfo& b,
                     ResolvedOutput& r) {
  const std::string& q = s.quantity;
  const std::vector<int> levels = selected_levels(s, b);
  if (q == "u" || q == "v" || q == "theta") {
    r.quantity = 0;  // displacement peaks of the DOFs
    const int offset = q == "u" ? 0 : q == "v" ? 1 : 2;
    for (const int l : levels) r.indices.push_back(b.level_dofs[l] + offset);
    return;
  }
  if (index_in(kLevelQuantities3D, q) < 0)
    fail_selector(s, "the building is 3D: peaks of its levels are " + joined(kLevelQuantities3D));
  const bool acceleration = q.starts_with("absolute_acceleration");
  const auto wanted = acceleration ? PlanProbe::Quantity::kAbsoluteAcceleration
                                   : PlanProbe::Quantity::kDisplacement;
  r.at_end = q == "residual_displacement";
  r.probe_component = q.ends_with("_x") ? 0 : q.ends_with("_y") ? 1 : 2;
  const std::string point = s.point.empty() ? "cm" : s.point;
  const int corner = numbered(point, "corner");
  for (const int l : levels) {
    const std::string prefix = level_name(model, b.level_dofs[l]) + "/";
    int corners = 0;
    bool found = false;
    for (std::size_t p = 0; p < model.probes.size(); ++p) {
      const PlanProbe& probe = model.probes[p];
      if (probe.quantity != wanted || !probe.label.starts_with(prefix)) continue;
      const std::string name = probe.label.substr(prefix.size());
      const bool is_corner = name.starts_with("corner ");
      corners += is_corner ? 1 : 0;
      const bool take = point == "points" || (point == "cm" && name == "CM") ||
                        (point == "corners" && is_corner) ||
                        (corner > 0 && name == "corner " + std::to_string(corner));
      if (!take) continue;
      found = true;
      r.indices.push_back(static_cast<int>(p));
      if (r.at_end) r.end_probes.push_back(probe);
    }
    if (!found)
      fail_selector(s, prefix.substr(0, prefix.size() - 1) + " has no plan point '" + point +
                           "' (its plan has " + std::to_string(corners) + " corners)");
  }
}

// 3D stories: the column drift probes of each storey, all, the corner columns or a pattern.
void resolve_story3d(const OutputSelector& s, const Model& model, const StructureInfo& b,
                     ResolvedOutput& r) {
  const std::string& q = s.quantity;
  const int count = static_cast<int>(b.level_dofs.size()) - (b.has_base ? 1 : 0);
  if (q == "shear") {  // the storey shear probes' resultant
    r.probe_component = 2;
    for (const int k : selected_stories(s, count)) {
      const std::string label = b.name + "/" + kStoreyShearPart + "/story " + std::to_string(k);
      for (std::size_t p = 0; p < model.probes.size(); ++p)
        if (model.probes[p].label == label) r.indices.push_back(static_cast<int>(p));
    }
    if (r.indices.empty())
      fail_selector(s,
                    "storey shear of a 3D building is recorded when its columns yield or "
                    "with p_delta: true");
    return;
  }
  if (index_in(kColumnOutputs, q) >= 0) {  // the storeys' yielding column elements
    r.kind = OutputSelector::Kind::kElement;
    r.sum = q != "ductility";
    for (const int k : selected_stories(s, count)) {
      const std::string prefix = b.name + "/story " + std::to_string(k) + "/column ";
      for (std::size_t e = 0; e < model.elements.size(); ++e) {
        const Element& element = *model.elements[e];
        if (!element.label().starts_with(prefix)) continue;
        const std::string label = element.label().substr(prefix.size());
        if (!s.point.empty() && fnmatch(s.point.c_str(), label.c_str(), 0) != 0) continue;
        for (int o = 0; o < element.output_count(); ++o)
          if (element.output_name(o) == q) {
            r.indices.push_back(static_cast<int>(e));
            r.element_outputs.push_back(o);
          }
      }
    }
    if (r.indices.empty())
      fail_selector(s, "no yielding column (columns: {hysteresis: ...}) in the selected storeys");
    return;
  }
  if (index_in(kStoryQuantities3D, q) < 0)
    fail_selector(
        s, "'" + q + "' is a peak of 2D storeys; a 3D storey has " + joined(kStoryQuantities3D));
  r.probe_component = q == "drift_x" ? 0 : q == "drift_y" ? 1 : q == "drift_ratio" ? 3 : 2;
  r.at_end = q == "residual_drift_ratio";
  r.end_ratio = r.at_end;
  for (const int k : selected_stories(s, count)) {
    const std::string prefix = b.name + "/story " + std::to_string(k) + "/";
    std::vector<std::pair<std::string, int>> columns;  // label, probe
    for (std::size_t p = 0; p < model.probes.size(); ++p)
      if (model.probes[p].label.starts_with(prefix))
        columns.emplace_back(model.probes[p].label.substr(prefix.size()), static_cast<int>(p));
    std::vector<std::string> labels;
    for (const auto& c : columns) labels.push_back(c.first);
    const std::vector<std::string> corners =
        s.point == "corners" ? corner_column_labels(labels) : std::vector<std::string>{};
    if (s.point == "corners" && corners.empty())
      fail_selector(s, "story " + std::to_string(k) +
                           ": corner columns need grid labels (A1, B1, ...); name columns "
                           "with a pattern instead, e.g. story1.A*." +
                           q);
    bool found = false;
    for (const auto& [label, p] : columns) {
      const bool take =
          s.point.empty() ||
          (s.point == "corners" ? std::find(corners.begin(), corners.end(), label) != corners.end()
                                : fnmatch(s.point.c_str(), label.c_str(), 0) == 0);
      if (!take) continue;
      found = true;
      r.indices.push_back(p);
      if (r.at_end) r.end_probes.push_back(model.probes[p]);
    }
    if (!found) {
      std::string names;
      for (const std::string& l : labels) names += (names.empty() ? "" : ", ") + l;
      fail_selector(s, "story " + std::to_string(k) + " has no column matching '" + s.point +
                           "' (its columns: " + (names.empty() ? "none" : names) + ")");
    }
  }
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
  // "base.corners", "story2.A1": a level or story, then a plan point or column set (3D).
  if (const std::size_t first = s.where.find('.'); first != std::string::npos) {
    const std::string place = s.where.substr(0, first);
    if (is_level_place(place) || is_story_place(place)) {
      s.point = s.where.substr(first + 1);
      s.where = place;
      if (s.point.empty()) fail("empty plan point or column after '" + place + ".'");
    }
  }
  if (s.where == "energy") {
    s.kind = OutputSelector::Kind::kEnergy;
    if (index_in(kEnergyTerms, s.quantity) < 0) fail("energy terms are " + joined(kEnergyTerms));
  } else if (s.where == "ground") {
    s.kind = OutputSelector::Kind::kGround;
    if (index_in(kGroundPeaks, s.quantity) < 0) fail("ground peaks are " + joined(kGroundPeaks));
  } else if (is_level_place(s.where)) {
    s.kind = OutputSelector::Kind::kLevel;
    if (index_in(kLevelQuantities, s.quantity) < 0 && index_in(kLevelQuantities3D, s.quantity) < 0)
      fail("peaks of a level are " + joined(kLevelQuantities) + "; of a 3D level also " +
           joined(kLevelQuantities3D) +
           (index_in(kStoryQuantities3D, s.quantity) >= 0
                ? " (drifts belong to stories: story<N> or stories)"
                : ""));
    if (!s.point.empty()) {
      if (s.quantity == "u" || s.quantity == "v" || s.quantity == "theta")
        fail("u, v and theta are the level's DOFs (at the plan origin): no plan point");
      if (s.quantity == "velocity")
        fail("plan points have displacement and absolute_acceleration peaks, not velocity");
      if (s.point != "cm" && s.point != "corners" && s.point != "points" &&
          numbered(s.point, "corner") < 0)
        fail("plan point '" + s.point + "': expected cm, corners, corner<K> or points");
    }
  } else if (is_story_place(s.where) || s.where == "columns") {
    // columns.<quantity>: every storey's columns (stories.<quantity>).
    if (s.where == "columns") s.where = "stories";
    s.kind = OutputSelector::Kind::kStory;
    if (index_in(kStoryQuantities, s.quantity) < 0 && index_in(kStoryQuantities3D, s.quantity) < 0)
      fail("peaks of a story are " + joined(kStoryQuantities) + "; of a 3D storey " +
           joined(kStoryQuantities3D));
    if (!s.point.empty() && s.quantity == "shear") fail("shear is a storey's, not a column's");
  } else {
    s.kind = OutputSelector::Kind::kElement;
  }
  if (s.sum && s.kind != OutputSelector::Kind::kElement) fail("'sum:' applies to elements only");
  if (s.sum && s.quantity == "first_impact_time")
    fail("first_impact_time is the earliest over the matches: no 'sum:'");
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
      {"dissipated_energy", "J"},
      {"displacement_x", "m"},
      {"displacement_y", "m"},
      {"absolute_acceleration_x", "m/s2"},
      {"absolute_acceleration_y", "m/s2"},
      {"u", "m"},
      {"v", "m"},
      {"theta", "rad"},
      {"drift_x", "m"},
      {"drift_y", "m"},
      {"normal_force", "N"},
      {"tangential_force", "N"},
      {"area", "m2"},
      {"time_in_stick", "s"},
      {"first_impact_time", "s"},
      {"time_in_slip", "s"},
      {"friction_dissipated_energy", "J"},
      {"impact_dissipated_energy", "J"},
      {"force_x", "N"},
      {"force_y", "N"},
      {"deformation_x", "m"},
      {"deformation_y", "m"},
      {"ductility", "-"},
      {"residual_drift", "m"},
      {"residual_drift_ratio", "-"},
      {"hysteretic_energy", "J"},
      {"yielded", "-"}};
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
      if (model.structures.empty()) fail("the model has no building");
      const StructureInfo& b = model.structures.front();
      if (is_3d(model, b)) {
        resolve_level3d(s, model, b, r);
        return r;
      }
      if (!s.point.empty())
        fail("plan points (" + s.point + ") belong to 3D buildings; this building is 2D");
      r.quantity = index_in(kLevelQuantities, s.quantity);
      if (r.quantity < 0)
        fail("'" + s.quantity + "' is a peak of 3D buildings; a 2D level has " +
             joined(kLevelQuantities));
      for (const int l : selected_levels(s, b)) r.indices.push_back(b.level_dofs[l]);
      return r;
    }
    case OutputSelector::Kind::kStory: {
      if (model.structures.empty()) fail("the model has no building");
      const StructureInfo& b = model.structures.front();  // its stories come first (stories_of)
      if (is_3d(model, b)) {
        resolve_story3d(s, model, b, r);
        return r;
      }
      if (!s.point.empty())
        fail("columns (" + s.point + ") belong to 3D buildings; this building is 2D");
      r.quantity = index_in(kStoryQuantities, s.quantity);
      if (r.quantity < 0)
        fail("'" + s.quantity + "' is a peak of 3D storeys; a 2D story has " +
             joined(kStoryQuantities));
      const int count = static_cast<int>(b.level_dofs.size()) - (b.has_base ? 1 : 0);
      for (const int k : selected_stories(s, count)) r.indices.push_back(k - 1);
      if (r.quantity == kStoryDuctility || r.quantity == kStoryHystereticEnergy) {
        // Yielding storeys only (an elastic storey has neither); `indices` keeps those.
        std::vector<int> yielding;
        for (const int k : r.indices) {
          const int e = k < static_cast<int>(b.story_elements.size()) ? b.story_elements[k] : -1;
          const auto* link =
              e >= 0 ? dynamic_cast<const StoryLink*>(model.elements[e].get()) : nullptr;
          if (!link) continue;
          yielding.push_back(k);
          r.story_links.push_back(e);
          r.yield_drifts.push_back(link->yield_drift());
        }
        if (yielding.empty())
          fail("'" + s.quantity +
               "' belongs to yielding storeys (floors: hysteresis); the selected are elastic");
        r.indices = yielding;
      }
      return r;
    }
    case OutputSelector::Kind::kElement: {
      r.first_time = s.quantity == "first_impact_time";
      std::vector<std::string> seen_outputs;
      const bool all_contacts = s.where == "contacts";  // every polygon contact pair
      for (std::size_t e = 0; e < model.elements.size(); ++e) {
        const Element& element = *model.elements[e];
        if (all_contacts ? dynamic_cast<const PolygonContact*>(&element) == nullptr
                         : !matches(s.where, element.label()))
          continue;
        // first_impact_time: when in_contact first reached 1 (its peak's time).
        const std::string wanted = r.first_time ? "in_contact" : s.quantity;
        int found = -1;
        for (int k = 0; k < element.output_count(); ++k) {
          if (element.output_name(k) == wanted) found = k;
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
        if (seen_outputs.empty() && all_contacts)
          fail("the model has no 3D contact pairs (walls or neighbours in `structures:`)");
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

RecordScope record_scope_of(const std::vector<ResolvedOutput>& outputs) {
  // The fields evaluate_output reads, branch by branch; displacements, drifts and the final
  // displacement are always recorded.
  RecordScope scope{false, false, false, false, false, false, false, {}};
  for (const ResolvedOutput& r : outputs) {
    switch (r.kind) {
      case OutputSelector::Kind::kEnergy:
        scope.energy = true;
        break;
      case OutputSelector::Kind::kGround:
        break;
      case OutputSelector::Kind::kLevel:
      case OutputSelector::Kind::kStory:
        if (r.at_end) break;
        if (r.probe_component >= 0) {
          scope.probes = true;
        } else if (r.kind == OutputSelector::Kind::kLevel) {
          scope.velocities = scope.velocities || r.quantity == 1;
          scope.accelerations = scope.accelerations || r.quantity == 2;
        } else if (r.quantity == kStoryHystereticEnergy) {
          scope.element_outputs = true;
          for (const int link : r.story_links)
            scope.element_output_subset.push_back({link, kStoryLinkEnergyOutput});
        } else {
          scope.story_shears = scope.story_shears || r.quantity == 2;
        }
        break;
      case OutputSelector::Kind::kElement:
        scope.element_outputs = true;
        for (std::size_t j = 0; j < r.indices.size(); ++j)
          scope.element_output_subset.push_back({r.indices[j], r.element_outputs[j]});
        break;
    }
  }
  return scope;
}

double evaluate_output(const ResolvedOutput& r, const AnalysisResult& result,
                       const GroundMotionPeaks& ground,
                       const std::vector<double>* first_impact_times) {
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
      if (r.at_end) {  // the resultant at the end of the plan points
        const auto sum = [&](const std::vector<std::pair<int, double>>& terms) {
          double x = 0.0;
          for (const auto& [dof, c] : terms) x += c * result.final_displacement[dof];
          return x;
        };
        for (const PlanProbe& p : r.end_probes)
          value = std::max(
              value, std::hypot(sum(p.x_terms), sum(p.y_terms)) / (r.end_ratio ? p.length : 1.0));
        return value;
      }
      if (r.probe_component >= 0) {
        for (const int i : r.indices) {
          const ProbePeaks& p = result.probes[i];
          const Peak* components[] = {&p.x, &p.y, &p.resultant, &p.ratio};
          value = std::max(value, components[r.probe_component]->value);
        }
        return value;
      }
      if (r.kind == OutputSelector::Kind::kLevel && r.quantity == 3) {  // |u| at the end
        for (const int i : r.indices)
          value = std::max(value, std::abs(result.final_displacement[i]));
        return value;
      }
      if (r.kind == OutputSelector::Kind::kStory && r.quantity >= kStoryDuctility) {
        for (std::size_t j = 0; j < r.indices.size(); ++j) {
          const int i = r.indices[j];
          const Story& st = result.stories[i];
          const double residual =
              std::abs(result.final_displacement[st.upper] -
                       (st.lower >= 0 ? result.final_displacement[st.lower] : 0.0));
          double x = 0.0;
          if (r.quantity == kStoryDuctility) x = result.drift[i].value / r.yield_drifts[j];
          if (r.quantity == kStoryResidualDrift) x = residual;
          if (r.quantity == kStoryResidualDriftRatio) x = residual / st.height;
          if (r.quantity == kStoryHystereticEnergy)
            x = result.element_outputs[r.story_links[j]][kStoryLinkEnergyOutput].value;
          value = std::max(value, x);
        }
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
      if (r.first_time) {  // the earliest onset over the pairs; none: an empty cell
        double first = std::numeric_limits<double>::quiet_NaN();
        for (std::size_t j = 0; j < r.indices.size(); ++j) {
          const Peak& in_contact = result.element_outputs[r.indices[j]][r.element_outputs[j]];
          const std::size_t e = static_cast<std::size_t>(r.indices[j]);
          const double t = first_impact_times
                               ? (e < first_impact_times->size() ? (*first_impact_times)[e] : -1.0)
                               : (in_contact.value > 0.0 ? in_contact.time : -1.0);
          if (t >= 0.0 && !(t >= first)) first = t;
        }
        return first;
      }
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
