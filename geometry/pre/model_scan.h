// Reading a model for isopound-pre: the solver's reader (load_model) preceded by a lenient scan
// of the YAML that collects every slab, column and bearing placement problem (the reader stops
// at the first) and keeps the input nodes that later checks blame (file:line and key).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "geometry/pre/problems.h"
#include "solver/io/yaml_reader.h"
#include "solver/structures/config.h"

namespace isopound::pre {

// Where each part of a 3D structure is written (nodes of the model file), for messages.
struct StructureMarks {
  std::optional<InputNode> item;      // the list item of `structures:`
  std::optional<InputNode> storeys;   // `storeys:` (short form or list)
  std::vector<InputNode> storey;      // per storey: its list item, or `storeys:` (short form)
  std::optional<InputNode> base;      // `base:`
  std::optional<InputNode> bearings;  // `bearings:` list
  std::optional<InputNode> walls;     // `walls:`
  std::optional<InputNode> adjacent;  // `adjacent:`
};

struct ScannedModel {
  std::string path;
  std::optional<InputNode> root;
  bool is3d = false;
  std::vector<StructureMarks> structures;  // 3D, in the order of `structures:`
  // 2D: `building:`, its `floors:`, and each item of `neighbours:`.
  std::optional<InputNode> building, floors;
  std::vector<InputNode> neighbours;
  // The model as the solver reads it, when the reader got through (after the scan's repairs:
  // a column or bearing outside its slab is left out, a non-convex polygon replaced by its hull,
  // each reported as an error; the rest of the checks then still run).
  std::optional<ModelConfig> config;
};

// Reads `path`; every problem found goes to `problems` (the reader's first error among them
// when it stops). Never throws InputError.
ScannedModel scan_model(const std::string& path, ProblemList& problems);

}  // namespace isopound::pre
