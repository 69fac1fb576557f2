// Typed reads from a YAML tree (quantity, number, integer, bool, string, enum) whose errors name
// "file:line:col: key.path: what". yaml-cpp marks are 0-based; here lines/columns are 1-based, 0 =
// unknown.
#pragma once

#include <yaml-cpp/yaml.h>

#include <initializer_list>
#include <memory>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "solver/io/units.h"

namespace isopound {

// An input problem: message is "file:line:col: key.path: what" (line, col 1-based). With line 0
// (no position known) it is "file: key.path: what"; an empty key drops "key.path: ".
class InputError : public std::runtime_error {
 public:
  InputError(std::string file, int line, int column, std::string key, std::string what);
  const std::string& file() const { return file_; }
  int line() const { return line_; }
  int column() const { return column_; }
  const std::string& key() const { return key_; }
  const std::string& detail() const { return detail_; }  // the "what" part alone

 private:
  std::string file_;
  int line_;
  int column_;
  std::string key_;
  std::string detail_;
};

// Reads a whole input file; a missing, unreadable or directory path, or one over InputLimits
// (yaml_document.h: read no further), is an InputError. `expected` names it ("a YAML model file").
std::string read_input_file(const std::string& path, std::string_view expected);
// Parses text holding one YAML document (none gives a null node). A syntax error, a second document
// ("---") or a passed InputLimits is an InputError at its line; `what` names the file's kind.
YAML::Node parse_single_document(const std::string& text, const std::string& path,
                                 std::string_view what);

// Bounds checked by InputNode::quantity/number, with the message they give.
enum class Bound {
  kAny,
  kPositive,     // > 0
  kNonNegative,  // >= 0
  kNonZero,      // != 0
  kFraction,     // in [0, 1): damping ratios
};

// A default the reader used for a key that was not written: shown in the run's settings.
struct DefaultUsed {
  std::string key;    // full key path, "building.walls.e"
  std::string value;  // as it acts, SI with its unit ("0.7", "500000 kg")
};

struct KeyLedger;  // what a tracked read looked up (yaml_reader.cpp)

// Every key path a tracked read has ever looked up in this process, list indices dropped
// ("building.walls.k_h", "neighbours.building.floors.mass"): the reader's own schema.
std::vector<std::string> known_model_keys();
// Every key path a tracked read has read as a quantity or number, with the dimension read
// (angles as dimensionless): the numeric part of the schema, for the plausibility tests.
std::vector<std::pair<std::string, Dimension>> known_quantity_keys();
// Every key path a tracked read has accepted (expect_keys), written or not, list indices
// dropped: what the readers accept, for the plausibility tests.
std::vector<std::string> known_accepted_keys();

// A node of an input file together with its key path ("building.floors[1].mass") and the
// nearest known position. Nodes built in code have no mark: errors then point at the nearest
// parent that has one, or at line 0.
class InputNode {
 public:
  // The root of a document; `file` is used in messages only.
  InputNode(YAML::Node root, std::string file);
  // The root of a document read under the one rule for keys: a null value ("walls: ~") is the
  // same as an absent key; every key looked up (find, has, required, read_*) counts as used,
  // and refuse_unused() then refuses any other key of every map read, naming what the section
  // uses. Defaults taken by read_* for absent keys are collected (defaults_used()).
  static InputNode tracked(YAML::Node root, std::string file);

  const YAML::Node& yaml() const { return node_; }
  const std::string& file() const { return file_; }
  const std::string& path() const { return path_; }  // "" for the root
  bool is_map() const { return node_.IsMap(); }
  bool is_sequence() const { return node_.IsSequence(); }

  // --- structure ---
  // Checks this is a map whose keys are all in `allowed`, each once (catches typos). An empty
  // value ("analysis:" with every key commented out) counts as an empty map, except at the root.
  void expect_keys(std::initializer_list<std::string_view> allowed) const;
  void expect_keys(const std::vector<std::string_view>& allowed) const;
  bool has(std::string_view key) const;
  // Whether this map holds `key` with a non-null value, without counting it as used (a rule that
  // asks whether a key was given before it decides to read it).
  bool written(std::string_view key) const;
  std::optional<InputNode> find(std::string_view key) const;
  // Throws "missing required key" at this node's position when absent.
  InputNode required(std::string_view key) const;
  // An absent key as an empty value (same ledger): its section's defaults are then noted.
  InputNode empty_child(std::string_view key) const;
  // The elements of a sequence, as "path[i]".
  std::vector<InputNode> elements() const;

  // --- typed reads of this node, which must be a scalar ---
  // A quantity with an optional unit ("340 t"); a bare number is SI of `expected`.
  double quantity(const Dimension& expected, Bound bound = Bound::kAny) const;
  // A dimensionless number; "5 %" and "0.05" both give 0.05.
  double number(Bound bound = Bound::kAny) const { return quantity(dim::kNone, bound); }
  // An angle in rad; the text must say deg or rad (a bare number is refused, naming both
  // readings: parse_angle in units.h).
  double angle() const;
  int integer(int min, int max) const;
  bool boolean() const;  // true/false, yes/no, on/off
  std::string string() const;
  // One of the named values: choice<Model>({{"linear", kLinear}, ...}).
  template <typename T>
  T choice(std::initializer_list<std::pair<std::string_view, T>> options) const {
    const std::string text = string();
    std::vector<std::string_view> names;
    for (const auto& [name, value] : options) {
      if (name == text) {
        note_choice(text);
        return value;
      }
      names.push_back(name);
    }
    fail_unknown_choice(text, names);
  }
  // One of the names of a table (hysteresis_model_names()): its index in `names`.
  std::size_t choice_index(std::span<const std::string_view> names) const;

  // --- optional keys of this map: each sets `out` only when `key` is present; when it is
  // absent, a tracked read records `out` as the default used (note_default) ---
  template <typename T>
  void read_choice(std::string_view key,
                   std::initializer_list<std::pair<std::string_view, T>> options, T& out) const {
    if (const auto child = find(key)) {
      out = child->choice<T>(options);
      return;
    }
    for (const auto& [name, value] : options)
      if (value == out) return note_default(key, std::string(name));
  }
  void read_quantity(std::string_view key, const Dimension& expected, Bound bound,
                     double& out) const;
  void read_number(std::string_view key, Bound bound, double& out) const;
  void read_angle(std::string_view key, double& out) const;
  void read_integer(std::string_view key, int min, int max, int& out) const;
  void read_boolean(std::string_view key, bool& out) const;
  void read_string(std::string_view key, std::string& out) const;

  // --- the one rule for keys (tracked reads only; no-ops otherwise) ---
  // Throws an InputError for the first key, in file order, that no read looked up, in any map
  // reached from this root.
  void refuse_unused() const;
  // Records that `key` of this map was absent and `value` is used instead.
  void note_default(std::string_view key, std::string value) const;
  std::vector<DefaultUsed> defaults_used() const;
  // Legal but implausible values read so far (plausibility.h), "file:line:col: key: what".
  std::vector<std::string> warnings() const;
  // Every key path looked up so far, list indices dropped ("building.walls.k"), sorted.
  std::vector<std::string> used_keys() const;

  // --- errors ---
  std::string kind() const;  // for messages: "a map", "a list", "an empty value", "'text'"
  [[noreturn]] void fail(const std::string& what) const;
  // The error fail(what) throws, not thrown (a warning located at this node).
  InputError error(const std::string& what) const;
  // An error about the key `key` of this map (which may be absent), at this node's position.
  [[noreturn]] void fail_at_key(std::string_view key, const std::string& what) const;

 private:
  InputNode(YAML::Node node, std::string file, std::string path, YAML::Mark key_mark,
            YAML::Mark parent_mark, std::shared_ptr<KeyLedger> ledger);
  void note_used(std::string_view key) const;
  void note_choice(const std::string& text) const;
  void check_plausibility(const Dimension& expected, double value, const std::string& text,
                          bool has_unit) const;
  YAML::Mark mark() const;  // the best known 0-based position, possibly null
  std::string child_path(std::string_view key) const;
  [[noreturn]] void fail_unknown_choice(const std::string& text,
                                        const std::vector<std::string_view>& names) const;
  [[noreturn]] static void fail_at(const std::string& file, const YAML::Mark& mark,
                                   const std::string& key, const std::string& what);

  YAML::Node node_;
  std::string file_;
  std::string path_;
  YAML::Mark
      key_mark_;  // where the key naming this node is written; null for the root and list items
  YAML::Mark parent_mark_;             // the parent's best known position, the fallback
  std::shared_ptr<KeyLedger> ledger_;  // null: an untracked read (study files)
};

}  // namespace isopound
