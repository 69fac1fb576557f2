// Reading a pushover directory (see pushover_data.h).
#include "post/pushover_data.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>

#include "post/contact_log.h"  // split_csv

namespace fs = std::filesystem;

namespace isopound::post {

int PushoverData::find(const std::string& name) const {
  const auto it = std::find(columns.begin(), columns.end(), name);
  return it == columns.end() ? -1 : static_cast<int>(it - columns.begin());
}

const std::vector<double>& PushoverData::column(const std::string& name) const {
  const int c = find(name);
  if (c < 0)
    throw PushoverDataError((dir / "pushover.csv").string() + ":1: no column '" + name +
                            "' in the header");
  return values[static_cast<std::size_t>(c)];
}

std::vector<double> PushoverData::superstructure_drift() const {
  std::vector<double> sum(rows(), 0.0);
  for (int k = 1; k <= storeys; ++k) {
    const std::vector<double>& d = column("story" + std::to_string(k) + "_drift_m");
    for (std::size_t i = 0; i < sum.size(); ++i) sum[i] += d[i];
  }
  return sum;
}

std::vector<double> PushoverData::bearing_displacement() const {
  std::vector<double> b = superstructure_drift();
  const std::vector<double>& roof = roof_displacement();
  for (std::size_t i = 0; i < b.size(); ++i) b[i] = roof[i] - b[i];
  return b;
}

bool PushoverData::isolated() const {
  if (storeys == 0) return false;
  const std::vector<double> b = bearing_displacement();
  const std::vector<double>& roof = roof_displacement();
  for (std::size_t i = 0; i < b.size(); ++i)
    if (std::abs(b[i]) > kIsolatedShare * std::abs(roof[i])) return true;
  return false;
}

namespace {

// The columns every pushover.csv starts with.
constexpr const char* kRequired[] = {"roof_displacement_m", "roof_drift_ratio", "base_shear_N"};

void read_table(PushoverData& d, const fs::path& path) {
  std::ifstream in(path);
  if (!in)
    throw PushoverDataError(path.string() +
                            ": cannot open (write it with `isopound pushover MODEL -o DIR`)");
  const auto chomp = [](std::string& line) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
  };
  std::string line;
  if (!std::getline(in, line)) throw PushoverDataError(path.string() + ":1: empty file");
  chomp(line);
  d.columns = split_csv(line);
  d.values.assign(d.columns.size(), {});
  for (const char* name : kRequired) d.column(name);  // throws naming the missing one
  int line_no = 1;
  while (std::getline(in, line)) {
    ++line_no;
    chomp(line);
    if (line.empty()) continue;
    const auto cells = split_csv(line);
    if (cells.size() != d.columns.size())
      throw PushoverDataError(path.string() + ":" + std::to_string(line_no) + ": " +
                              std::to_string(cells.size()) + " values, the header has " +
                              std::to_string(d.columns.size()));
    for (std::size_t c = 0; c < cells.size(); ++c) {
      char* end = nullptr;
      const double v = std::strtod(cells[c].c_str(), &end);
      if (cells[c].empty() || *end != '\0' || !std::isfinite(v))
        throw PushoverDataError(path.string() + ":" + std::to_string(line_no) + ": column '" +
                                d.columns[c] + "': not a number: '" + cells[c] + "'");
      d.values[c].push_back(v);
    }
  }
  if (d.rows() < 2) throw PushoverDataError(path.string() + ": fewer than 2 data rows");
  while (d.find("story" + std::to_string(d.storeys + 1) + "_drift_ratio") >= 0) ++d.storeys;
}

// Key `key` of the object j, or an error naming the file and the key.
const nlohmann::json& key_of(const nlohmann::json& j, const std::string& key, const fs::path& path,
                             const std::string& where = "") {
  if (!j.is_object() || !j.contains(key))
    throw PushoverDataError(path.string() + ": no key '" + where + key + "'");
  return j.at(key);
}

double number_of(const nlohmann::json& j, const std::string& key, const fs::path& path,
                 const std::string& where = "") {
  const nlohmann::json& v = key_of(j, key, path, where);
  if (!v.is_number())
    throw PushoverDataError(path.string() + ": '" + where + key + "': not a number");
  return v.get<double>();
}

// A marked point: null, or {row, roof_displacement_m, roof_drift_ratio, base_shear_N} whose row is
// a data row of the table and whose values are that row's.
std::optional<PushoverPoint> point_of(const nlohmann::json& j, const std::string& name,
                                      const PushoverData& d, const fs::path& path) {
  const nlohmann::json& p = key_of(j, name, path);
  if (p.is_null()) return std::nullopt;
  const std::string where = name + ".";
  const double row = number_of(p, "row", path, where);
  if (!(row >= 0.0 && row < static_cast<double>(d.rows())) || row != std::floor(row))
    throw PushoverDataError(path.string() + ": '" + where + "row' " + p.at("row").dump() +
                            " is not a data row of " + (d.dir / "pushover.csv").string() +
                            " (0 to " + std::to_string(d.rows() - 1) + ")");
  PushoverPoint pt;
  pt.row = static_cast<int>(row);
  pt.roof_displacement = d.roof_displacement()[pt.row];
  pt.roof_drift_ratio = d.roof_drift_ratio()[pt.row];
  pt.base_shear = d.base_shear()[pt.row];
  // The JSON repeats the row's values (full precision; the CSV has 10 digits): a mismatch means
  // the two files are not of the same run.
  const std::pair<const char*, const std::vector<double>*> checks[] = {
      {"roof_displacement_m", &d.roof_displacement()}, {"base_shear_N", &d.base_shear()}};
  for (const auto& [key, col] : checks) {
    const double json_value = number_of(p, key, path, where);
    double scale = 0.0;
    for (double v : *col) scale = std::max(scale, std::abs(v));
    if (std::abs(json_value - (*col)[pt.row]) > 1e-6 * scale)
      throw PushoverDataError(path.string() + ": '" + where + key + "' " + p.at(key).dump() +
                              " differs from row " + std::to_string(pt.row) + " of " +
                              (d.dir / "pushover.csv").string() +
                              " (are the two files of the same pushover?)");
  }
  return pt;
}

void read_description(PushoverData& d, const fs::path& path) {
  std::ifstream in(path);
  if (!in)
    throw PushoverDataError(path.string() +
                            ": cannot open (write it with `isopound pushover MODEL -o DIR`)");
  nlohmann::json j;
  try {
    j = nlohmann::json::parse(in);
  } catch (const nlohmann::json::exception& e) {
    throw PushoverDataError(path.string() + ": not valid JSON (" + e.what() + ")");
  }
  if (!j.is_object()) throw PushoverDataError(path.string() + ": not a JSON object");
  const auto text = [&](const std::string& key) {
    const nlohmann::json& v = key_of(j, key, path);
    if (!v.is_string()) throw PushoverDataError(path.string() + ": '" + key + "': not a string");
    return v.get<std::string>();
  };
  d.building = text("building");
  d.pattern = text("pattern");
  if (j.contains("model_file") && j.at("model_file").is_string()) d.model_file = text("model_file");
  const double dimension = number_of(j, "dimension", path);
  if (dimension != 2.0 && dimension != 3.0)
    throw PushoverDataError(path.string() + ": 'dimension' must be 2 or 3");
  d.dimension = static_cast<int>(dimension);
  d.height = number_of(j, "height_m", path);
  if (j.contains("angle_deg")) d.angle_deg = number_of(j, "angle_deg", path);
  if (j.contains("target_drift_ratio"))
    d.target_drift_ratio = number_of(j, "target_drift_ratio", path);
  if (j.contains("columns") && j.at("columns") != nlohmann::json(d.columns))
    throw PushoverDataError(path.string() + ": 'columns' differ from the header of " +
                            (d.dir / "pushover.csv").string() +
                            " (are the two files of the same pushover?)");
  d.first_yield = point_of(j, "first_yield", d, path);
  d.capping = point_of(j, "capping", d, path);
}

}  // namespace

PushoverData read_pushover(const fs::path& dir) {
  if (!fs::is_directory(dir))
    throw PushoverDataError(dir.string() + ": pushover directory not found");
  PushoverData d;
  d.dir = dir;
  read_table(d, dir / "pushover.csv");
  read_description(d, dir / "pushover.json");
  return d;
}

}  // namespace isopound::post
