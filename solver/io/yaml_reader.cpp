// Typed reads from a YAML tree with file:line:key errors (see yaml_reader.h).
// yaml-cpp 0.7: never index a missing key (InvalidNode, no position); look keys up by iterating.
#include "solver/io/yaml_reader.h"

#include "solver/io/plausibility.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <limits>
#include <mutex>
#include <numbers>
#include <optional>
#include <set>
#include <sstream>
#include <unordered_map>

namespace isopound {
namespace {

std::string format_message(const std::string& file, int line, int column, const std::string& key,
                           const std::string& what) {
  std::string out = file;
  if (line > 0) {
    out += ":" + std::to_string(line);
    if (column > 0) out += ":" + std::to_string(column);
  }
  out += ": ";
  if (!key.empty()) out += key + ": ";
  return out + what;
}

bool has_position(const YAML::Mark& mark) {
  return !mark.is_null() && mark.line >= 0;
}

// Node::Mark() throws on an invalid node; such nodes simply have no position.
YAML::Mark mark_of(const YAML::Node& node) {
  return node.IsDefined() ? node.Mark() : YAML::Mark::null_mark();
}

std::string lower(std::string_view s) {
  std::string out(s);
  for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

std::string join(const std::vector<std::string_view>& names) {
  std::string out;
  for (const auto& name : names) {
    if (!out.empty()) out += ", ";
    out += name;
  }
  return out;
}

// Case-insensitive edit distance, for "did you mean" on misspelt keys.
std::size_t edit_distance(std::string_view a_text, std::string_view b_text) {
  const std::string a = lower(a_text), b = lower(b_text);
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t above = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = above;
    }
  }
  return row[b.size()];
}

// "building.walls[1].k" -> "building.walls.k": the schema does not care which list item.
std::string generic_path(std::string_view path) {
  std::string out;
  for (std::size_t i = 0; i < path.size(); ++i) {
    if (path[i] == '[') {
      while (i < path.size() && path[i] != ']') ++i;
      continue;
    }
    out += path[i];
  }
  return out;
}

std::mutex& registry_mutex() {
  static std::mutex m;
  return m;
}
std::set<std::string>& registry() {
  static std::set<std::string> keys;
  return keys;
}
std::set<std::string>& accepted_registry() {
  static std::set<std::string> keys;
  return keys;
}
std::vector<std::pair<std::string, Dimension>>& quantity_registry() {
  static std::vector<std::pair<std::string, Dimension>> keys;
  return keys;
}

void register_quantity_key(const std::string& key, const Dimension& d) {
  const std::lock_guard<std::mutex> lock(registry_mutex());
  auto& keys = quantity_registry();
  for (const auto& [k, dimension] : keys)
    if (k == key && dimension == d) return;
  keys.emplace_back(key, d);
}

std::string format_si(double value, const Dimension& d) {
  std::ostringstream os;
  os.precision(6);
  os << value;
  static const std::pair<Dimension, const char*> kUnits[] = {
      {dim::kLength, "m"},      {dim::kMass, "kg"},           {dim::kTime, "s"},
      {dim::kVelocity, "m/s"},  {dim::kAcceleration, "m/s2"}, {dim::kForce, "N"},
      {dim::kStiffness, "N/m"}, {dim::kDamping, "N s/m"}};
  if (d == dim::kNone) return os.str();
  for (const auto& [dimension, unit] : kUnits)
    if (d == dimension) return os.str() + " " + unit;
  return os.str() + " (SI, " + d.to_string() + ")";
}

}  // namespace

// The ledger of one tracked read: every map reached, the keys looked up in it, the choices made
// in it ("law: hertz") and the defaults used.
struct KeyLedger {
  struct Map {
    YAML::Node node;
    std::string path;
    std::vector<std::string> used;
    std::vector<std::string> choices;
  };
  std::vector<Map> maps;
  std::unordered_map<std::string, std::size_t> index;  // path -> maps[i]: a lookup is O(1)
  std::vector<DefaultUsed> defaults;
  std::vector<std::string> warnings;

  Map& at(const std::string& path, const YAML::Node& node) {
    const auto [it, added] = index.try_emplace(path, maps.size());
    if (added) maps.push_back(Map{node, path, {}, {}});
    return maps[it->second];
  }
  Map* find(const std::string& path) {
    const auto it = index.find(path);
    return it == index.end() ? nullptr : &maps[it->second];
  }
};

std::vector<std::string> known_model_keys() {
  const std::lock_guard<std::mutex> lock(registry_mutex());
  return {registry().begin(), registry().end()};
}

std::vector<std::pair<std::string, Dimension>> known_quantity_keys() {
  const std::lock_guard<std::mutex> lock(registry_mutex());
  return quantity_registry();
}

std::vector<std::string> known_accepted_keys() {
  const std::lock_guard<std::mutex> lock(registry_mutex());
  return {accepted_registry().begin(), accepted_registry().end()};
}

InputError::InputError(std::string file, int line, int column, std::string key, std::string what)
    : std::runtime_error(format_message(file, line, column, key, what)),
      file_(std::move(file)),
      line_(line),
      column_(column),
      key_(std::move(key)),
      detail_(std::move(what)) {}

InputNode::InputNode(YAML::Node root, std::string file)
    : InputNode(std::move(root), std::move(file), "", YAML::Mark::null_mark(),
                YAML::Mark::null_mark(), nullptr) {}

InputNode::InputNode(YAML::Node node, std::string file, std::string path, YAML::Mark key_mark,
                     YAML::Mark parent_mark, std::shared_ptr<KeyLedger> ledger)
    : node_(std::move(node)),
      file_(std::move(file)),
      path_(std::move(path)),
      key_mark_(key_mark),
      parent_mark_(parent_mark),
      ledger_(std::move(ledger)) {
  if (ledger_ && node_.IsDefined() && node_.IsMap()) ledger_->at(path_, node_);
}

InputNode InputNode::tracked(YAML::Node root, std::string file) {
  return InputNode(std::move(root), std::move(file), "", YAML::Mark::null_mark(),
                   YAML::Mark::null_mark(), std::make_shared<KeyLedger>());
}

void InputNode::note_used(std::string_view key) const {
  if (!ledger_) return;
  KeyLedger::Map& m = ledger_->at(path_, node_);
  if (std::find(m.used.begin(), m.used.end(), key) == m.used.end()) m.used.emplace_back(key);
  const std::lock_guard<std::mutex> lock(registry_mutex());
  registry().insert(generic_path(child_path(key)));
}

void InputNode::note_choice(const std::string& text) const {
  if (!ledger_) return;
  const std::size_t dot = path_.find_last_of('.');
  const std::string parent = dot == std::string::npos ? "" : path_.substr(0, dot);
  const std::string key = dot == std::string::npos ? path_ : path_.substr(dot + 1);
  if (key.find('[') != std::string::npos) return;  // a list item is not a key of a map
  if (KeyLedger::Map* m = ledger_->find(parent)) m->choices.push_back(key + ": " + text);
}

void InputNode::note_default(std::string_view key, std::string value) const {
  if (!ledger_) return;
  ledger_->defaults.push_back({child_path(key), std::move(value)});
}

std::vector<DefaultUsed> InputNode::defaults_used() const {
  return ledger_ ? ledger_->defaults : std::vector<DefaultUsed>{};
}

std::vector<std::string> InputNode::warnings() const {
  return ledger_ ? ledger_->warnings : std::vector<std::string>{};
}

std::vector<std::string> InputNode::used_keys() const {
  std::set<std::string> keys;
  if (ledger_)
    for (const KeyLedger::Map& m : ledger_->maps)
      for (const std::string& key : m.used)
        keys.insert(generic_path(m.path.empty() ? key : m.path + "." + key));
  return {keys.begin(), keys.end()};
}

void InputNode::refuse_unused() const {
  if (!ledger_) return;
  struct Unused {
    const KeyLedger::Map* map;
    std::string key;
    YAML::Mark mark;
  };
  std::optional<Unused> first;
  for (const KeyLedger::Map& m : ledger_->maps) {
    if (!m.node.IsDefined() || !m.node.IsMap()) continue;
    for (const auto& entry : m.node) {
      if (!entry.first.IsScalar()) continue;
      if (!entry.second.IsDefined() || entry.second.IsNull()) continue;  // null = absent
      const std::string& key = entry.first.Scalar();
      if (std::find(m.used.begin(), m.used.end(), key) != m.used.end()) continue;
      const YAML::Mark mark = mark_of(entry.first);
      const auto before = [](const YAML::Mark& a, const YAML::Mark& b) {
        if (!has_position(b)) return has_position(a);
        return has_position(a) && (a.line < b.line || (a.line == b.line && a.column < b.column));
      };
      if (!first || before(mark, first->mark)) first = Unused{&m, key, mark};
    }
  }
  if (!first) return;
  const KeyLedger::Map& m = *first->map;
  std::string why = "'" + first->key + "' is not used";
  if (!m.choices.empty()) {
    std::string choices;
    for (const auto& c : m.choices) choices += (choices.empty() ? "" : ", ") + c;
    why += " with " + choices;
  } else if (!m.path.empty()) {
    why += " here";
  }
  std::vector<std::string_view> used(m.used.begin(), m.used.end());
  std::string_view suggestion;
  std::size_t best = 3;
  for (const auto& candidate : used) {
    const std::size_t d = edit_distance(first->key, candidate);
    if (d < best && d < std::max(first->key.size(), candidate.size())) {
      best = d;
      suggestion = candidate;
    }
  }
  if (!suggestion.empty()) why += " (did you mean '" + std::string(suggestion) + "'?)";
  why += "; " + (m.path.empty() ? std::string("the file") : m.path) +
         " uses: " + (used.empty() ? std::string("nothing else") : join(used)) +
         ". Remove it (a study override can set it to ~)";
  const std::string key = m.path.empty() ? first->key : m.path + "." + first->key;
  fail_at(file_, has_position(first->mark) ? first->mark : mark_of(m.node), key, why);
}

// A scalar's own mark is where its text is. A null value's mark is wherever the next token
// starts (often the next line), and a block map's is its first key: prefer the key for those.
YAML::Mark InputNode::mark() const {
  const YAML::Mark own = mark_of(node_);
  if (node_.IsDefined() && node_.IsScalar() && has_position(own)) return own;
  if (has_position(key_mark_)) return key_mark_;
  if (has_position(own)) return own;
  return parent_mark_;
}

void InputNode::fail_at(const std::string& file, const YAML::Mark& mark, const std::string& key,
                        const std::string& what) {
  if (!has_position(mark)) throw InputError(file, 0, 0, key, what);
  throw InputError(file, mark.line + 1, mark.column + 1, key, what);
}

void InputNode::fail(const std::string& what) const {
  fail_at(file_, mark(), path_, what);
}

InputError InputNode::error(const std::string& what) const {
  const YAML::Mark m = mark();
  if (!has_position(m)) return InputError(file_, 0, 0, path_, what);
  return InputError(file_, m.line + 1, m.column + 1, path_, what);
}

void InputNode::fail_at_key(std::string_view key, const std::string& what) const {
  fail_at(file_, mark(), child_path(key), what);
}

std::string InputNode::child_path(std::string_view key) const {
  return path_.empty() ? std::string(key) : path_ + "." + std::string(key);
}

std::string InputNode::kind() const {
  if (!node_.IsDefined() || node_.IsNull()) return "an empty value";
  if (node_.IsMap()) return "a map";
  if (node_.IsSequence()) return "a list";
  return "'" + node_.Scalar() + "'";
}

void InputNode::expect_keys(std::initializer_list<std::string_view> allowed) const {
  expect_keys(std::vector<std::string_view>(allowed));
}

void InputNode::expect_keys(const std::vector<std::string_view>& names) const {
  if (ledger_) {
    const std::lock_guard<std::mutex> lock(registry_mutex());
    for (const auto& name : names) accepted_registry().insert(generic_path(child_path(name)));
  }
  if (!node_.IsDefined() || node_.IsNull()) {
    if (path_.empty()) fail("the document is empty; expected a map with keys: " + join(names));
    return;
  }
  if (!node_.IsMap()) fail("expected a map with keys: " + join(names) + "; got " + kind());
  std::vector<std::pair<std::string, YAML::Mark>> seen;
  for (const auto& entry :
       node_) {  // by value per element: it->first would dangle (iterator proxy)
    const YAML::Node& key = entry.first;
    YAML::Mark key_mark = mark_of(key);
    if (!has_position(key_mark)) key_mark = mark();
    if (!key.IsScalar())
      fail_at(file_, key_mark, path_,
              "keys must be plain names, got " + InputNode(key, file_).kind());
    const std::string& name = key.Scalar();
    for (const auto& [previous, previous_mark] : seen) {
      if (previous != name) continue;
      const std::string first_line =
          has_position(previous_mark)
              ? " (first at line " + std::to_string(previous_mark.line + 1) + ")"
              : "";
      fail_at(file_, key_mark, child_path(name), "duplicate key '" + name + "'" + first_line);
    }
    seen.emplace_back(name, key_mark);
    if (std::find(names.begin(), names.end(), name) != names.end()) continue;
    std::string_view suggestion;
    std::size_t best = 3;  // close spellings only: at most 2 edits, and fewer edits than letters
    for (const auto& candidate : names) {
      const std::size_t d = edit_distance(name, candidate);
      if (d < best && d < std::max(name.size(), candidate.size())) {
        best = d;
        suggestion = candidate;
      }
    }
    const std::string hint =
        suggestion.empty() ? "" : " (did you mean '" + std::string(suggestion) + "'?)";
    fail_at(file_, key_mark, child_path(name),
            "unknown key '" + name + "'" + hint + "; allowed: " + join(names));
  }
}

std::optional<InputNode> InputNode::find(std::string_view key) const {
  note_used(key);
  if (!node_.IsDefined() || !node_.IsMap()) return std::nullopt;
  for (const auto& entry : node_) {
    if (!entry.first.IsScalar() || entry.first.Scalar() != key) continue;
    if (ledger_ && (!entry.second.IsDefined() || entry.second.IsNull())) return std::nullopt;
    return InputNode(entry.second, file_, child_path(key), mark_of(entry.first), mark(), ledger_);
  }
  return std::nullopt;
}

bool InputNode::has(std::string_view key) const {
  return find(key).has_value();
}

bool InputNode::written(std::string_view key) const {
  if (!node_.IsDefined() || !node_.IsMap()) return false;
  for (const auto& entry : node_)
    if (entry.first.IsScalar() && entry.first.Scalar() == key)
      return entry.second.IsDefined() && !entry.second.IsNull();
  return false;
}

InputNode InputNode::required(std::string_view key) const {
  std::optional<InputNode> child = find(key);
  if (!child) fail_at_key(key, "missing required key '" + std::string(key) + "'");
  return *child;
}

InputNode InputNode::empty_child(std::string_view key) const {
  return InputNode(YAML::Node(), file_, child_path(key), YAML::Mark::null_mark(), mark(), ledger_);
}

std::vector<InputNode> InputNode::elements() const {
  if (!node_.IsDefined() || !node_.IsSequence()) fail("expected a list, got " + kind());
  std::vector<InputNode> out;
  out.reserve(node_.size());
  const YAML::Mark here = mark();
  for (const auto& element : node_)
    out.push_back(InputNode(element, file_, path_ + "[" + std::to_string(out.size()) + "]",
                            YAML::Mark::null_mark(), here, ledger_));
  return out;
}

std::string InputNode::string() const {
  if (!node_.IsDefined() || node_.IsNull()) fail("missing value");
  if (!node_.IsScalar()) fail("expected a single value, got " + kind());
  return node_.Scalar();
}

double InputNode::quantity(const Dimension& expected, Bound bound) const {
  if (node_.IsDefined() && (node_.IsMap() || node_.IsSequence()))
    fail("expected a number with an optional unit (e.g. '340 t', '2 s', '5 %'), got " + kind());
  const std::string text = string();
  double value = 0.0;
  bool has_unit = false;
  try {
    value = parse_quantity_as(text, expected);
    has_unit = parse_quantity(text).has_unit;
  } catch (const UnitError& e) {
    fail(e.what());
  }
  const std::string got = " (got '" + text + "')";
  switch (bound) {
    case Bound::kAny:
      break;
    case Bound::kPositive:
      if (!(value > 0.0)) fail("must be > 0" + got);
      break;
    case Bound::kNonNegative:
      if (!(value >= 0.0)) fail("must be >= 0" + got);
      break;
    case Bound::kNonZero:
      if (value == 0.0) fail("must not be 0" + got);
      break;
    case Bound::kFraction:
      if (!(value >= 0.0 && value < 1.0)) fail("must be in [0, 1), e.g. '5 %' or 0.05" + got);
      break;
  }
  if (ledger_) check_plausibility(expected, value, text, has_unit);
  return value;
}

// The plausibility table (plausibility.h) for tracked reads: an impossible value is an error,
// an implausible one a warning kept in the ledger. Registers the key as numeric.
void InputNode::check_plausibility(const Dimension& expected, double value, const std::string& text,
                                   bool has_unit) const {
  register_quantity_key(generic_path(path_), expected);
  const PlausibilityVerdict verdict = check_plausible(path_, expected, value, text, has_unit);
  if (verdict.level == Plausibility::kError) fail(verdict.message);
  if (verdict.level == Plausibility::kWarning) {
    const YAML::Mark m = mark();
    std::string warning = InputError(file_, has_position(m) ? m.line + 1 : 0,
                                     has_position(m) ? m.column + 1 : 0, path_, verdict.message)
                              .what();
    auto& all = ledger_->warnings;
    if (std::find(all.begin(), all.end(), warning) == all.end()) all.push_back(std::move(warning));
  }
}

double InputNode::angle() const {
  if (node_.IsDefined() && (node_.IsMap() || node_.IsSequence()))
    fail("expected an angle with its unit (e.g. '30 deg'), got " + kind());
  const std::string text = string();
  double value = 0.0;
  try {
    value = parse_angle(text);
  } catch (const UnitError& e) {
    fail(e.what());
  }
  if (ledger_) register_quantity_key(generic_path(path_), dim::kNone);
  return value;
}

int InputNode::integer(int min, int max) const {
  if (node_.IsDefined() && (node_.IsMap() || node_.IsSequence()))
    fail("expected an integer, got " + kind());
  const std::string text = string();
  std::string_view digits = text;
  while (!digits.empty() && std::isspace(static_cast<unsigned char>(digits.back())))
    digits.remove_suffix(1);
  if (digits.starts_with("+")) digits.remove_prefix(1);
  long long value = 0;
  const auto [ptr, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
  if (digits.empty() || ec != std::errc() || ptr != digits.data() + digits.size())
    fail("expected an integer, got '" + text + "'");
  if (value < min || value > max) {
    const std::string range =
        max == std::numeric_limits<int>::max()
            ? ">= " + std::to_string(min)
            : "between " + std::to_string(min) + " and " + std::to_string(max);
    fail("must be " + range + " (got " + text + ")");
  }
  return static_cast<int>(value);
}

bool InputNode::boolean() const {
  if (node_.IsDefined() && (node_.IsMap() || node_.IsSequence()))
    fail("expected true or false, got " + kind());
  const std::string text = lower(string());
  if (text == "true" || text == "yes" || text == "on") return true;
  if (text == "false" || text == "no" || text == "off") return false;
  fail("expected true or false, got '" + string() + "'");
}

void InputNode::read_quantity(std::string_view key, const Dimension& expected, Bound bound,
                              double& out) const {
  if (const auto child = find(key))
    out = child->quantity(expected, bound);
  else
    note_default(key, format_si(out, expected));
}
void InputNode::read_number(std::string_view key, Bound bound, double& out) const {
  if (const auto child = find(key))
    out = child->number(bound);
  else
    note_default(key, format_si(out, dim::kNone));
}
void InputNode::read_angle(std::string_view key, double& out) const {
  if (const auto child = find(key))
    out = child->angle();
  else
    note_default(key, format_si(out * 180.0 / std::numbers::pi, dim::kNone) + " deg");
}
void InputNode::read_integer(std::string_view key, int min, int max, int& out) const {
  if (const auto child = find(key))
    out = child->integer(min, max);
  else
    note_default(key, std::to_string(out));
}
void InputNode::read_boolean(std::string_view key, bool& out) const {
  if (const auto child = find(key))
    out = child->boolean();
  else
    note_default(key, out ? "true" : "false");
}
void InputNode::read_string(std::string_view key, std::string& out) const {
  if (const auto child = find(key))
    out = child->string();
  else
    note_default(key, out);
}

std::size_t InputNode::choice_index(std::span<const std::string_view> names) const {
  const std::string text = string();
  for (std::size_t i = 0; i < names.size(); ++i)
    if (names[i] == text) {
      note_choice(text);
      return i;
    }
  fail_unknown_choice(text, {names.begin(), names.end()});
}

void InputNode::fail_unknown_choice(const std::string& text,
                                    const std::vector<std::string_view>& names) const {
  const std::size_t dot = path_.find_last_of('.');
  std::string noun = dot == std::string::npos ? path_ : path_.substr(dot + 1);
  if (noun.empty()) noun = "value";
  fail("unknown " + noun + " '" + text + "'; allowed: " + join(names));
}

}  // namespace isopound
