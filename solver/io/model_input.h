// Reading a model file (YAML) into ModelConfig: every quantity through the unit parser, every
// value checked; an input problem is an InputError "file:line:col: key.path: what" (yaml_reader.h).
#pragma once

#include <string>
#include <vector>

#include "solver/io/yaml_reader.h"
#include "solver/structures/config.h"

namespace isopound {

class ProblemList;  // solver/io/problems.h

// Reads and parses the file. A missing or unreadable file is an InputError with line 0; a YAML
// syntax error one at the line yaml-cpp reports. Relative record paths are taken from the file's
// directory.
ModelConfig load_model_file(const std::string& path);

// Parses an already-loaded YAML tree. source_name is used in messages, base_dir resolves
// relative record paths (absolute ones are kept).
// `used_keys` (optional) receives every key path the reader looked up for this model (the keys its
// choices of model, law and format use), list indices dropped.
// The site checks (site_checks.h) run once the structures are read: their errors are thrown
// together (InputErrors), or, when `site_problems` is given (isopound-pre), collected there and
// the reading goes on.
ModelConfig load_model(const YAML::Node& root, const std::string& source_name,
                       const std::string& base_dir, std::vector<std::string>* used_keys = nullptr,
                       ProblemList* site_problems = nullptr);

// The impact-law keys of a 2D wall or neighbour (law, k, e, ...), also the 3D contact's option.
ImpactLawUses read_impact_law(const InputNode& node, ImpactLawConfig& config);

}  // namespace isopound
