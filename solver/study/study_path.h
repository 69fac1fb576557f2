// Parameter paths of a study: "building.isolator.uy", "building.floors[2].mass" address a node
// of the model's YAML tree; an override sets (or, with a null value, removes) the node there.
#pragma once

#include <yaml-cpp/yaml.h>

#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace isopound {

// A key path into a YAML tree. Same spelling as the key paths of model-input errors.
struct ParameterPath {
  struct Step {
    std::string key;  // a map key, or empty for a list index
    int index = -1;   // >= 0 for a list index "[i]"
  };
  std::vector<Step> steps;
  std::string text;  // canonical spelling, e.g. "building.floors[2].mass"

  bool operator==(const ParameterPath& other) const { return text == other.text; }
};

// Parses "a.b[2].c". Throws std::invalid_argument naming what is wrong.
ParameterPath parse_parameter_path(std::string_view text);

// True if `prefix` addresses `path` itself or one of its ancestors (by whole steps).
bool is_prefix_of(const ParameterPath& prefix, const ParameterPath& path);

// Sets the node at `path` in the tree `root` to a deep copy of `value` (a null or undefined
// value removes the key). Missing map keys on the way are created as maps; lists are never
// extended. Throws std::invalid_argument when the path runs through a value or a list by key,
// or indexes past the end of a list.
void apply_override(YAML::Node root, const ParameterPath& path, const YAML::Node& value);

// A record file of the ground motion: "ground_motion.record", or a component's of a 3D model's
// pair, "ground_motion.L.record" / "ground_motion.T.record". Such paths are written relative to
// the study file, and setting one drops the built-in pulse beside it (and the other way round).
bool is_record_path(const std::string& path_text);

// The position of the deepest existing node on `path` in a parsed tree (for error messages);
// a null mark if even the first step is missing.
YAML::Mark locate(const YAML::Node& root, const ParameterPath& path);

}  // namespace isopound
