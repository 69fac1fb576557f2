// Reading a model for isopound-pre: the solver's reader (load_model), whose site checks
// (solver/io/site_checks.h) collect every problem here rather than stop at the first, preceded by
// a scan that replaces a non-convex plan by its hull (reported as the reader does) so that the
// reader gets through; and the input nodes that isopound-pre's own warnings blame.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "solver/io/problems.h"
#include "solver/io/site_checks.h"
#include "solver/io/yaml_reader.h"
#include "solver/structures/config.h"

namespace isopound::pre {

struct ScannedModel {
  std::string path;
  std::optional<InputNode> root;
  bool is3d = false;
  std::vector<StructureMarks> structures;  // 3D, in the order of `structures:`
  // 2D: `building:`, its `floors:`, and each item of `neighbours:`.
  std::optional<InputNode> building, floors;
  std::vector<InputNode> neighbours;
  // The model as the solver reads it, when the reader got through (after the scan's repair of a
  // non-convex polygon, reported as an error; the site checks' errors are in the problems).
  std::optional<ModelConfig> config;
};

// Reads `path`; every problem found goes to `problems` (the reader's first error among them
// when it stops). Never throws InputError.
ScannedModel scan_model(const std::string& path, ProblemList& problems);

}  // namespace isopound::pre
