// Reading a study file (format in study_spec.h and docs/studies.md) into a Study. Everything that
// can be checked without building models is checked here, each error at its file:line:col: key.
#include "solver/study/study_spec.h"

#include "solver/study/study_ensemble.h"

#include <fnmatch.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <map>
#include <numbers>
#include <optional>
#include <set>

#include "solver/io/units.h"
#include "solver/study/study_csv.h"
#include "solver/study/study_outputs.h"

namespace isopound {
namespace {

namespace fs = std::filesystem;

constexpr std::int64_t kMaxCases = 100'000'000;
constexpr std::int64_t kMaxAxisValues = 1'000'000;
constexpr const char* kRecordPath = "ground_motion.record";
constexpr const char* kRecordAxis = "record";
constexpr const char* kVariantAxis = "variant";

int line_of(const YAML::Mark& m) {
  return m.is_null() ? 0 : m.line + 1;
}
int column_of(const YAML::Mark& m) {
  return m.is_null() ? 0 : m.column + 1;
}

std::string read_text(const std::string& path) {
  return read_input_file(path, "a YAML file");
}

YAML::Node parse_document(const std::string& text, const std::string& path) {
  try {
    return parse_single_document(text, path, "a study or model file");
  } catch (const InputError& e) {
    // The commonest cause in a study: {path: structures[0].x, ...}, where YAML's flow style
    // reads the bare '[' as the start of a list.
    if (e.detail().find("flow") == std::string::npos) throw;
    throw InputError(e.file(), e.line(), e.column(), e.key(),
                     e.detail() +
                         " (inside {...}, quote a path with a list index: path: "
                         "\"structures[0].bearing.QW\")");
  }
}

std::string canonical_text(const YAML::Node& value) {
  if (!value.IsDefined() || value.IsNull()) return "~";
  if (value.IsScalar()) return value.Scalar();
  YAML::Emitter out;
  out.SetMapFormat(YAML::Flow);
  out.SetSeqFormat(YAML::Flow);
  out << value;
  return out.c_str();
}

// The keys of a map node in file order (the InputNode of each is found with find()).
std::vector<std::string> keys_of(const InputNode& map) {
  std::vector<std::string> keys;
  for (auto entry : map.yaml())
    if (entry.first.IsScalar()) keys.push_back(entry.first.Scalar());
  return keys;
}

// Letters, digits and '_' only: safe as a column name in SQL, CSV, pandas and R.
std::string column_name_of(std::string_view text) {
  std::string out;
  for (const char c : text) {
    const bool ok = std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_';
    if (ok) {
      out += c;
    } else if (!out.empty() && out.back() != '_') {
      out += '_';
    }
  }
  while (!out.empty() && out.back() == '_') out.pop_back();
  return out;
}

bool is_column_name(std::string_view text) {
  return !text.empty() && column_name_of(text) == text;
}

// SI unit text of a dimension that the unit parser reads back ("kg*s^-2"); "" if dimensionless.
std::string si_unit_of(const Dimension& d) {
  std::string out;
  const auto factor = [&](const char* symbol, double exponent) {
    if (exponent == 0.0) return;
    if (!out.empty()) out += '*';
    out += symbol;
    if (exponent != 1.0) {
      char buffer[32];
      std::snprintf(buffer, sizeof buffer, "^%g", exponent);
      out += buffer;
    }
  };
  factor("m", d.length);
  factor("kg", d.mass);
  factor("s", d.time);
  return out;
}

class StudyReader {
 public:
  explicit StudyReader(Study& study) : study_(study) {}

  void read(const InputNode& top) {
    top.expect_keys({"name", "model", "set", "records", "axes", "variants", "outputs", "derived",
                     "statistics", "ensemble"});
    study_.name = fs::path(study_.file).stem().string();
    if (const auto name = top.find("name")) {
      study_.name = name->string();
      if (study_.name.empty()) name->fail("must not be empty");
    }
    read_model(top.required("model"));
    if (const auto set = top.find("set")) study_.fixed = read_override_map(*set);

    int group = 0;
    if (const auto records = top.find("records")) {
      Axis axis{kRecordAxis, read_records(*records), group++, *records};
      study_.axes.push_back(std::move(axis));
    }
    if (const auto axes = top.find("axes")) {
      for (const InputNode& item : axes->elements()) {
        if (item.is_map() && item.has("zip")) {
          item.expect_keys({"zip"});
          const InputNode zip = item.required("zip");
          const std::vector<InputNode> members = zip.elements();
          if (members.empty()) zip.fail("empty zip: give the axes that advance together");
          const std::size_t first = study_.axes.size();
          for (const InputNode& member : members) {
            if (member.is_map() && member.has("zip")) member.fail("a zip cannot hold another zip");
            study_.axes.push_back(read_axis(member, group));
          }
          for (std::size_t a = first + 1; a < study_.axes.size(); ++a) {
            if (study_.axes[a].levels.size() != study_.axes[first].levels.size())
              study_.axes[a].where.fail("zipped axes must have the same number of values: '" +
                                        study_.axes[a].name + "' has " +
                                        std::to_string(study_.axes[a].levels.size()) + ", '" +
                                        study_.axes[first].name + "' has " +
                                        std::to_string(study_.axes[first].levels.size()));
          }
          ++group;
        } else {
          study_.axes.push_back(read_axis(item, group++));
        }
      }
    }
    if (const auto variants = top.find("variants")) {
      Axis axis{kVariantAxis, read_levels(*variants), group++, *variants};
      study_.axes.push_back(std::move(axis));
    }
    study_.group_count = group;
    check_axis_names();

    std::int64_t count = 1;
    for (const std::int64_t size : study_.group_sizes()) {
      if (count > kMaxCases / size) {
        const InputNode& where = study_.axes.empty() ? top : study_.axes.back().where;
        where.fail("the study has more than " + std::to_string(kMaxCases) + " runs");
      }
      count *= size;
    }

    read_outputs(top.find("outputs"), top);
    if (const auto derived = top.find("derived")) read_ratios(*derived);
    read_statistics(top.find("statistics"));
    if (const auto ensemble = top.find("ensemble")) read_ensemble(*ensemble);
  }

 private:
  void read_model(const InputNode& node) {
    study_.model_where = node;
    if (node.is_map()) {
      study_.model = node.yaml();
      study_.model_file = study_.file;
      study_.model_dir = study_.dir;
      return;
    }
    if (node.is_sequence())
      node.fail("expected a model file (path) or an inline model (a map), got a list");
    const std::string written = node.string();
    if (written.empty()) node.fail("must not be empty");
    fs::path path(written);
    if (path.is_relative()) path = fs::path(study_.dir) / path;
    const std::string resolved = path.lexically_normal().string();
    std::error_code ec;
    if (!fs::is_regular_file(resolved, ec)) node.fail("model file '" + resolved + "' not found");
    study_.model_text = read_text(resolved);
    study_.model = parse_document(study_.model_text, resolved);
    study_.model_file = resolved;
    study_.model_dir = fs::path(resolved).parent_path().string();
  }

  Override make_override(const InputNode& where, const std::string& path_text,
                         const YAML::Node& value) {
    ParameterPath path;
    try {
      path = parse_parameter_path(path_text);
    } catch (const std::invalid_argument& e) {
      where.fail(e.what());
    }
    const YAML::Node copy = with_records_resolved(where, path.text, YAML::Clone(value));
    return Override{path, copy, canonical_text(copy), where};
  }

  // The value with every record file in it (at a record path, or inside a map set at one of its
  // ancestors, e.g. ground_motion.L: {record: ...}) resolved relative to the study file.
  YAML::Node with_records_resolved(const InputNode& where, const std::string& path,
                                   const YAML::Node& value) {
    if (is_record_path(path)) {
      if (!value.IsScalar() || value.Scalar().empty()) where.fail("a record must be a file path");
      return YAML::Node(resolve_record(where, value.Scalar()));
    }
    if (!value.IsMap() || !path.starts_with("ground_motion")) return value;
    YAML::Node out(YAML::NodeType::Map);
    for (auto entry : value) {
      if (!entry.first.IsScalar()) return value;  // not a model key: the model reader says so
      out[entry.first.Scalar()] =
          with_records_resolved(where, path + "." + entry.first.Scalar(), entry.second);
    }
    return out;
  }

  // A record path relative to the study file, checked to exist; returns the absolute path.
  std::string resolve_record(const InputNode& where, const std::string& written) {
    fs::path path(written);
    if (path.is_relative()) path = fs::path(study_.dir) / path;
    path = path.lexically_normal();
    std::error_code ec;
    if (!fs::is_regular_file(path, ec)) where.fail("record file '" + path.string() + "' not found");
    const std::string relative =
        fs::path(path).lexically_relative(study_.dir.empty() ? "." : study_.dir).string();
    if (std::find(study_.record_files.begin(), study_.record_files.end(), relative) ==
        study_.record_files.end())
      study_.record_files.push_back(relative);
    return fs::absolute(path, ec).lexically_normal().string();
  }

  // {path: value, ...} as overrides, in file order.
  std::vector<Override> read_override_map(const InputNode& map) {
    if (!map.is_map())
      map.fail(
          "expected a map of parameter paths to values, e.g. {building.isolator.model: bilinear}");
    std::vector<Override> out;
    std::set<std::string> seen;
    for (const std::string& key : keys_of(map)) {
      const InputNode value = *map.find(key);
      Override o = make_override(value, key, value.yaml());
      if (!seen.insert(o.path.text).second) value.fail("'" + o.path.text + "' is set twice");
      out.push_back(std::move(o));
    }
    return out;
  }

  // Named sets of overrides: {label: {path: value, ...}, ...}.
  std::vector<Level> read_levels(const InputNode& map) {
    if (!map.is_map() || keys_of(map).empty())
      map.fail(
          "empty axis: expected named sets of overrides, e.g. {BL: {building.isolator.model: "
          "bilinear}}");
    std::vector<Level> levels;
    for (const std::string& label : keys_of(map)) {
      const InputNode overrides = *map.find(label);
      if (label.empty()) overrides.fail("a level needs a name");
      Level level;
      level.label = label;
      if (!overrides.yaml().IsNull())
        level.overrides = read_override_map(overrides);  // "free: {}" or "base:"
      levels.push_back(std::move(level));
    }
    return levels;
  }

  Level value_level(const InputNode& where, const ParameterPath& path, const YAML::Node& value) {
    Level level;
    level.overrides.push_back(make_override(where, path.text, value));
    if (!value.IsDefined() || value.IsNull()) {
      level.label = "none";
    } else if (is_record_path(path.text)) {
      level.label = fs::path(value.Scalar()).stem().string();
    } else if (value.IsSequence()) {
      level.label = canonical_text(value);  // "[0.6 m, 0 m]", a label
    } else {
      level.label = value.Scalar();
      try {
        const Quantity q = parse_quantity(value.Scalar());
        level.numeric = true;
        level.si = q.si;
        level.label = format_number(q.si);
      } catch (const UnitError&) {
        // a name ("bilinear"): kept as text
      }
    }
    return level;
  }

  std::vector<Level> read_range(const InputNode& range, const ParameterPath& path) {
    range.expect_keys({"from", "to", "step"});
    const InputNode from = range.required("from"), to = range.required("to"),
                    step = range.required("step");
    const auto quantity = [](const InputNode& node) {
      try {
        return parse_quantity(node.string());
      } catch (const UnitError& e) {
        node.fail(e.what());
      }
    };
    const Quantity a = quantity(from), b = quantity(to), h = quantity(step);
    const auto dimension = [](const Quantity& q) {
      return q.dimension == dim::kNone ? std::string("dimensionless")
                                       : "of dimension " + q.dimension.to_string();
    };
    for (const auto& [node, q] : {std::pair{&to, b}, std::pair{&step, h}}) {
      if (!(q.dimension == a.dimension))
        node->fail("unit mismatch: '" + node->string() + "' is " + dimension(q) + " but from: '" +
                   from.string() + "' is " + dimension(a));
    }
    if (h.si == 0.0) step.fail("the step must not be 0");
    if ((b.si > a.si && h.si < 0) || (b.si < a.si && h.si > 0))
      step.fail("step of wrong sign: going from '" + from.string() + "' to '" + to.string() +
                "' needs a " + (b.si > a.si ? "positive" : "negative") + " step (got '" +
                step.string() + "')");
    const double intervals = (b.si - a.si) / h.si;
    if (!(intervals < static_cast<double>(kMaxAxisValues)))
      step.fail("the range has more than " + std::to_string(kMaxAxisValues) + " values");
    const auto count = static_cast<std::int64_t>(std::floor(intervals + 1e-9)) + 1;
    std::string unit = si_unit_of(a.dimension);
    // Angles written in degrees are written back in degrees ("135 deg"), so that a case reads
    // exactly the angle a model file with that value gives (pounding amplifies a 1e-12 rad
    // difference to visible ones); their level is still the SI value, in rad.
    double scale = 1.0;
    if (const std::string written = from.string();
        written.ends_with("deg") || written.ends_with("\xC2\xB0")) {
      scale = 180.0 / std::numbers::pi;
      unit = "deg";
    } else if (written.ends_with("rad")) {
      unit = "rad";  // a bare angle is refused by the model reader (units.h, parse_angle)
    }
    std::vector<Level> levels;
    for (std::int64_t i = 0; i < count; ++i) {
      // %.12g drops the last bits of a + i h, so 1 cm + 3 x 0.05 cm is written 0.0115 m.
      char number[40];
      std::snprintf(number, sizeof number, "%.12g", (a.si + static_cast<double>(i) * h.si) * scale);
      const std::string text =
          unit.empty() ? std::string(number) : std::string(number) + " " + unit;
      levels.push_back(value_level(range, path, YAML::Node(text)));
    }
    return levels;
  }

  Axis read_axis(const InputNode& item, int group) {
    if (!item.is_map())
      item.fail("expected an axis {path, values | range} or {name, levels} or {zip: [...]}");
    item.expect_keys({"name", "path", "values", "range", "levels"});
    Axis axis{"", {}, group, item};
    if (const auto name = item.find("name")) {
      axis.name = name->string();
      if (!is_column_name(axis.name))
        name->fail("an axis name may hold letters, digits and '_' only (it names a column)");
    }
    if (const auto levels = item.find("levels")) {
      for (const char* key : {"path", "values", "range"})
        if (const auto other = item.find(key))
          other->fail("give either levels or path with values/range");
      if (axis.name.empty()) item.fail_at_key("name", "an axis with levels needs a name");
      axis.levels = read_levels(*levels);
      return axis;
    }
    const InputNode path_node = item.required("path");
    ParameterPath path;
    try {
      path = parse_parameter_path(path_node.string());
    } catch (const std::invalid_argument& e) {
      path_node.fail(e.what());
    }
    if (axis.name.empty()) {
      for (auto step = path.steps.rbegin(); step != path.steps.rend(); ++step)
        if (step->index < 0) {
          axis.name = column_name_of(step->key);
          break;
        }
      if (path.text == kRecordPath) axis.name = kRecordAxis;
    }
    const auto values = item.find("values");
    const auto range = item.find("range");
    if (values && range) range->fail("give either values or range, not both");
    if (!values && !range)
      item.fail_at_key("values", "missing 'values' (a list) or 'range' ({from, to, step})");
    if (values) {
      const std::vector<InputNode> list = values->elements();
      if (list.empty()) values->fail("empty axis: give at least one value");
      for (const InputNode& value : list) {
        const YAML::Node& v = value.yaml();
        // A value is a scalar, or a list of scalars such as a point [e_x, e_y].
        bool list_of_scalars = v.IsSequence() && v.size() > 0;
        if (v.IsSequence())
          for (const auto& item : v) list_of_scalars = list_of_scalars && item.IsScalar();
        if (v.IsDefined() && !v.IsNull() && !v.IsScalar() && !list_of_scalars)
          value.fail(
              "a value must be a single value or a list of values such as [0.6 m, 0 m] (use "
              "'levels' for named sets of overrides)");
        axis.levels.push_back(value_level(value, path, v));
      }
    } else {
      axis.levels = read_range(*range, path);
    }
    return axis;
  }

  std::vector<Level> read_records(const InputNode& node) {
    std::vector<Level> levels;
    if (node.is_sequence()) {
      const std::vector<InputNode> entries = node.elements();
      if (entries.empty()) node.fail("empty record set");
      for (const InputNode& entry : entries) read_record_set(entry, levels);
    } else {
      read_record_set(node, levels);
    }
    std::set<std::string> labels;
    for (const Level& level : levels)
      if (!labels.insert(level.label).second)
        level.overrides.front().where.fail("two records are named '" + level.label +
                                           "' (file name without extension): rename one");
    return levels;
  }

  // One entry of `records`: a path, or {file | files | folder + glob, components, scale, ...}.
  void read_record_set(const InputNode& entry, std::vector<Level>& levels) {
    std::vector<std::pair<InputNode, std::string>> files;  // where written, path
    std::vector<Override> options;
    std::vector<std::pair<std::string, InputNode>> components;
    if (!entry.is_map()) {
      files.emplace_back(entry, entry.string());
    } else {
      entry.expect_keys({"file", "files", "folder", "glob", "components", "scale", "format",
                         "column", "time_column", "dt", "unit", "L", "T", "name", "pairs", "swap"});
      if (entry.has("L") || entry.has("T") || entry.has("pairs")) {
        read_record_pairs(entry, levels);
        return;
      }
      if (const auto swap = entry.find("swap")) swap->fail("'swap' goes with 'pairs: rsn'");
      if (const auto name = entry.find("name"))
        name->fail(
            "'name' labels a record pair {L, T, name}; a single record is named by its file");
      const auto file = entry.find("file");
      const auto list = entry.find("files");
      const auto folder = entry.find("folder");
      const auto glob = entry.find("glob");
      if ((file ? 1 : 0) + (list ? 1 : 0) + (glob ? 1 : 0) != 1)
        entry.fail("give one of: file, files (a list), or folder with glob");
      if (file && folder) folder->fail("'folder' goes with 'glob' or 'files', not 'file'");
      fs::path base = study_.dir;
      if (folder) {
        base = fs::path(folder->string());
        if (base.is_relative()) base = fs::path(study_.dir) / base;
        std::error_code ec;
        if (!fs::is_directory(base, ec))
          folder->fail("folder '" + base.lexically_normal().string() + "' not found");
      }
      const auto relative_to_study = [&](const std::string& name) {
        return (folder ? (fs::path(folder->string()) / name) : fs::path(name)).string();
      };
      if (file) files.emplace_back(*file, file->string());
      if (list) {
        const std::vector<InputNode> items = list->elements();
        if (items.empty()) list->fail("empty list of record files");
        for (const InputNode& item : items)
          files.emplace_back(item, relative_to_study(item.string()));
      }
      if (glob) {
        const std::string pattern = glob->string();
        if (!folder) glob->fail("'glob' needs a 'folder'");
        std::vector<std::string> names;
        for (const auto& f : fs::directory_iterator(base))
          if (f.is_regular_file() && fnmatch(pattern.c_str(), f.path().filename().c_str(), 0) == 0)
            names.push_back(f.path().filename().string());
        std::sort(names.begin(),
                  names.end());  // the order of cases must not depend on the file system
        if (names.empty())
          glob->fail("no file in '" + base.lexically_normal().string() + "' matches '" + pattern +
                     "'");
        for (const std::string& name : names) files.emplace_back(*glob, relative_to_study(name));
      }
      for (const char* key : {"scale", "format", "column", "time_column", "dt", "unit"})
        if (const auto option = entry.find(key)) {
          if (!option->yaml().IsScalar()) option->fail("expected a single value");
          options.push_back(
              make_override(*option, std::string("ground_motion.") + key, option->yaml()));
        }
      if (const auto list_of_components = entry.find("components")) {
        if (entry.has("column")) list_of_components->fail("give either column or components");
        if (!list_of_components->is_map() || keys_of(*list_of_components).empty())
          list_of_components->fail("expected {name: column, ...}, e.g. {NS: 0, EW: 1}");
        for (const std::string& name : keys_of(*list_of_components)) {
          const InputNode column = *list_of_components->find(name);
          column.integer(0, std::numeric_limits<int>::max());
          if (!is_column_name(name))
            column.fail("a component name may hold letters, digits and '_' only");
          components.emplace_back(name, column);
        }
      }
    }
    if (model_is_3d())
      entry.fail(
          "the model is 3D (structures:): its records are pairs, {L: file, T: file, name: ...} "
          "or {folder, glob, pairs: rsn}");
    for (const auto& [where, written] : files) {
      Level level;
      level.overrides.push_back(make_override(where, kRecordPath, YAML::Node(written)));
      level.label = fs::path(written).stem().string();
      level.overrides.insert(level.overrides.end(), options.begin(), options.end());
      if (components.empty()) {
        levels.push_back(std::move(level));
        continue;
      }
      for (const auto& [name, column] : components) {
        Level component = level;
        component.label = level.label + "_" + name;
        component.overrides.push_back(make_override(column, "ground_motion.column", column.yaml()));
        levels.push_back(std::move(component));
      }
    }
  }

  // The base model has `structures:` (3D buildings).
  bool model_is_3d() const {
    if (study_.model.IsMap())
      for (auto entry : study_.model)
        if (entry.first.IsScalar() && entry.first.Scalar() == "structures") return true;
    return false;
  }

  // Record pairs for 3D models: {L: file, T: file, name, folder, scale, ...}, L and T possibly
  // maps {file, scale, format, column, time_column, dt, unit} with options of their own; or
  // {folder, glob, pairs: rsn, swap}: the matching files grouped by their PEER RSN (the name up to
  // its first '_'), two per RSN, L the first by name (the second with swap: true).
  void read_record_pairs(const InputNode& entry, std::vector<Level>& levels) {
    fs::path folder;
    if (const auto f = entry.find("folder")) {
      folder = f->string();
      const fs::path base = folder.is_relative() ? fs::path(study_.dir) / folder : folder;
      std::error_code ec;
      if (!fs::is_directory(base, ec))
        f->fail("folder '" + base.lexically_normal().string() + "' not found");
    }
    if (const auto how = entry.find("pairs")) {
      how->choice<int>({{"rsn", 0}});
      for (const char* key : {"file", "files", "components", "L", "T", "name"})
        if (const auto other = entry.find(key))
          other->fail(std::string("'") + key +
                      "' does not go with 'pairs': the pairs are the files 'glob' matches");
      const auto glob = entry.find("glob");
      if (!glob || !entry.has("folder"))
        how->fail("pairs: rsn pairs the files of a folder matching a glob: give folder and glob");
      const bool swap = entry.has("swap") && entry.find("swap")->boolean();
      const std::string pattern = glob->string();
      std::map<std::string, std::vector<std::string>> by_rsn;  // sorted: the order of cases
      const fs::path base = folder.is_relative() ? fs::path(study_.dir) / folder : folder;
      for (const auto& f : fs::directory_iterator(base)) {
        const std::string name = f.path().filename().string();
        if (f.is_regular_file() && fnmatch(pattern.c_str(), name.c_str(), 0) == 0)
          by_rsn[name.substr(0, std::min(name.find('_'), name.rfind('.')))].push_back(name);
      }
      if (by_rsn.empty())
        glob->fail("no file in '" + base.lexically_normal().string() + "' matches '" + pattern +
                   "'");
      for (auto& [rsn, files] : by_rsn) {
        std::sort(files.begin(), files.end());
        if (files.size() != 2) {
          std::string names;
          for (const std::string& n : files) names += (names.empty() ? "" : ", ") + n;
          glob->fail("pairs: rsn needs two files (L and T) per RSN; '" + rsn + "' has " +
                     std::to_string(files.size()) + ": " + names);
        }
        if (swap) std::swap(files[0], files[1]);
        levels.push_back(pair_level(entry, {*glob, *glob}, {nullptr, nullptr}, files, folder, rsn));
      }
      return;
    }
    if (const auto swap = entry.find("swap")) swap->fail("'swap' goes with 'pairs: rsn'");
    for (const char* key : {"file", "files", "glob", "components"})
      if (const auto other = entry.find(key))
        other->fail(std::string("'") + key +
                    "' belongs to single records; a pair is {L: file, T: file, name: ...}");
    const auto l = entry.find("L");
    const auto t = entry.find("T");
    if (!l || !t) entry.fail_at_key(l ? "T" : "L", "a record pair needs both components, L and T");
    std::vector<InputNode> file_nodes;
    std::vector<std::string> files;
    for (const InputNode& c : {*l, *t}) {
      if (c.is_map()) {
        c.expect_keys({"file", "scale", "format", "column", "time_column", "dt", "unit"});
        file_nodes.push_back(c.required("file"));
      } else if (c.yaml().IsScalar()) {
        file_nodes.push_back(c);
      } else {
        c.fail("expected a record file, or {file, scale, column, ...}");
      }
      files.push_back(file_nodes.back().string());
      if (files.back().empty()) file_nodes.back().fail("expected a record file");
    }
    std::string label =
        fs::path(files[0]).stem().string() + "+" + fs::path(files[1]).stem().string();
    if (const auto name = entry.find("name")) {
      label = name->string();
      if (label.empty()) name->fail("must not be empty");
    }
    levels.push_back(pair_level(entry, file_nodes, {&*l, &*t}, files, folder, label));
  }

  // The level of one pair: ground_motion.L and .T set, the single-component keys removed.
  Level pair_level(const InputNode& entry, const std::vector<InputNode>& file_nodes,
                   const std::vector<const InputNode*>& own_options,
                   const std::vector<std::string>& files, const fs::path& folder,
                   const std::string& label) {
    static constexpr const char* kOptions[] = {"scale",       "format", "column",
                                               "time_column", "dt",     "unit"};
    Level level;
    level.label = label;
    // A pair replaces a single-component motion (record or pulse) of the model. (Overrides hold
    // YAML handles: they are appended, never shifted by insert, which would assign into them.)
    for (const char* key :
         {"record", "pulse", "scale", "format", "column", "time_column", "dt", "unit"})
      level.overrides.push_back(Override{parse_parameter_path(std::string("ground_motion.") + key),
                                         YAML::Node(), "~", entry});
    for (std::size_t i = 0; i < 2; ++i) {
      YAML::Node component(YAML::NodeType::Map);
      component["record"] =
          resolve_record(file_nodes[i], folder.empty() ? files[i] : (folder / files[i]).string());
      for (const InputNode* options : {&entry, own_options[i]})  // the component's own win
        for (const char* key : kOptions)
          if (const auto option =
                  options && options->is_map() ? options->find(key) : std::nullopt) {
            if (!option->yaml().IsScalar()) option->fail("expected a single value");
            component[key] = option->string();
          }
      level.overrides.push_back(
          Override{parse_parameter_path(i == 0 ? "ground_motion.L" : "ground_motion.T"), component,
                   canonical_text(component), own_options[i] ? *own_options[i] : file_nodes[i]});
    }
    return level;
  }

  void check_axis_names() {
    for (std::size_t a = 0; a < study_.axes.size(); ++a) {
      const Axis& axis = study_.axes[a];
      if (axis.name.empty())
        axis.where.fail_at_key("name", "give the axis a name (it names a column)");
      if (is_reserved_column(axis.name))
        axis.where.fail_at_key(
            "name", "'" + axis.name + "' names a fixed column of the results; choose another name");
      for (std::size_t b = 0; b < a; ++b)
        if (study_.axes[b].name == axis.name)
          axis.where.fail_at_key(
              "name", "two axes are named '" + axis.name + "'" +
                          (axis.name == kRecordAxis || axis.name == kVariantAxis
                               ? " ('" + axis.name + "' is the axis of `" +
                                     (axis.name == kRecordAxis ? "records" : "variants") + "`)"
                               : "") +
                          ": give one a different `name:`");
    }
  }

  void add_output(const InputNode& where, const std::string& column, const std::string& selector) {
    try {
      parse_output_selector(selector);
    } catch (const std::invalid_argument& e) {
      where.fail(e.what());
    }
    if (!is_column_name(column))
      where.fail("column name '" + column + "' may hold letters, digits and '_' only");
    if (is_reserved_column(column) || study_.axis_index(column) >= 0)
      where.fail("column '" + column + "' is already used by " +
                 (is_reserved_column(column) ? std::string("a fixed column") : "an axis") +
                 "; name the peak with {name: selector}");
    for (const OutputSpec& o : study_.outputs)
      if (o.column == column)
        where.fail("two peaks give the column '" + column + "'; name one with {name: selector}");
    study_.outputs.push_back({column, selector, where});
  }

  // `ensemble: N` (study_ensemble.h): its columns must not clash with the study's own.
  void read_ensemble(const InputNode& node) {
    study_.ensemble = node.integer(2, 10000);
    std::vector<std::string> columns;
    for (const OutputSpec& o : study_.outputs) columns.push_back(o.column);
    for (const std::string& name : ensemble_column_names(columns)) {
      bool clash = is_reserved_column(name);
      for (const OutputSpec& o : study_.outputs) clash = clash || o.column == name;
      for (const Axis& a : study_.axes) clash = clash || a.name == name;
      if (clash) node.fail("the ensemble column '" + name + "' is already a column; rename it");
    }
  }

  void read_outputs(const std::optional<InputNode>& node, const InputNode& top) {
    if (!node) {
      for (const char* selector :
           {"base.displacement", "stories.drift_ratio", "floors.absolute_acceleration"})
        add_output(top, column_name_of(selector), selector);
      return;
    }
    if (node->is_map()) {
      for (const std::string& column : keys_of(*node))
        add_output(*node->find(column), column, node->find(column)->string());
    } else {
      for (const InputNode& item : node->elements()) {
        if (item.is_map()) {
          const std::vector<std::string> keys = keys_of(item);
          if (keys.size() != 1) item.fail("expected a selector or {column: selector}");
          add_output(*item.find(keys[0]), keys[0], item.find(keys[0])->string());
        } else {
          add_output(item, column_name_of(item.string()), item.string());
        }
      }
    }
    if (study_.outputs.empty())
      node->fail("no peaks to keep: list at least one, e.g. base.displacement");
  }

  void read_ratios(const InputNode& node) {
    if (!node.is_map())
      node.fail("expected {name: {ratio: [numerator, denominator], axis: variant}, ...}");
    for (const std::string& name : keys_of(node)) {
      const InputNode item = *node.find(name);
      item.expect_keys({"ratio", "axis"});
      RatioSpec r{name, kVariantAxis, "", ""};
      if (const auto axis = item.find("axis")) r.axis = axis->string();
      const int a = study_.axis_index(r.axis);
      if (a < 0)
        (item.has("axis") ? *item.find("axis") : item).fail("no axis named '" + r.axis + "'");
      const Axis& axis = study_.axes[a];
      int members = 0;
      for (const Axis& other : study_.axes) members += other.group == axis.group ? 1 : 0;
      if (members > 1) item.fail("ratios between levels of a zipped axis are not supported");
      const InputNode ratio = item.required("ratio");
      const std::vector<InputNode> pair = ratio.elements();
      if (pair.size() != 2)
        ratio.fail("expected [numerator, denominator], two labels of axis '" + r.axis + "'");
      r.numerator = pair[0].string();
      r.denominator = pair[1].string();
      for (const InputNode& label : pair) {
        const auto found = std::find_if(axis.levels.begin(), axis.levels.end(),
                                        [&](const Level& l) { return l.label == label.string(); });
        if (found == axis.levels.end()) {
          std::string labels;
          for (const Level& l : axis.levels) labels += (labels.empty() ? "" : ", ") + l.label;
          label.fail("axis '" + r.axis + "' has no level '" + label.string() +
                     "' (levels: " + labels + ")");
        }
      }
      if (r.numerator == r.denominator) ratio.fail("numerator and denominator are the same level");
      for (const Level& l : axis.levels)
        if (l.label == name)
          item.fail("'" + name + "' is also a level of axis '" + r.axis + "': choose another name");
      for (const RatioSpec& other : study_.ratios)
        if (other.name == name) item.fail("two ratios are named '" + name + "'");
      study_.ratios.push_back(r);
    }
  }

  void read_statistics(const std::optional<InputNode>& node) {
    if (!node) {
      if (study_.axis_index(kRecordAxis) >= 0) study_.statistics.push_back({{kRecordAxis}, true});
      return;
    }
    std::vector<InputNode> items;
    if (node->is_sequence())
      items = node->elements();
    else
      items.push_back(*node);
    for (const InputNode& item : items) {
      item.expect_keys({"over", "std"});
      StatisticsSpec s;
      const InputNode over = item.required("over");
      const std::vector<InputNode> names =
          over.is_sequence() ? over.elements() : std::vector<InputNode>{over};
      if (names.empty()) over.fail("name at least one axis to take statistics over");
      for (const InputNode& name : names) {
        if (study_.axis_index(name.string()) < 0) {
          std::string axes;
          for (const Axis& a : study_.axes) axes += (axes.empty() ? "" : ", ") + a.name;
          name.fail("no axis named '" + name.string() +
                    "' (axes: " + (axes.empty() ? "none" : axes) + ")");
        }
        if (std::find(s.over.begin(), s.over.end(), name.string()) != s.over.end())
          name.fail("named twice");
        s.over.push_back(name.string());
      }
      if (const auto std_kind = item.find("std"))
        s.sample_std = std_kind->choice<bool>({{"sample", true}, {"population", false}});
      study_.statistics.push_back(s);
    }
  }

  Study& study_;
};

}  // namespace

bool is_reserved_column(const std::string& name) {
  static const char* const kReserved[] = {
      "case_id", "status", "steps", "wall_seconds",   "session",       "error", "over", "output",
      "n",       "mean",   "std",   "mean_minus_std", "mean_plus_std", "min",   "max",  "median"};
  return std::any_of(std::begin(kReserved), std::end(kReserved),
                     [&](const char* r) { return name == r; });
}

std::vector<std::int64_t> Study::group_sizes() const {
  std::vector<std::int64_t> sizes(static_cast<std::size_t>(group_count), 1);
  for (const Axis& axis : axes) sizes[axis.group] = static_cast<std::int64_t>(axis.levels.size());
  return sizes;
}

std::int64_t Study::case_count() const {
  std::int64_t count = 1;
  for (const std::int64_t size : group_sizes()) count *= size;
  return count;
}

std::vector<int> Study::levels_of(std::int64_t case_id) const {
  const std::vector<std::int64_t> sizes = group_sizes();
  std::vector<int> digit(sizes.size(), 0);
  for (std::size_t g = sizes.size(); g-- > 0;) {
    digit[g] = static_cast<int>(case_id % sizes[g]);
    case_id /= sizes[g];
  }
  std::vector<int> levels(axes.size());
  for (std::size_t a = 0; a < axes.size(); ++a) levels[a] = digit[axes[a].group];
  return levels;
}

int Study::axis_index(const std::string& name) const {
  for (std::size_t a = 0; a < axes.size(); ++a)
    if (axes[a].name == name) return static_cast<int>(a);
  return -1;
}

Study load_study_file(const std::string& path) {
  Study study;
  study.file = path;
  study.dir = fs::path(path).parent_path().string();
  study.text = read_text(path);
  const YAML::Node root = parse_document(study.text, path);
  const InputNode top(root, path);
  if (!root.IsDefined() || root.IsNull())
    top.fail("the document is empty; expected a study (model, axes, ...)");
  try {
    StudyReader(study).read(top);
  } catch (const YAML::Exception& e) {
    throw InputError(path, line_of(e.mark), column_of(e.mark), "", "YAML error: " + e.msg);
  }
  return study;
}

}  // namespace isopound
