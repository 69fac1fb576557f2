// Writers of summary.json and histories.csv, and the console summary. Values are SI; every
// JSON key ends in its unit (_m, _s, _N, _J, _m_s2) or is dimensionless.
#include "solver/io/report.h"

#include <filesystem>

#include <optional>

#include "solver/elements/column_line.h"
#include "solver/elements/column_link.h"
#include "solver/elements/contact.h"
#include "solver/elements/polygon_contact.h"
#include "solver/elements/struck_column3d.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iomanip>
#include <stdexcept>
#include <string>

#include "solver/io/computed_defaults.h"
#include "solver/io/report3d.h"
#include "solver/io/report_damage2d.h"
#include "solver/io/report_struck_columns.h"
#include "solver/materials/bumper_law.h"
#include "solver/structures/config3d.h"
#include "solver/structures/isolator.h"

namespace isopound {

nlohmann::json peak_json(const Peak& p, const std::string& unit) {
  return {{"value", p.value},
          {"unit", unit},
          {"time_s", p.time},
          {"positive", p.positive},
          {"positive_time_s", p.time_positive},
          {"negative", p.negative},
          {"negative_time_s", p.time_negative}};
}

namespace {

const char* stepping_name(AnalysisConfig::Stepping s) {
  return s == AnalysisConfig::Stepping::kAdaptive ? "adaptive" : "fixed";
}

const char* max_step_rule_name(AnalysisConfig::MaxStepRule rule) {
  return rule == AnalysisConfig::MaxStepRule::kParticipating ? "participating" : "all_modes";
}

const char* isolator_name(IsolatorConfig::Model m) {
  switch (m) {
    case IsolatorConfig::Model::kLinear:
      return "linear";
    case IsolatorConfig::Model::kBilinear:
      return "bilinear";
    case IsolatorConfig::Model::kBoucWen:
      return "bouc_wen";
    case IsolatorConfig::Model::kFrictionPendulum:
      return "friction_pendulum";
  }
  return "?";
}

// A 2D contact (6 outputs; 9 with a bumper, whose 3 come after the 6).
bool is_contact(const Element& el) {
  return el.output_count() >= 6 && el.output_name(5) == "dissipated_energy";
}

// Impact-dissipated energy: the contacts' own dissipation at the end of the run.
// (3D polygon contacts: their impact-dissipated output; friction is booked apart.)
double impact_energy(const Model& model) {
  double sum = 0.0;
  for (const auto& el : model.elements) {
    if (is_contact(*el)) sum += el->output(5);
    // A 3D struck column's outputs begin with its PolygonContact's.
    if (dynamic_cast<const PolygonContact*>(el.get()) ||
        dynamic_cast<const StruckColumn3D*>(el.get()))
      sum += el->output(10);
  }
  return sum;
}

// Friction-dissipated energy of the 3D polygon contacts; nullopt when the model has none.
std::optional<double> friction_energy(const Model& model) {
  std::optional<double> sum;
  for (const auto& el : model.elements)
    if (dynamic_cast<const PolygonContact*>(el.get()) ||
        dynamic_cast<const StruckColumn3D*>(el.get()))
      sum = sum.value_or(0.0) + el->output(9);
  return sum;
}

// Why the analysis ended where it did, when that is not the record's end (plus extra_time):
// t_end (analysis.t_end or --until) before it, or a t_end past it, clipped to it. "" otherwise.
std::string analysis_end_note(const RunStatistics& st) {
  if (st.t_end <= 0) return "";
  char line[256];
  if (st.t_end < st.record_end * (1 - 1e-12)) {
    std::snprintf(line, sizeof line,
                  "stopped early at t_end = %.6g s (analysis.t_end or --until), before the end of "
                  "the record + extra_time at %.6g s",
                  st.duration, st.record_end);
  } else if (st.t_end > st.record_end * (1 + 1e-12)) {
    std::snprintf(line, sizeof line,
                  "t_end = %.6g s (analysis.t_end or --until) is past the end of the record + "
                  "extra_time: clipped to %.6g s",
                  st.t_end, st.duration);
  } else {
    return "";
  }
  return line;
}

constexpr const char* kNothingToCompare =
    "nothing to compare: the model has no walls and no contacts with neighbours, so the run "
    "without them is this run (every amplification would be 1)";

// Whether the model has contact elements (2D walls and neighbours, 3D polygon contacts).
bool has_contacts(const Model& model) {
  for (const auto& el : model.elements)
    if (is_contact(*el) || dynamic_cast<const PolygonContact*>(el.get())) return true;
  return false;
}

// u_slab - u_below at the end: what is left on the isolators.
double residual_isolator_displacement(const AnalysisResult& r, const StructureInfo& s) {
  const int bottom = s.isolator_bottom_dof();
  return r.final_displacement[s.base_dof()] - (bottom >= 0 ? r.final_displacement[bottom] : 0.0);
}

int dof_by_label(const Model& model, const std::string& label) {
  for (int i = 0; i < model.size(); ++i)
    if (model.dofs[i].label == label) return i;
  return -1;
}

// The peaks of structure `s` of the pounding run `job` beside those of the same structure in the
// unobstructed run, and their ratios; nullopt for a structure absent there (a flexible wall).
std::optional<nlohmann::json> unobstructed_structure_json(const JobResult& job,
                                                          const JobResult& free_job,
                                                          const StructureInfo& s) {
  using nlohmann::json;
  const AnalysisResult& r = job.analysis;
  const AnalysisResult& u = free_job.analysis;
  const Model& model = job.model;
  if (s.level_dofs.empty() || dof_by_label(free_job.model, model.dofs[s.level_dofs[0]].label) < 0)
    return std::nullopt;
  const auto ratio = [](double x, double y) { return y > 0 ? x / y : 0.0; };
  json levels = json::array();
  for (const int d : s.level_dofs) {
    const int f = dof_by_label(free_job.model, model.dofs[d].label);
    levels.push_back(
        {{"label", model.dofs[d].label},
         {"unobstructed_displacement", peak_json(u.displacement[f], "m")},
         {"unobstructed_absolute_acceleration", peak_json(u.absolute_acceleration[f], "m/s2")},
         {"displacement_amplification", ratio(r.displacement[d].value, u.displacement[f].value)},
         {"acceleration_amplification",
          ratio(r.absolute_acceleration[d].value, u.absolute_acceleration[f].value)}});
  }
  json stories = json::array();
  for (std::size_t k = 0; k < r.stories.size(); ++k) {
    if (r.stories[k].label.rfind(s.name + "/", 0) != 0) continue;
    for (std::size_t f = 0; f < u.stories.size(); ++f)
      if (u.stories[f].label == r.stories[k].label)
        stories.push_back({{"label", r.stories[k].label},
                           {"unobstructed_drift", peak_json(u.drift[f], "m")},
                           {"drift_amplification", ratio(r.drift[k].value, u.drift[f].value)}});
  }
  return json{{"name", s.name}, {"levels", levels}, {"stories", stories}};
}

// Energy dissipated by yielding 3D columns (their final state); nullopt when the model has none.
std::optional<double> column_energy(const Model& model) {
  std::optional<double> sum;
  for (const auto& el : model.elements) {
    if (const auto* c = dynamic_cast<const ColumnLink*>(el.get()))
      sum = sum.value_or(0.0) + c->hysteretic_energy();
    if (const auto* c = dynamic_cast<const ColumnLine*>(el.get()))  // columns: hinges
      sum = sum.value_or(0.0) + c->hinge_dissipated_energy();
  }
  if (const std::optional<double> struck = struck_column_energy(model))  // 2D struck columns
    sum = sum.value_or(0.0) + *struck;
  return sum;
}

// The structures' isolators (2D) or bearings (3D): any isolated structure has them.
bool has_isolators(const Model& model) {
  for (const StructureInfo& s : model.structures)
    if (s.has_base) return true;
  return false;
}

// The hysteretic total less every term with an owner (contacts, friction, storeys, columns):
// the isolators' (or bearings') dissipation; without isolators what the trapezoidal rule's
// integration of the element powers leaves over (reported as unattributed, never as an
// isolator's: issue 37).
double unattributed_hysteretic_energy(const Model& model, const AnalysisResult& r) {
  return r.energy.hysteretic - impact_energy(model) - friction_energy(model).value_or(0.0) -
         story_hysteretic_energy(model) - column_energy(model).value_or(0.0);
}

double structure_weight(const Model& model, const StructureInfo& s) {
  double mass = 0.0;
  for (const int d : s.level_dofs) mass += model.mass(d, d);
  return mass * kGravity;
}

}  // namespace

nlohmann::json summary_json(const ModelConfig& config, const JobResult& job,
                            const UnobstructedResult* unobstructed) {
  using nlohmann::json;
  const AnalysisResult& r = job.analysis;
  const Model& model = job.model;
  json j;
  j["isopound_version"] = kIsopoundVersion;
  // Absolute, so that isopound-post finds the model from any directory; the text as given and
  // the directory it was resolved from say how.
  {
    std::error_code ec;
    const std::filesystem::path cwd = std::filesystem::current_path(ec);
    const std::filesystem::path given(config.source);
    const bool is_file = !config.source.empty() && config.source.front() != '(';
    j["model_file"] = is_file && !ec
                          ? (given.is_absolute() ? given : cwd / given).lexically_normal().string()
                          : config.source;
    if (is_file) {
      j["model_file_as_given"] = config.source;
      j["model_file_resolved_from"] = ec ? std::string() : cwd.string();
    }
  }
  j["warnings"] = config.warnings;  // implausible values (solver/io/plausibility.h)

  const GroundMotionConfig& g = config.ground_motion;
  j["ground_motion"] = {{"name", job.motion.name},
                        {"source", g.use_pulse ? "built-in near-fault pulse" : g.record_path},
                        {"dt_s", job.motion.dt},
                        {"samples", job.motion.acceleration.size()},
                        {"duration_s", job.motion.duration()},
                        {"scale", g.read.scale},
                        {"pga_m_s2", job.motion_peaks.pga},
                        {"pga_g", job.motion_peaks.pga / kGravity},
                        {"pgv_m_s", job.motion_peaks.pgv},
                        {"pgd_m", job.motion_peaks.pgd},
                        {"baseline",
                         "none: velocity and displacement integrated exactly from the "
                         "piecewise-linear acceleration, zero initial conditions"}};
  if (!job.motion.acceleration_y.empty()) {  // a pair rotated into x and y (3D)
    GroundMotion y = job.motion;
    y.acceleration = y.acceleration_y;
    const GroundMotionPeaks py = peaks_of(y);
    j["ground_motion"]["angle_deg"] = g.angle * 180.0 / 3.14159265358979323846;
    j["ground_motion"]["angle_convention"] =
        "counter-clockwise from X to L: a_x = a_L cos - a_T sin, a_y = a_L sin + a_T cos; "
        "pga_m_s2, "
        "pgv_m_s, pgd_m are of a_x";
    if (g.components.size() == 2) {
      j["ground_motion"]["source"] =
          g.components[0].use_pulse ? "pulse" : g.components[0].record_path;
      j["ground_motion"]["source_T"] =
          g.components[1].use_pulse ? "pulse" : g.components[1].record_path;
    }
    j["ground_motion"]["pga_y_m_s2"] = py.pga;
    j["ground_motion"]["pgv_y_m_s"] = py.pgv;
    j["ground_motion"]["pgd_y_m"] = py.pgd;
  }

  const AnalysisConfig& a = config.analysis;
  json defaults = json::object();
  for (const auto& [key, value] : defaults_with_values(config, job.motion.dt, &r.stats))
    defaults[key] = value;
  j["settings"] = {
      {"integrator", "Newmark average acceleration (gamma 1/2, beta 1/4), Newton-Raphson"},
      {"stepping", stepping_name(a.stepping)},
      {"dt_s", a.dt},
      {"analysis_interval_s", r.stats.interval},
      {"steps_per_period", a.steps_per_period},
      {"max_step_rule", max_step_rule_name(a.max_step_rule)},
      {"max_step_period_s", r.stats.step_period},
      {"tolerance", a.tolerance},
      {"max_halvings", a.max_halvings},
      {"newton_tolerance", a.newton_tolerance},
      {"max_iterations", a.max_iterations},
      {"extra_time_s", g.extra_time},
      {"output_interval_s", config.output.interval > 0 ? config.output.interval : job.motion.dt},
      {"isolator_model", isolator_name(config.building.isolator.model)},
      {"defaults_used", defaults}};

  if (!config.structures3d.empty()) j["settings"].erase("isolator_model");  // 3D: per building
  json structures = json::array();
  std::size_t story_index = 0;
  for (std::size_t si = 0; si < model.structures.size(); ++si) {
    const StructureInfo& s = model.structures[si];
    json js;
    js["name"] = s.name;
    json levels = json::array();
    for (std::size_t k = 0; k < s.level_dofs.size(); ++k) {
      const int d = s.level_dofs[k];
      levels.push_back(
          {{"label", model.dofs[d].label},
           {"displacement", peak_json(r.displacement[d], "m")},
           {"velocity", peak_json(r.velocity[d], "m/s")},
           {"absolute_acceleration", peak_json(r.absolute_acceleration[d], "m/s2")},
           {"absolute_acceleration_peak_g", r.absolute_acceleration[d].value / kGravity},
           {"residual_displacement_m", r.final_displacement[d]}});
    }
    js["levels"] = levels;
    const double weight = structure_weight(model, s);
    js["weight_N"] = weight;
    if (s.has_base) {
      js["base_displacement_m"] = r.displacement[s.base_dof()].value;
      // What is left on the isolators when the shaking (and extra_time) is over.
      js["residual_isolator_displacement_m"] = residual_isolator_displacement(r, s);
      // The force through the isolation layer (isolators, their damping, contacts on the slab).
      js["base_shear"] = peak_json(r.base_shear[si], "N");  // x in plan (3D)
      js["base_shear_coefficient"] = weight > 0 ? r.base_shear[si].value / weight : 0.0;
      if (!s.level_dofs_y.empty()) {
        js["base_shear_y"] = peak_json(r.base_shear_y[si], "N");
        js["base_shear_resultant"] = peak_json(r.base_shear_resultant[si], "N");
        js["base_shear_resultant_coefficient"] =
            weight > 0 ? r.base_shear_resultant[si].value / weight : 0.0;
      }
    }
    json stories = json::array();
    const std::size_t count = s.story_heights.size();
    for (std::size_t k = 0; k < count; ++k, ++story_index) {
      const Story& st = r.stories[story_index];
      stories.push_back(
          {{"label", st.label},
           {"height_m", st.height},
           {"drift", peak_json(r.drift[story_index], "m")},
           {"drift_ratio", peak_json(r.drift_ratio[story_index], "-")},
           {"shear", peak_json(r.story_shear[story_index], "N")},
           {"shear_coefficient", weight > 0 ? r.story_shear[story_index].value / weight : 0.0}});
      add_story_damage_json(stories.back(), model, r, s, k, story_index);  // report_damage2d
    }
    js["stories"] = stories;
    if (s.has_base && s.base_level > 0 && count > 0) {
      // Isolated above storey k (2D: a 3D building's storeys are its column probes, and
      // report3d.cpp gives its isolation level): where the slab sits, and the shear that
      // reaches the ground (storey 1's, below the substructure).
      js["isolation_level"] = s.base_level;
      js["isolation_height_m"] = s.isolation_height;
      const std::size_t first_story = story_index - count;
      js["ground_shear"] = peak_json(r.story_shear[first_story], "N");
      js["ground_shear_coefficient"] = weight > 0 ? r.story_shear[first_story].value / weight : 0.0;
      if (s.isolator_element >= 0)
        js["isolator_displacement"] =
            peak_json(r.element_outputs[static_cast<std::size_t>(s.isolator_element)][1], "m");
    }
    structures.push_back(js);
  }
  j["structures"] = structures;
  if (!config.structures3d.empty()) {
    j["buildings_3d"] = summary3d_json(job);  // report3d.cpp
    j["contacts_3d"] = contacts3d_json(job);
  }

  json elements = json::array();
  for (std::size_t e = 0; e < model.elements.size(); ++e) {
    const Element& el = *model.elements[e];
    json je;
    je["label"] = el.label();
    for (int k = 0; k < el.output_count(); ++k) {
      if (el.output_kind(k) == Element::OutputKind::kCount) {
        je[el.output_name(k)] = static_cast<long>(std::lround(r.element_outputs[e][k].value));
        continue;
      }
      je["peak_" + el.output_name(k)] =
          peak_json(r.element_outputs[e][k], el.output_unit(k).c_str());
    }
    const auto* contact = dynamic_cast<const Contact1D*>(&el);
    if (contact && contact->bumper()) {
      je["bumper"] = {{"thickness_m", contact->bumper()->thickness()},
                      {"peak_compression_m", contact->bumper_peak_compression()},
                      {"bottomings", contact->bottomings()},
                      {"first_bottoming_s", contact->first_bottoming_time() >= 0
                                                ? json(contact->first_bottoming_time())
                                                : json(nullptr)},
                      {"dissipated_J", contact->bumper_dissipated_energy()}};
    }
    elements.push_back(je);
  }
  j["elements"] = elements;
  if (json struck = struck_columns_json(model, r); !struck.empty()) j["struck_columns"] = struck;

  const EnergyBalance& en = r.energy;
  const double impacts = impact_energy(model);
  const std::optional<double> friction = friction_energy(model);
  const double stories_hysteretic = story_hysteretic_energy(model);
  const std::optional<double> columns = column_energy(model);
  j["energy"] = {{"input_J", en.input},
                 {"kinetic_J", en.kinetic},
                 {"elastic_J", en.elastic},
                 {"viscous_J", en.viscous},
                 {"hysteretic_J", en.hysteretic},
                 {has_isolators(model) ? "isolator_hysteretic_J" : "unattributed_hysteretic_J",
                  unattributed_hysteretic_energy(model, r)},
                 {"impact_dissipated_J", impacts},
                 {"balance_error_J", en.error},
                 {"relative_error", en.relative_error},
                 {"max_relative_error", en.max_relative_error},
                 {"note",
                  "each term integrated from its power with the trapezoidal rule in "
                  "time; relative_error = |input - sum| / input at the end; hysteretic = "
                  "isolator_hysteretic + impact_dissipated (+ friction_dissipated in 3D "
                  "pounding)"}};
  if (friction) j["energy"]["friction_dissipated_J"] = *friction;
  if (has_yielding_stories(model)) {
    j["energy"]["story_hysteretic_J"] = stories_hysteretic;
    j["energy"]["story_note"] =
        "story_hysteretic: the yielding storeys' work along their drift (trapezoidal between "
        "steps) minus their recoverable energy; hysteretic = isolator_hysteretic + "
        "impact_dissipated + story_hysteretic; residual drifts are at the end of the analysis "
        "(record + extra_time)";
  }
  if (columns) {
    j["energy"]["column_hysteretic_J"] = *columns;
    j["energy"]["note"] = j["energy"]["note"].get<std::string>() +
                          " + column_hysteretic (the yielding 3D columns' dissipation)";
  }
  if (unobstructed && !has_contacts(model)) {
    j[config.structures3d.empty() ? "unobstructed" : "unobstructed_3d"] = {
        {"note", kNothingToCompare}};
  } else if (unobstructed && !config.structures3d.empty()) {
    j["unobstructed_3d"] = unobstructed3d_json(job, *unobstructed);  // report3d.cpp
  } else if (unobstructed) {
    // Every building: the main one (structure 0, also under the old keys "levels" and
    // "stories") and each neighbour; DOFs and stories matched by label (wall structures shift
    // the numbering of later structures).
    json buildings = json::array();
    for (const StructureInfo& s : model.structures) {
      const std::optional<json> b = unobstructed_structure_json(job, unobstructed->job, s);
      if (b) buildings.push_back(*b);
    }
    json gaps = json::array();
    for (const ContactGap& c : unobstructed->gaps)
      gaps.push_back({{"label", c.label},
                      {"gap_m", c.gap},
                      {"critical_gap_m", c.critical_gap},
                      {"pounds_without_obstruction", c.critical_gap > c.gap}});
    j["unobstructed"] = {
        {"note",
         "the same analysis without walls and without contacts between neighbours; "
         "amplification = peak with pounding / peak without; critical_gap_m per contact = the "
         "largest closing of its gap without contact (a smaller gap pounds under this record); "
         "buildings: the main building and every neighbour"},
        {"levels", buildings.at(0)["levels"]},
        {"stories", buildings.at(0)["stories"]},
        {"buildings", buildings},
        {"contacts", gaps}};
  }

  const RunStatistics& st = r.stats;
  j["statistics"] = {{"steps", st.steps},
                     {"rejected_steps", st.rejected_steps},
                     {"newton_iterations", st.newton_iterations},
                     {"restarts", st.restarts},
                     {"min_step_s", st.min_step},
                     {"max_step_s", st.max_step},
                     {"analysed_time_s", st.duration},
                     {"wall_seconds", st.wall_seconds}};
  // Only when it happened (docs/theory.md, "Steps at a jump of the contact force").
  if (st.held_steps > 0) j["statistics"]["held_steps"] = st.held_steps;
  // How the analysis ended: at the record's end + extra_time, or at t_end (stated, with the
  // clipping of a t_end past the record), so that a shortened run never reads as a whole one.
  const std::string end_note = analysis_end_note(st);
  j["end_of_analysis"] = {{"analysed_time_s", st.duration},
                          {"record_end_s", st.record_end},
                          {"requested_end_s", st.t_end > 0 ? json(st.t_end) : json(nullptr)},
                          {"stopped_by", st.t_end > 0 && st.t_end < st.record_end * (1 - 1e-12)
                                             ? "t_end"
                                             : "end of record + extra_time"},
                          {"clipped", st.t_end > st.record_end * (1 + 1e-12)},
                          {"note", end_note}};
  return j;
}

void write_summary(const std::string& path, const ModelConfig& config, const JobResult& job,
                   const UnobstructedResult* unobstructed) {
  std::ofstream out(path);
  if (!out) throw std::runtime_error("cannot write " + path);
  out << std::setw(2) << summary_json(config, job, unobstructed) << '\n';
  if (!out) throw std::runtime_error("error writing " + path);
}

void write_histories(const std::string& path, const History& history) {
  std::FILE* f = std::fopen(path.c_str(), "w");
  if (!f) throw std::runtime_error("cannot write " + path);
  for (std::size_t c = 0; c < history.columns.size(); ++c)
    std::fprintf(f, "%s%s", c ? "," : "", history.columns[c].c_str());
  std::fputc('\n', f);
  const std::size_t cols = history.columns.size();
  for (std::size_t r = 0; r < history.rows(); ++r) {
    for (std::size_t c = 0; c < cols; ++c)
      std::fprintf(f, "%s%.9g", c ? "," : "", history.values[r * cols + c]);
    std::fputc('\n', f);
  }
  if (std::fclose(f) != 0) throw std::runtime_error("error writing " + path);
}

CsvHistoryWriter::CsvHistoryWriter(std::string path) : path_(std::move(path)) {
  file_ = std::fopen(path_.c_str(), "w");
  if (!file_) throw std::runtime_error("cannot write " + path_ + ": " + std::strerror(errno));
}

CsvHistoryWriter::~CsvHistoryWriter() {
  if (file_) std::fclose(file_);
}

void CsvHistoryWriter::begin(const std::vector<std::string>& columns) {
  for (std::size_t c = 0; c < columns.size(); ++c)
    std::fprintf(file_, "%s%s", c ? "," : "", columns[c].c_str());
  std::fputc('\n', file_);
}

void CsvHistoryWriter::row(const double* values, std::size_t count) {
  for (std::size_t c = 0; c < count; ++c) std::fprintf(file_, "%s%.9g", c ? "," : "", values[c]);
  std::fputc('\n', file_);
  ++rows_;
}

void CsvHistoryWriter::close() {
  if (!file_) return;
  const bool failed = std::ferror(file_) != 0;
  const bool close_failed = std::fclose(file_) != 0;
  file_ = nullptr;
  if (failed || close_failed) throw std::runtime_error("error writing " + path_);
}

void print_summary(std::ostream& out, const ModelConfig& config, const JobResult& job) {
  const AnalysisResult& r = job.analysis;
  const Model& model = job.model;
  char line[256];
  const GroundMotionPeaks& gp = job.motion_peaks;
  std::snprintf(line, sizeof line,
                "Ground motion %s: %zu samples at %.4g s, PGA %.3f g, PGV %.3f m/s, PGD %.3f m\n",
                job.motion.name.c_str(), job.motion.acceleration.size(), job.motion.dt,
                gp.pga / kGravity, gp.pgv, gp.pgd);
  out << line;
  if (!config.defaults.empty()) {
    out << "Defaults used (keys not in the file):\n";
    for (const auto& [key, value] : defaults_with_values(config, job.motion.dt, &r.stats))
      out << "  " << key << " = " << value << '\n';
  }
  std::snprintf(
      line, sizeof line,
      "Analysis: %s stepping, interval %.4g s (record %.4g s / %d), output every %.4g s\n",
      stepping_name(config.analysis.stepping), r.stats.interval, job.motion.dt,
      r.stats.interval > 0 ? static_cast<int>(std::lround(job.motion.dt / r.stats.interval)) : 0,
      config.output.interval > 0 ? config.output.interval : job.motion.dt);
  out << line;
  if (const std::string note = analysis_end_note(r.stats); !note.empty())
    out << "  " << note << '\n';
  if (r.stats.step_period > 0) {
    std::snprintf(line, sizeof line,
                  "  largest step from T_min %.4g s / %g steps per period (%s modes)\n",
                  r.stats.step_period, config.analysis.steps_per_period,
                  config.analysis.max_step_rule == AnalysisConfig::MaxStepRule::kParticipating
                      ? "participating"
                      : "all");
    out << line;
  }
  if (!config.structures3d.empty()) {  // report3d.cpp
    print_summary3d(out, job);
  } else {
    out << "Building " << config.building.name << " ("
        << isolator_name(config.building.isolator.model) << " isolators)\n";
    std::size_t story_index = 0;
    for (std::size_t si = 0; si < model.structures.size(); ++si) {
      const StructureInfo& s = model.structures[si];
      if (s.has_base) {
        const double weight = structure_weight(model, s);
        std::snprintf(line, sizeof line,
                      "  %-22s base shear %8.1f kN (V/W %.3f)   residual isolator displacement "
                      "%.2f cm\n",
                      s.name.c_str(), r.base_shear[si].value / 1e3,
                      weight > 0 ? r.base_shear[si].value / weight : 0.0,
                      100 * residual_isolator_displacement(r, s));
        out << line;
        if (s.base_level > 0 && s.isolator_element >= 0) {
          std::snprintf(
              line, sizeof line,
              "  %-22s isolators on floor %d: isolator displacement %.2f cm, ground "
              "shear %8.1f kN (storey 1)\n",
              "", s.base_level,
              100 * r.element_outputs[static_cast<std::size_t>(s.isolator_element)][1].value,
              r.story_shear[story_index].value / 1e3);
          out << line;
        }
      }
      for (std::size_t k = 0; k < s.level_dofs.size(); ++k) {
        const int d = s.level_dofs[k];
        std::snprintf(line, sizeof line,
                      "  %-22s displacement %8.2f cm   abs. acceleration %6.3f g\n",
                      model.dofs[d].label.c_str(), 100 * r.displacement[d].value,
                      r.absolute_acceleration[d].value / kGravity);
        out << line;
      }
      const std::size_t count = s.story_heights.size();
      for (std::size_t k = 0; k < count; ++k, ++story_index) {
        std::snprintf(
            line, sizeof line, "  %-22s drift %8.3f cm   drift ratio %.3f %%   shear %8.1f kN\n",
            r.stories[story_index].label.c_str(), 100 * r.drift[story_index].value,
            100 * r.drift_ratio[story_index].value, r.story_shear[story_index].value / 1e3);
        out << line;
        print_story_damage(out, model, r, s, k, story_index);  // report_damage2d
      }
    }
    for (std::size_t e = 0; e < model.elements.size(); ++e) {
      const Element& el = *model.elements[e];
      std::snprintf(line, sizeof line, "  %-22s peak force %8.1f kN   peak %s %6.2f cm",
                    el.label().c_str(), r.element_outputs[e][0].value / 1e3,
                    el.output_name(1).c_str(), 100 * r.element_outputs[e][1].value);
      out << line;
      if (el.output_count() > 3 && el.output_name(2) == "impacts") {
        std::snprintf(line, sizeof line, "   %d impacts, max impact velocity %.3f m/s",
                      static_cast<int>(r.element_outputs[e][2].value),
                      r.element_outputs[e][3].value);
        out << line;
      }
      const auto* contact = dynamic_cast<const Contact1D*>(&el);
      if (contact && contact->bumper()) {
        std::snprintf(line, sizeof line,
                      "\n  %-22s bumper %.0f cm: peak compression %.2f cm, %d bottom-outs", "",
                      100 * contact->bumper()->thickness(),
                      100 * contact->bumper_peak_compression(), contact->bottomings());
        out << line;
        if (contact->bottomings() > 0) {
          std::snprintf(line, sizeof line, " (first at %.3f s)", contact->first_bottoming_time());
          out << line;
        }
        std::snprintf(line, sizeof line, ", rubber dissipated %.4g kJ",
                      contact->bumper_dissipated_energy() / 1e3);
        out << line;
      }
      out << '\n';
    }
    print_struck_columns(out, model, r);  // report_struck_columns
  }
  {
    const std::optional<double> friction = friction_energy(model);
    const bool stories = has_yielding_stories(model);
    std::snprintf(line, sizeof line, "Energy: input %.4g kJ, %s %.4g kJ", r.energy.input / 1e3,
                  has_isolators(model) ? "isolator hysteretic" : "unattributed hysteretic",
                  unattributed_hysteretic_energy(model, r) / 1e3);
    out << line;
    if (stories) {
      std::snprintf(line, sizeof line, ", storey hysteretic %.4g kJ",
                    story_hysteretic_energy(model) / 1e3);
      out << line;
    }
    std::snprintf(line, sizeof line, ", impact-dissipated %.4g kJ", impact_energy(model) / 1e3);
    out << line;
    if (friction) {
      std::snprintf(line, sizeof line, ", friction %.4g kJ", *friction / 1e3);
      out << line;
    }
    std::snprintf(line, sizeof line, ", viscous %.4g kJ, balance error %.2e\n",
                  r.energy.viscous / 1e3, r.energy.relative_error);
  }
  out << line;
  if (const std::optional<double> columns = column_energy(model)) {
    std::snprintf(line, sizeof line, "  column hysteretic %.4g kJ (of the hysteretic total)\n",
                  *columns / 1e3);
    out << line;
  }
  std::snprintf(line, sizeof line,
                "Steps: %ld accepted, %ld rejected, %ld Newton iterations, step %.3g..%.3g s, "
                "%.1f ms\n",
                r.stats.steps, r.stats.rejected_steps, r.stats.newton_iterations, r.stats.min_step,
                r.stats.max_step, 1e3 * r.stats.wall_seconds);
  out << line;
  if (r.stats.held_steps > 0) {
    std::snprintf(line, sizeof line,
                  "  %ld smallest steps held a contact's overlap shape (triangle or not, eq. 5.20) "
                  "where Newton flipped between the two: docs/theory.md\n",
                  r.stats.held_steps);
    out << line;
  }
}

}  // namespace isopound

namespace isopound {

void print_unobstructed(std::ostream& out, const ModelConfig& config, const JobResult& job,
                        const UnobstructedResult& unobstructed) {
  if (!has_contacts(job.model)) {
    out << "--compare-unobstructed: " << kNothingToCompare << '\n';
    return;
  }
  if (!config.structures3d.empty()) return print_unobstructed3d(out, job, unobstructed);
  char line[256];
  out << "Without walls and neighbour contacts (amplification = with / without):\n";
  const auto amplification = [](const nlohmann::json& x) { return x.get<double>(); };
  for (const StructureInfo& s : job.model.structures) {
    const std::optional<nlohmann::json> b = unobstructed_structure_json(job, unobstructed.job, s);
    if (!b) continue;
    for (const auto& l : (*b)["levels"]) {
      std::snprintf(line, sizeof line,
                    "  %-22s displacement %8.2f cm (x%.2f)   abs. acceleration %6.3f g (x%.2f)\n",
                    l["label"].get<std::string>().c_str(),
                    100 * l["unobstructed_displacement"]["value"].get<double>(),
                    amplification(l["displacement_amplification"]),
                    l["unobstructed_absolute_acceleration"]["value"].get<double>() / kGravity,
                    amplification(l["acceleration_amplification"]));
      out << line;
    }
    for (const auto& st : (*b)["stories"]) {
      std::snprintf(line, sizeof line, "  %-22s drift %8.3f cm (x%.2f)\n",
                    st["label"].get<std::string>().c_str(),
                    100 * st["unobstructed_drift"]["value"].get<double>(),
                    amplification(st["drift_amplification"]));
      out << line;
    }
  }
  out << "Critical gaps (a gap below this pounds under this record):\n";
  for (const ContactGap& c : unobstructed.gaps) {
    std::snprintf(line, sizeof line, "  %-34s gap %7.2f cm   critical gap %7.2f cm%s\n",
                  c.label.c_str(), 100 * c.gap, 100 * c.critical_gap,
                  c.critical_gap > c.gap ? "   (pounds)" : "");
    out << line;
  }
}

}  // namespace isopound
