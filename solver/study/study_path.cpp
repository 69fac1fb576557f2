// Parameter paths on YAML trees (see study_path.h). yaml-cpp 0.7 pitfalls kept in mind: a Node
// variable is a handle (walk with reset(), never `node = child`), and missing keys are never
// indexed.
#include "solver/study/study_path.h"

#include <cctype>
#include <charconv>

namespace isopound {
namespace {

// "[i]", built by appending: "[" + std::string trips GCC 12's false -Wrestrict at -O3.
std::string index_text(int index) {
  std::string out(1, '[');
  out += std::to_string(index);
  out += ']';
  return out;
}

bool is_key_char(char c) {
  return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_' || c == '-';
}

// The child of map `node` under `key`, or an invalid node (found by iteration, not indexing).
YAML::Node find_child(const YAML::Node& node, const std::string& key) {
  for (auto entry : node)
    if (entry.first.IsScalar() && entry.first.Scalar() == key) return entry.second;
  return YAML::Node(YAML::NodeType::Undefined);
}

std::string describe(const YAML::Node& node) {
  if (node.IsSequence()) return "a list";
  if (node.IsScalar()) return "a value ('" + node.Scalar() + "')";
  return "an empty value";
}

}  // namespace

bool is_record_path(const std::string& path_text) {
  return path_text == "ground_motion.record" || path_text == "ground_motion.L.record" ||
         path_text == "ground_motion.T.record";
}

ParameterPath parse_parameter_path(std::string_view text) {
  ParameterPath path;
  std::size_t i = 0;
  const auto fail = [&](const std::string& what) -> void {
    throw std::invalid_argument("bad parameter path '" + std::string(text) + "': " + what);
  };
  if (text.empty()) fail("empty");
  while (i < text.size()) {
    std::size_t start = i;
    while (i < text.size() && is_key_char(text[i])) ++i;
    if (i == start) fail("expected a key name at character " + std::to_string(start + 1));
    path.steps.push_back({std::string(text.substr(start, i - start)), -1});
    while (i < text.size() && text[i] == '[') {
      const std::size_t close = text.find(']', i);
      if (close == std::string_view::npos) fail("missing ']'");
      int index = -1;
      const auto [ptr, ec] = std::from_chars(text.data() + i + 1, text.data() + close, index);
      if (ec != std::errc() || ptr != text.data() + close || index < 0)
        fail("a list index must be an integer >= 0, e.g. floors[2]");
      path.steps.push_back({"", index});
      i = close + 1;
    }
    if (i == text.size()) break;
    if (text[i] != '.') fail("unexpected '" + std::string(1, text[i]) + "'");
    ++i;
    if (i == text.size()) fail("ends with '.'");
  }
  for (const ParameterPath::Step& step : path.steps) {
    if (step.index >= 0)
      path.text += index_text(step.index);
    else
      path.text += (path.text.empty() ? "" : ".") + step.key;
  }
  return path;
}

bool is_prefix_of(const ParameterPath& prefix, const ParameterPath& path) {
  if (prefix.steps.size() > path.steps.size()) return false;
  for (std::size_t i = 0; i < prefix.steps.size(); ++i)
    if (prefix.steps[i].key != path.steps[i].key || prefix.steps[i].index != path.steps[i].index)
      return false;
  return true;
}

void apply_override(YAML::Node root, const ParameterPath& path, const YAML::Node& value) {
  const bool remove = !value.IsDefined() || value.IsNull();
  YAML::Node node;
  node.reset(root);
  std::string walked;
  for (std::size_t s = 0; s < path.steps.size(); ++s) {
    const ParameterPath::Step& step = path.steps[s];
    const bool last = s + 1 == path.steps.size();
    const std::string here = walked.empty() ? "the model" : walked;
    if (step.index >= 0) {
      if (!node.IsSequence())
        throw std::invalid_argument(here + " is " + describe(node) +
                                    ", not a list: cannot index it with " + index_text(step.index));
      if (static_cast<std::size_t>(step.index) >= node.size())
        throw std::invalid_argument(here + " has " + std::to_string(node.size()) +
                                    " items: " + index_text(step.index) + " does not exist");
      if (last) {
        if (remove)
          throw std::invalid_argument("a list item cannot be removed (" + path.text + ")");
        node[step.index] = YAML::Clone(value);
        return;
      }
      YAML::Node child = node[step.index];
      node.reset(child);
      walked += index_text(step.index);
      continue;
    }
    if (node.IsNull() && !remove) node = YAML::Node(YAML::NodeType::Map);  // "walls:" left empty
    if (!node.IsMap()) {
      if (!node.IsDefined() && remove) return;
      const std::string hint =
          node.IsSequence() ? " (address an item as " + here + "[i]." + step.key + ")" : "";
      throw std::invalid_argument(here + " is " + describe(node) + ", not a map: cannot set '" +
                                  step.key + "' inside it" + hint);
    }
    YAML::Node child = find_child(node, step.key);
    if (last) {
      if (remove) {
        if (child.IsDefined()) node.remove(step.key);
      } else {
        node[step.key] = YAML::Clone(value);
      }
      return;
    }
    if (!child.IsDefined()) {
      if (remove) return;  // nothing to remove below a missing key
      node[step.key] = YAML::Node(YAML::NodeType::Map);
      child = find_child(node, step.key);
    }
    node.reset(child);
    walked += (walked.empty() ? "" : ".") + step.key;
  }
}

// Read-only on a tree other threads read too: iteration only (non-const operator[] writes).
YAML::Mark locate(const YAML::Node& root, const ParameterPath& path) {
  YAML::Mark best = YAML::Mark::null_mark();
  YAML::Node node;
  node.reset(root);
  for (const ParameterPath::Step& step : path.steps) {
    if (step.index >= 0) {
      if (!node.IsSequence() || static_cast<std::size_t>(step.index) >= node.size()) break;
      int i = 0;
      for (auto item : node) {
        if (i++ != step.index) continue;
        YAML::Node child = item;
        node.reset(child);
        break;
      }
      best = node.Mark();
      continue;
    }
    if (!node.IsMap()) break;
    YAML::Node child(YAML::NodeType::Undefined);
    for (auto entry : node) {
      if (entry.first.IsScalar() && entry.first.Scalar() == step.key) {
        best = entry.first.Mark();  // the key's own line reads best in a message
        child.reset(entry.second);
        break;
      }
    }
    if (!child.IsDefined()) break;
    node.reset(child);
  }
  return best;
}

}  // namespace isopound
