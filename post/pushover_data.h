// A pushover read back from its directory: pushover.csv (the capacity-curve table, SI, columns by
// their header names) and pushover.json (what was pushed; the first-yield and capping rows).
// The only place in post/ that knows these two formats (written by solver/io/pushover_report.h).
#pragma once

#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace isopound::post {

class PushoverDataError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// A marked point of the curve: a data row of pushover.csv (0-based, header not counted) and that
// row's values (taken from the CSV, so that a marker lies exactly on the drawn curve).
struct PushoverPoint {
  int row = -1;
  double roof_displacement = 0.0;  // m, along the push
  double roof_drift_ratio = 0.0;   // roof displacement / building height
  double base_shear = 0.0;         // N, along the push
};

struct PushoverData {
  std::filesystem::path dir;
  // From pushover.json.
  std::string model_file, building, pattern;  // pattern: "first_mode" | "uniform"
  int dimension = 2;                          // 2 or 3
  double angle_deg = 0.0;                     // 3D: direction of the push from the plan's x axis
  double target_drift_ratio = 0.0;
  double height = 0.0;  // m, the building's height above its foundation
  std::optional<PushoverPoint> first_yield, capping;
  // From pushover.csv: header names and values per column, per row.
  std::vector<std::string> columns;
  std::vector<std::vector<double>> values;
  int storeys = 0;  // number of consecutive story<k>_drift_ratio columns, k = 1, 2, ...

  std::size_t rows() const { return values.empty() ? 0 : values[0].size(); }
  int find(const std::string& name) const;  // column index, -1 when absent
  // The named column; throws PushoverDataError naming pushover.csv when absent.
  const std::vector<double>& column(const std::string& name) const;
  const std::vector<double>& roof_displacement() const { return column("roof_displacement_m"); }
  const std::vector<double>& roof_drift_ratio() const { return column("roof_drift_ratio"); }
  const std::vector<double>& base_shear() const { return column("base_shear_N"); }

  // An isolated building's split of the roof displacement (docs/yielding-storeys.md): the
  // superstructure's drift, the storeys' drifts story<k>_drift_m summed (the roof relative to the
  // base slab; with isolation_level k > 0 the substructure's storeys too), and the bearings'
  // share, the roof displacement less that sum. Each storey's drift is taken at its upper
  // level's centre of mass, so the split is exact when the levels' centres of mass lie on one
  // vertical line. A fixed-base building's bearings' share is 0 (up to the CSV's 10 digits).
  std::vector<double> superstructure_drift() const;
  std::vector<double> bearing_displacement() const;
  // The bearings' share exceeds kIsolatedShare of the roof displacement at some row.
  bool isolated() const;
  static constexpr double kIsolatedShare = 0.01;
};

// Reads DIR/pushover.csv and DIR/pushover.json. Throws PushoverDataError naming the file (and the
// line, column or key) when a file is missing or unreadable, a required column or key is absent,
// a number is malformed, a marked row is outside the table, or the two files disagree (columns,
// or a point's values against its row).
PushoverData read_pushover(const std::filesystem::path& dir);

}  // namespace isopound::post
