// A finished run read back from its directory: histories.csv (columns by the names in the header)
// and summary.json, plus the model geometry (story heights, walls, neighbours). The only place
// that knows the output formats: adapt here when summary.json or histories.csv change.
#pragma once

#include <filesystem>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "post/contact_log.h"
#include "post/site3d.h"

namespace isopound::post {

class RunDataError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// A history column "<label> <quantity> [<unit>]", e.g. "3-storey/floor 1 a_abs [m/s2]".
struct ColumnName {
  std::string label, quantity, unit;
};
ColumnName parse_column_name(const std::string& header);

// A level of a structure (base slab or floor) with its history columns.
struct Level {
  std::string label;               // "3-storey/floor 1"
  double elevation = 0.0;          // m above the ground (base slab: 0)
  int u = -1, v = -1, a_abs = -1;  // column indices (-1: absent); 3D: the x DOF's
  // 3D runs: the y and theta DOFs' displacement and absolute acceleration columns.
  int u_y = -1, theta = -1, a_abs_y = -1, a_abs_theta = -1;
  int body = -1;  // 3D: index into RunData::site.bodies
};

struct Structure {
  std::string name;
  std::vector<Level> levels;  // bottom to top
  // Placement in the x-z drawing: +1 the main building, or a neighbour's side (+1 right, -1 left).
  bool neighbour = false;
  int side = 0;
  double gap = 0.0;  // m, neighbours: clear distance to the main building at rest
};

// An element output group: isolator (force, deformation) or contact (force, penetration, ...).
struct ElementColumns {
  std::string label;
  bool contact = false;
  int force = -1, deformation = -1, penetration = -1, indentation = -1;
  // 3D bearings: components (force and deformation above are the resultants).
  int force_x = -1, force_y = -1, deformation_x = -1, deformation_y = -1;
};

// A moat wall next to a level of the main building.
struct Wall {
  std::string label;       // the contact's label, "" when not found among the outputs
  int side = +1;           // +1 right of the building, -1 left
  double gap = 0.0;        // m at rest
  double elevation = 0.0;  // m, of the level it faces
  bool gap_known = true;   // false: inferred, see run_geometry notes
  int u = -1;              // flexible wall: its own displacement column ("<label> structure u")
};

struct RunData {
  std::filesystem::path dir;
  std::vector<std::string> columns;         // header names as written
  std::vector<std::vector<double>> values;  // per column, per row
  nlohmann::json summary;                   // null when summary.json is absent
  std::vector<Structure> structures;        // main building first
  std::vector<ElementColumns> isolators, contacts;
  std::vector<Wall> walls;
  std::vector<std::string> notes;  // what could not be found and was assumed
  // 3D runs (DOF columns "<structure>/<level> (x) u [m]"): the plan geometry from the model file
  // and the contact-event log (empty without contact_events.csv).
  bool three_d = false;
  Site3D site;
  ContactLog contact_log;
  // 3D: the friction coefficients of each pair of the contact log as the model sets them (the
  // contact law's; a bumper's contacts: its rubber's), by pair label. Absent: no friction
  // (contact.friction false).
  struct Friction {
    double mu_static = 0.0, mu_kinetic = 0.0;
  };
  std::map<std::string, Friction> friction;

  std::size_t rows() const { return values.empty() ? 0 : values[0].size(); }
  int find(const std::string& label, const std::string& quantity) const;  // -1 when absent
  const std::vector<double>& column(int index) const { return values.at(index); }
  const std::vector<double>& time() const { return values.at(0); }
  std::string unit_of(int index) const { return parse_column_name(columns.at(index)).unit; }
};

// The friction coefficients of the 3D contact pair labelled `pair` as `config` sets them
// (RunData::friction): a bumper's contacts ("<A>|<face> bumper", "... bumper bottomed") its
// rubber's, every other pair the contact law's; nullopt when contact.friction is false.
std::optional<RunData::Friction> pair_friction(const ModelConfig& config, const std::string& pair);

// Reads RUN_DIR. `model_file` overrides the model named in summary.json (for wall gaps and
// neighbour placement); without either, wall gaps are inferred from the contact histories.
// Throws RunDataError naming the file (and line) on anything missing or malformed.
RunData read_run(const std::filesystem::path& dir, const std::string& model_file = "");

// step-accelerations.csv (a run with output.floor_spectra: true): the time, the ground's and every
// DOF's absolute acceleration at every accepted analysis step, the columns named as in
// histories.csv. A time may repeat (a step cut at an event: the values before and after).
struct StepTable {
  std::vector<std::string> columns;
  std::vector<std::vector<double>> values;    // per column, per step
  int find(const std::string& column) const;  // -1 when absent
  const std::vector<double>& time() const { return values.at(0); }
};
// Read on demand (the file holds every step): nullopt when the run has none. Throws RunDataError.
std::optional<StepTable> read_step_accelerations(const RunData& run);

// Linear interpolation of a column at time t (clamped to the recorded span).
double value_at(const RunData& run, int column, double t);

}  // namespace isopound::post
