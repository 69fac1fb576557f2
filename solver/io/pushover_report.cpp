// pushover.csv and pushover.json (pushover_report.h).
#include "solver/io/pushover_report.h"

#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>
#include <numbers>
#include <stdexcept>

namespace isopound {

void write_pushover_csv(const std::string& path, const BuildingPushoverResult& r) {
  std::FILE* f = std::fopen(path.c_str(), "w");
  if (!f) throw std::runtime_error("cannot write " + path);
  for (std::size_t c = 0; c < r.columns.size(); ++c)
    std::fprintf(f, "%s%s", c ? "," : "", r.columns[c].c_str());
  std::fputc('\n', f);
  for (const auto& row : r.rows) {
    for (std::size_t c = 0; c < row.size(); ++c) std::fprintf(f, "%s%.10g", c ? "," : "", row[c]);
    std::fputc('\n', f);
  }
  if (std::fclose(f) != 0) throw std::runtime_error("error writing " + path);
}

void write_pushover_json(const std::string& path, const std::string& model_file,
                         const BuildingPushoverOptions& options, const BuildingPushoverResult& r) {
  const auto point = [&](int row) -> nlohmann::ordered_json {
    if (row < 0) return nullptr;
    const auto& values = r.rows[static_cast<std::size_t>(row)];
    return {{"row", row},
            {"roof_displacement_m", values[0]},
            {"roof_drift_ratio", values[1]},
            {"base_shear_N", values[2]}};
  };
  nlohmann::ordered_json j;
  j["model_file"] = model_file;
  j["building"] = r.building;
  j["dimension"] = r.dimension;
  j["pattern"] = pattern_name(options.pattern);
  j["angle_deg"] = options.angle * 180.0 / std::numbers::pi;
  j["target_drift_ratio"] = options.target_drift_ratio;
  j["height_m"] = r.height;
  j["steps"] = options.steps;
  j["columns"] = r.columns;
  j["first_yield"] = point(r.first_yield_row);
  j["capping"] = point(r.capping_row);
  std::ofstream out(path);
  out << j.dump(2) << '\n';
  if (!out) throw std::runtime_error("error writing " + path);
}

}  // namespace isopound
