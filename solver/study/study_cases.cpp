// Case models of a study (see study_cases.h): clone the base tree, apply the overrides, load it as
// a model file would be; validation does that for every case up front, in parallel.
#include "solver/study/study_cases.h"

#include <algorithm>
#include <atomic>
#include <exception>
#include <limits>
#include <mutex>
#include <thread>
#include <unordered_map>

#include "solver/io/model_input.h"
#include "solver/structures/job.h"
#include "solver/study/study_hash.h"
#include "solver/study/study_outputs.h"

namespace isopound {
namespace {

const ParameterPath& record_path() {
  static const ParameterPath path = parse_parameter_path("ground_motion.record");
  return path;
}

// Where a ground motion's record and pulse sit: the single component, and L and T of a pair.
struct ComponentPaths {
  ParameterPath record, pulse;
};
const std::vector<ComponentPaths>& component_paths() {
  static const std::vector<ComponentPaths> paths = [] {
    std::vector<ComponentPaths> out;
    for (const char* c : {"ground_motion", "ground_motion.L", "ground_motion.T"})
      out.push_back({parse_parameter_path(std::string(c) + ".record"),
                     parse_parameter_path(std::string(c) + ".pulse")});
    return out;
  }();
  return paths;
}

int line_of(const YAML::Mark& m) {
  return m.is_null() ? 0 : m.line + 1;
}
int column_of(const YAML::Mark& m) {
  return m.is_null() ? 0 : m.column + 1;
}

std::string emit_flow(const YAML::Node& node) {
  YAML::Emitter out;
  out.SetMapFormat(YAML::Flow);
  out.SetSeqFormat(YAML::Flow);
  out << node;
  return out.c_str();
}

YAML::Node child_of(const YAML::Node& map, const std::string& key) {
  if (map.IsMap())
    for (auto entry : map)
      if (entry.first.IsScalar() && entry.first.Scalar() == key) return entry.second;
  return YAML::Node(YAML::NodeType::Undefined);
}

struct PairHash {
  std::size_t operator()(const std::pair<std::uint64_t, std::uint64_t>& p) const {
    return static_cast<std::size_t>(p.first ^ (p.second * 0x9e3779b97f4a7c15ull));
  }
};

}  // namespace

std::vector<const Override*> CaseBuilder::overrides_of(std::int64_t case_id) const {
  std::vector<const Override*> out;
  for (const Override& o : study_.fixed) out.push_back(&o);
  const std::vector<int> levels = study_.levels_of(case_id);
  for (std::size_t a = 0; a < study_.axes.size(); ++a)
    for (const Override& o : study_.axes[a].levels[levels[a]].overrides) out.push_back(&o);
  return out;
}

std::string CaseBuilder::describe(std::int64_t case_id) const {
  const std::vector<int> levels = study_.levels_of(case_id);
  std::string out;
  for (std::size_t a = 0; a < study_.axes.size(); ++a)
    out += (out.empty() ? "" : ", ") + study_.axes[a].name + "=" +
           study_.axes[a].levels[levels[a]].label;
  return out;
}

std::string CaseBuilder::identity(std::int64_t case_id) const {
  const std::vector<const Override*> overrides = overrides_of(case_id);
  std::string out;
  for (std::size_t i = 0; i < overrides.size(); ++i) {
    bool replaced = false;
    for (std::size_t j = i + 1; j < overrides.size() && !replaced; ++j)
      replaced = is_prefix_of(overrides[j]->path, overrides[i]->path);
    if (!replaced) out += overrides[i]->path.text + "=" + overrides[i]->canonical + "\n";
  }
  return out;
}

const Override* CaseBuilder::override_for(std::int64_t case_id, const ParameterPath& path) const {
  const std::vector<const Override*> overrides = overrides_of(case_id);
  for (auto it = overrides.rbegin(); it != overrides.rend(); ++it)
    if (is_prefix_of((*it)->path, path)) return *it;
  return nullptr;
}

CaseInput CaseBuilder::input_of(std::int64_t case_id) const {
  const std::vector<const Override*> overrides = overrides_of(case_id);
  const auto in_case = [&] {
    return " (case " + std::to_string(case_id) + ": " + describe(case_id) + ")";
  };
  YAML::Node tree = YAML::Clone(study_.model);
  for (const Override* o : overrides) {
    try {
      apply_override(tree, o->path, o->value);
      // A record replaces the built-in pulse and the other way round (of a pair's L or T too).
      for (const ComponentPaths& c : component_paths()) {
        if (o->path == c.record) apply_override(tree, c.pulse, YAML::Node());
        if (is_prefix_of(c.pulse, o->path)) apply_override(tree, c.record, YAML::Node());
      }
    } catch (const std::invalid_argument& e) {
      o->where.fail(e.what() + in_case());
    }
  }
  CaseInput input;
  try {
    input.config = load_model(tree, study_.model_file, study_.model_dir);
  } catch (const InputError& e) {
    // The cloned tree has no positions: point at the override that wrote the key, else at the
    // key in the base model.
    ParameterPath path;
    bool parsed = false;
    try {
      path = parse_parameter_path(e.key());
      parsed = true;
    } catch (const std::invalid_argument&) {
    }
    if (parsed)
      for (auto it = overrides.rbegin(); it != overrides.rend(); ++it)
        if (is_prefix_of((*it)->path, path) || is_prefix_of(path, (*it)->path))
          (*it)->where.fail(e.key() + ": " + e.detail() + in_case());
    const YAML::Mark mark = parsed ? locate(study_.model, path) : YAML::Mark::null_mark();
    if (mark.is_null() && study_.model_where) study_.model_where->fail(e.what() + in_case());
    throw InputError(study_.model_file, line_of(mark), column_of(mark), e.key(),
                     e.detail() + in_case());
  }
  // Its plausibility warnings, read from the cloned tree (no positions), are located as its
  // errors are: at the override that wrote the key, else at the key in the base model.
  for (std::string& w : input.config.warnings) {
    const std::string prefix = study_.model_file + ":";
    if (w.rfind(prefix, 0) != 0) continue;
    const std::size_t key_at = w.find(": ", prefix.size());  // after "line:col"
    if (key_at == std::string::npos) continue;
    const std::size_t what_at = w.find(": ", key_at + 2);
    if (what_at == std::string::npos) continue;
    const std::string key = w.substr(key_at + 2, what_at - key_at - 2);
    const std::string what = w.substr(what_at + 2);
    ParameterPath path;
    try {
      path = parse_parameter_path(key);
    } catch (const std::invalid_argument&) {
      continue;
    }
    const Override* writer = nullptr;
    for (auto it = overrides.rbegin(); it != overrides.rend() && !writer; ++it)
      if (is_prefix_of((*it)->path, path) || is_prefix_of(path, (*it)->path)) writer = *it;
    if (writer) {
      w = writer->where.error(key + ": " + what).what();
    } else {
      const YAML::Mark mark = locate(study_.model, path);
      w = InputError(study_.model_file, line_of(mark), column_of(mark), key, what).what();
    }
  }
  input.config.output.histories = false;
  // A 3D model reads the same ground_motion subtree as a pair (two components).
  input.motion_key =
      (input.config.structures3d.empty() ? "" : "3D ") + emit_flow(child_of(tree, "ground_motion"));
  return input;
}

ValidatedStudy validate_study(const Study& study, int threads) {
  const std::int64_t count = study.case_count();
  const CaseBuilder builder(study);
  std::vector<OutputSelector> selectors;
  for (const OutputSpec& o : study.outputs) selectors.push_back(parse_output_selector(o.selector));

  std::vector<std::pair<std::uint64_t, std::uint64_t>> identities(static_cast<std::size_t>(count));
  const bool keep_inputs = count <= ValidatedStudy::kKeptInputs;
  std::vector<std::shared_ptr<const CaseInput>> inputs(keep_inputs ? static_cast<std::size_t>(count)
                                                                   : 0);
  // Element peaks may be absent from some cases (walls removed in a variant): an error only when
  // no case has them.
  std::vector<std::atomic<bool>> found_somewhere(selectors.size());
  std::atomic<std::int64_t> next{0};
  std::atomic<std::int64_t> first_error{std::numeric_limits<std::int64_t>::max()};
  struct Found {
    std::map<std::string, std::int64_t> motions;  // key -> lowest case using it
    std::map<std::string, std::pair<std::int64_t, std::int64_t>> warnings;  // -> (case, count)
    std::int64_t error_case = std::numeric_limits<std::int64_t>::max();
    std::exception_ptr error;
  };
  const int workers =
      static_cast<int>(std::max<std::int64_t>(1, std::min<std::int64_t>(threads, count)));
  std::vector<Found> found(static_cast<std::size_t>(workers));

  const auto validate = [&](Found& mine) {
    for (;;) {
      const std::int64_t c = next.fetch_add(1);
      if (c >= count || c > first_error.load()) return;
      try {
        auto kept = std::make_shared<CaseInput>(builder.input_of(c));
        const CaseInput& input = *kept;
        const auto in_case = [&] {
          return " (case " + std::to_string(c) + ": " + builder.describe(c) + ")";
        };
        Model model;
        try {
          model = build_model(input.config);
        } catch (const std::exception& e) {
          study.model_where->fail(std::string("the model cannot be built: ") + e.what() +
                                  in_case());
        }
        for (std::size_t k = 0; k < selectors.size(); ++k) {
          try {
            resolve_output(selectors[k], model);
            found_somewhere[k] = true;
          } catch (const std::invalid_argument& e) {
            if (selectors[k].kind != OutputSelector::Kind::kElement)
              study.outputs[k].where.fail(e.what() + in_case());
          }
        }
        mine.motions.emplace(input.motion_key,
                             c);  // cases come in increasing order: keeps the lowest
        for (const std::string& w : input.config.warnings) {
          auto& [first, n] = mine.warnings.try_emplace(w, c, 0).first->second;
          first = std::min(first, c);
          ++n;
        }
        const std::string identity = builder.identity(c);
        identities[static_cast<std::size_t>(c)] = {fnv1a64(identity),
                                                   std::hash<std::string>{}(identity)};
        if (keep_inputs) inputs[static_cast<std::size_t>(c)] = std::move(kept);
      } catch (...) {
        if (c < mine.error_case) {
          mine.error_case = c;
          mine.error = std::current_exception();
        }
        std::int64_t seen = first_error.load();
        while (c < seen && !first_error.compare_exchange_weak(seen, c)) {
        }
      }
    }
  };
  std::vector<std::thread> pool;
  for (int w = 1; w < workers; ++w)
    pool.emplace_back(validate, std::ref(found[static_cast<std::size_t>(w)]));
  validate(found[0]);
  for (std::thread& t : pool) t.join();

  const Found* failed = nullptr;
  for (const Found& f : found)
    if (f.error && (!failed || f.error_case < failed->error_case)) failed = &f;
  if (failed) std::rethrow_exception(failed->error);
  for (std::size_t k = 0; k < selectors.size(); ++k) {
    if (found_somewhere[k]) continue;
    try {
      resolve_output(selectors[k], build_model(builder.input_of(0).config));
    } catch (const std::invalid_argument& e) {
      study.outputs[k].where.fail(e.what() + std::string(" (in every case)"));
    }
  }

  ValidatedStudy out;
  out.inputs = std::move(inputs);
  std::map<std::string, std::int64_t> motions;
  for (const Found& f : found)
    for (const auto& [key, c] : f.motions) {
      const auto [it, inserted] = motions.emplace(key, c);
      if (!inserted) it->second = std::min(it->second, c);
    }
  std::map<std::string, std::pair<std::int64_t, std::int64_t>> warnings;
  for (const Found& f : found)
    for (const auto& [text, seen] : f.warnings) {
      auto& [first, n] = warnings.try_emplace(text, seen.first, 0).first->second;
      first = std::min(first, seen.first);
      n += seen.second;
    }
  for (const auto& [text, seen] : warnings)
    out.warnings.push_back(text + " (case " + std::to_string(seen.first) + ": " +
                           builder.describe(seen.first) + "; " + std::to_string(seen.second) +
                           (seen.second == 1 ? " case)" : " cases)"));
  out.representative.resize(static_cast<std::size_t>(count));
  std::unordered_map<std::pair<std::uint64_t, std::uint64_t>, std::int64_t, PairHash> first_with;
  for (std::int64_t c = 0; c < count; ++c) {
    const auto [it, inserted] = first_with.emplace(identities[static_cast<std::size_t>(c)], c);
    out.representative[static_cast<std::size_t>(c)] = it->second;
  }
  out.distinct_models = static_cast<std::int64_t>(first_with.size());

  for (const auto& [key, c] : motions) {
    const CaseInput input = builder.input_of(c);
    try {
      auto prepared = std::make_shared<PreparedMotion>();
      // A 3D model takes two components (a record pair, or the built-in pulse pair).
      prepared->motion =
          load_ground_motion(input.config.ground_motion, !input.config.structures3d.empty());
      prepared->peaks = peaks_of(prepared->motion);
      out.motions.emplace(key, std::move(prepared));
    } catch (const std::exception& e) {
      const std::string what = std::string("cannot read the ground motion: ") + e.what() +
                               " (case " + std::to_string(c) + ": " + builder.describe(c) + ")";
      for (const ComponentPaths& component : component_paths())
        if (const Override* o = builder.override_for(c, component.record)) o->where.fail(what);
      const YAML::Mark mark = locate(study.model, record_path());
      if (mark.is_null()) study.model_where->fail(what);
      throw InputError(study.model_file, line_of(mark), column_of(mark), "ground_motion.record",
                       what);
    }
  }
  return out;
}

}  // namespace isopound
