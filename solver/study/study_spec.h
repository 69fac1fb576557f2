// A parametric study as written in its YAML file: base model, record set, sweep axes, variants,
// peaks to keep, ratios and statistics. Cases are the product of axis groups, the last fastest.
#pragma once

#include <yaml-cpp/yaml.h>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "solver/io/yaml_reader.h"
#include "solver/study/study_path.h"

namespace isopound {

// One change to the base model: the node at `path` becomes `value` (null: the key is removed).
struct Override {
  ParameterPath path;
  YAML::Node value;       // owned deep copy; record paths already resolved to absolute paths
  std::string canonical;  // value as text, for telling identical models apart
  InputNode where;        // where it is written in the study file; where.fail(...) reports there
};

// One value of an axis: its label in the results table and the overrides it applies.
struct Level {
  std::string label;     // "0.0105", "bilinear", "RSN1084_NORTHR_SCS052", "BL"
  bool numeric = false;  // label is a number (stored as REAL, in SI)
  double si = 0.0;       // the number, when numeric
  std::vector<Override> overrides;
};

struct Axis {
  std::string name;  // column of the results table
  std::vector<Level> levels;
  int group = 0;  // axes of one group (a zip) advance together
  InputNode where;
};

// A peak kept per run: column name and selector (grammar in study_outputs.h).
struct OutputSpec {
  std::string column;
  std::string selector;
  InputNode where;
};

// Rows "numerator / denominator" between two levels of one axis, the other axes equal.
struct RatioSpec {
  std::string name;  // written in the axis column of the ratio rows
  std::string axis;
  std::string numerator;  // level labels
  std::string denominator;
};

// Statistics over the axes `over` (grouped by all other axes).
struct StatisticsSpec {
  std::vector<std::string> over;
  bool sample_std = true;  // std with n - 1 (sample) or n (population)
};

struct Study {
  std::string file;  // as given
  std::string dir;   // directory of the file (relative paths in it start here)
  std::string name;
  std::string text;  // the file's text (hashed into the database)

  // Base model: parsed tree with marks, where its errors point to, and how relative
  // record paths inside it resolve.
  YAML::Node model;
  std::string model_file;  // the model file, or the study file for an inline model
  std::string model_dir;
  std::string model_text;                // text of a separate model file ("" for inline)
  std::optional<InputNode> model_where;  // the `model:` entry of the study file

  std::vector<Override> fixed;  // `set:` — applied to every case first
  std::vector<Axis> axes;       // in enumeration order: record, axes..., variant
  int group_count = 0;          // groups 0..group_count-1, product over groups, last fastest
  std::vector<OutputSpec> outputs;
  std::vector<RatioSpec> ratios;
  std::vector<StatisticsSpec> statistics;
  int ensemble = 0;  // `ensemble: N`: members per case (study_ensemble.h); 0 = one run per case
  std::vector<std::string> record_files;  // record files in use, relative to the study dir (hash)

  std::int64_t case_count() const;
  // Number of levels of each group.
  std::vector<std::int64_t> group_sizes() const;
  // Level index of every axis for case `case_id` (0 <= case_id < case_count()).
  std::vector<int> levels_of(std::int64_t case_id) const;
  int axis_index(const std::string& name) const;  // -1 if none
};

// Reads and checks a study file. Every problem is an InputError "file:line:col: key: what".
// Models of the cases are not built here (see study_cases.h).
Study load_study_file(const std::string& path);

// Names that cannot be axis or output columns (fixed columns of the tables).
bool is_reserved_column(const std::string& name);

}  // namespace isopound
