// Reading a run directory (see run_data.h).
#include "post/run_data.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <optional>
#include <sstream>

#include "post/contact_log.h"
#include "solver/io/model_input.h"
#include "solver/structures/config3d.h"
#include "solver/structures/pounding2d.h"
#include "solver/structures/pounding3d.h"

namespace fs = std::filesystem;

namespace isopound::post {
namespace {

// A summary number that may be written as a bare number or as {value, unit}.
std::optional<double> number_of(const nlohmann::json& j, const std::string& key) {
  if (!j.is_object() || !j.contains(key)) return std::nullopt;
  const auto& v = j.at(key);
  if (v.is_number()) return v.get<double>();
  if (v.is_object() && v.contains("value") && v.at("value").is_number())
    return v.at("value").get<double>();
  return std::nullopt;
}

// Story heights of a structure by story label, from summary.json.
std::map<std::string, double> story_heights(const nlohmann::json& summary) {
  std::map<std::string, double> h;
  if (!summary.is_object() || !summary.contains("structures")) return h;
  for (const auto& s : summary.at("structures"))
    if (s.contains("stories"))
      for (const auto& st : s.at("stories")) {
        const auto height =
            number_of(st, "height_m") ? number_of(st, "height_m") : number_of(st, "height");
        if (st.contains("label") && height) h[st.at("label").get<std::string>()] = *height;
      }
  return h;
}

// Isolated above a storey (summary.json, docs/isolation-level.md): structure name -> (k, h).
std::map<std::string, std::pair<int, double>> isolation_levels(const nlohmann::json& summary) {
  std::map<std::string, std::pair<int, double>> out;
  if (!summary.is_object() || !summary.contains("structures")) return out;
  for (const auto& s : summary.at("structures"))
    if (s.contains("isolation_level") && s.contains("name")) {
      const auto h = number_of(s, "isolation_height_m");
      out[s.at("name").get<std::string>()] = {s.at("isolation_level").get<int>(), h ? *h : 0.0};
    }
  return out;
}

// A table of numbers with a header line whose first column is time [s] (histories.csv,
// step-accelerations.csv).
void read_table(const fs::path& path, std::vector<std::string>& columns,
                std::vector<std::vector<double>>& values) {
  std::ifstream in(path);
  if (!in) throw RunDataError(path.string() + ": cannot open (is this a run directory?)");
  std::string line;
  if (!std::getline(in, line)) throw RunDataError(path.string() + ":1: empty file");
  columns = split_csv(line);
  if (columns.empty() || parse_column_name(columns[0]).quantity != "time")
    throw RunDataError(path.string() + ":1: the first column must be time [s]");
  values.assign(columns.size(), {});
  int line_no = 1;
  while (std::getline(in, line)) {
    ++line_no;
    if (line.empty()) continue;
    const auto cells = split_csv(line);
    if (cells.size() != columns.size())
      throw RunDataError(path.string() + ":" + std::to_string(line_no) + ": " +
                         std::to_string(cells.size()) + " values, the header has " +
                         std::to_string(columns.size()));
    for (std::size_t c = 0; c < cells.size(); ++c) {
      char* end = nullptr;
      const double v = std::strtod(cells[c].c_str(), &end);
      if (end == cells[c].c_str() || *end != '\0' || !std::isfinite(v))
        throw RunDataError(path.string() + ":" + std::to_string(line_no) + ": column '" +
                           columns[c] + "': not a number: '" + cells[c] + "'");
      values[c].push_back(v);
    }
  }
  if (values[0].size() < 2) throw RunDataError(path.string() + ": fewer than 2 rows");
}

void read_histories(RunData& run, const fs::path& path) {
  read_table(path, run.columns, run.values);
}

// 3D: levels from the x DOF columns "<structure>/<level> (x) u [m]" (y and theta beside them).
void find_structures3d(RunData& run) {
  for (std::size_t c = 1; c < run.columns.size(); ++c) {
    const ColumnName n = parse_column_name(run.columns[c]);
    if (n.quantity != "u" || n.label.size() < 5 ||
        n.label.compare(n.label.size() - 4, 4, " (x)") != 0)
      continue;
    const std::string label = n.label.substr(0, n.label.size() - 4);
    const auto slash = label.find('/');
    if (slash == std::string::npos) continue;
    const std::string name = label.substr(0, slash);
    auto it = std::find_if(run.structures.begin(), run.structures.end(),
                           [&](const Structure& s) { return s.name == name; });
    if (it == run.structures.end()) {
      run.structures.push_back({name, {}});
      it = run.structures.end() - 1;
    }
    Level lv;
    lv.label = label;
    lv.u = static_cast<int>(c);
    lv.v = run.find(label + " (x)", "v");
    lv.a_abs = run.find(label + " (x)", "a_abs");
    lv.u_y = run.find(label + " (y)", "u");
    lv.theta = run.find(label + " (theta)", "u");
    lv.a_abs_y = run.find(label + " (y)", "a_abs");
    lv.a_abs_theta = run.find(label + " (theta)", "a_abs");
    if (lv.u_y < 0 || lv.theta < 0)
      throw RunDataError((run.dir / "histories.csv").string() + ":1: '" + label +
                         " (x) u [m]' without its (y) and (theta) columns");
    it->levels.push_back(lv);
  }
}

// Structures and levels from the DOF columns "<structure>/<level> u [m]".
void find_structures(RunData& run) {
  for (const std::string& c : run.columns) {
    const ColumnName n = parse_column_name(c);
    if (n.quantity == "u" && n.label.size() > 4 &&
        n.label.compare(n.label.size() - 4, 4, " (x)") == 0)
      run.three_d = true;
  }
  if (run.three_d) {
    find_structures3d(run);
    return;
  }
  const auto heights = story_heights(run.summary);
  const auto isolation = isolation_levels(run.summary);
  for (std::size_t c = 1; c < run.columns.size(); ++c) {
    const ColumnName n = parse_column_name(run.columns[c]);
    if (n.quantity != "u") continue;
    const auto slash = n.label.find('/');
    if (slash == std::string::npos) continue;
    const std::string name = n.label.substr(0, slash), level = n.label.substr(slash + 1);
    if (level.rfind("wall ", 0) == 0) continue;  // a flexible wall's own DOF (see find_geometry)
    auto it = std::find_if(run.structures.begin(), run.structures.end(),
                           [&](const Structure& s) { return s.name == name; });
    if (it == run.structures.end()) {
      run.structures.push_back({name, {}});
      it = run.structures.end() - 1;
    }
    Level lv;
    lv.label = n.label;
    lv.u = static_cast<int>(c);
    lv.v = run.find(n.label, "v");
    lv.a_abs = run.find(n.label, "a_abs");
    // "floor k": elevation = sum of the heights of stories 1..k (3 m when unknown), plus the
    // isolation storey's above the isolation level; "base" above it: floor k's + that height.
    const auto iso = isolation.find(name);
    const int iso_level = iso == isolation.end() ? 0 : iso->second.first;
    const double iso_height = iso == isolation.end() ? 0.0 : iso->second.second;
    const bool raised_base = level == "base" && iso_level > 0;
    if (level.rfind("floor ", 0) == 0 || raised_base) {
      const int k = raised_base ? iso_level : std::atoi(level.c_str() + 6);
      double z = iso_level > 0 && (raised_base || k > iso_level) ? iso_height : 0.0;
      for (int s = 1; s <= k; ++s) {
        const auto h = heights.find(name + "/story " + std::to_string(s));
        if (h == heights.end()) {
          z += 3.0;
          run.notes.push_back("story height of " + name + "/story " + std::to_string(s) +
                              " not in summary.json: 3 m assumed");
        } else {
          z += h->second;
        }
      }
      lv.elevation = z;
    }
    it->levels.push_back(lv);
  }
  for (Structure& s : run.structures)
    std::stable_sort(s.levels.begin(), s.levels.end(),
                     [](const Level& a, const Level& b) { return a.elevation < b.elevation; });
  if (run.structures.empty())
    throw RunDataError((run.dir / "histories.csv").string() +
                       ":1: no displacement columns ('<structure>/<level> u [m]')");
}

void find_elements(RunData& run) {
  std::vector<std::string> seen;
  for (std::size_t c = 1; c < run.columns.size(); ++c) {
    const ColumnName n = parse_column_name(run.columns[c]);
    if (n.quantity != "force") continue;
    ElementColumns e;
    e.label = n.label;
    e.force = static_cast<int>(c);
    e.deformation = run.find(n.label, "deformation");
    e.penetration = run.find(n.label, "penetration");
    e.indentation = run.find(n.label, "indentation");
    e.contact = e.penetration >= 0;
    e.force_x = run.find(n.label, "force_x");
    e.force_y = run.find(n.label, "force_y");
    e.deformation_x = run.find(n.label, "deformation_x");
    e.deformation_y = run.find(n.label, "deformation_y");
    (e.contact ? run.contacts : run.isolators).push_back(e);
  }
}

const Structure* structure_named(const RunData& run, const std::string& name) {
  for (const Structure& s : run.structures)
    if (s.name == name) return &s;
  return nullptr;
}

// Model file: the override, else summary.json's model_file as written, else relative to the run.
std::string locate_model(const RunData& run, const std::string& override_path) {
  if (!override_path.empty()) {
    if (!fs::exists(override_path)) throw RunDataError(override_path + ": model file not found");
    return override_path;
  }
  if (!run.summary.is_object() || !run.summary.contains("model_file") ||
      !run.summary.at("model_file").is_string())
    return "";
  const fs::path p = run.summary.at("model_file").get<std::string>();
  for (const fs::path& candidate : {p, run.dir / p, run.dir.parent_path() / p})
    if (fs::exists(candidate) && fs::is_regular_file(candidate)) return candidate.string();
  return "";
}

// 3D: the plan geometry of the model file (required: histories hold only the DOFs), elevations
// of the levels from it, and the contact-event log.
void find_geometry3d(RunData& run, const std::string& model_path) {
  if (model_path.empty())
    throw RunDataError((run.dir / "summary.json").string() +
                       ": a 3D run is drawn from its model's plan geometry, and the model file "
                       "named in \"model_file\" was not found; give it with --model FILE");
  ModelConfig config;
  try {
    config = load_model_file(model_path);
    run.site = site_geometry(config);
  } catch (const std::exception& e) {
    throw RunDataError(std::string("model file of the run: ") + e.what());
  }
  for (Structure& s : run.structures) {
    for (Level& l : s.levels) {
      for (std::size_t b = 0; b < run.site.bodies.size(); ++b)
        if (run.site.bodies[b].dof_label == l.label) l.body = static_cast<int>(b);
      if (l.body < 0)
        throw RunDataError(model_path + ": has no level '" + l.label +
                           "' of the run's histories (another model?)");
      l.elevation = run.site.bodies[l.body].elevation;
    }
    std::stable_sort(s.levels.begin(), s.levels.end(),
                     [](const Level& a, const Level& b) { return a.elevation < b.elevation; });
  }
  try {
    run.contact_log = read_contact_log(run.dir / "contact_events.csv");
  } catch (const std::exception& e) {
    throw RunDataError(e.what());
  }
  for (const auto& [pair, rows] : run.contact_log.pairs)
    if (const auto f = pair_friction(config, pair)) run.friction[pair] = *f;
  for (PlanColumn& c : run.site.columns)
    if (!c.struck.label.empty()) {
      c.struck.drift_x = run.find(c.struck.label, "local_drift_x");
      c.struck.drift_y = run.find(c.struck.label, "local_drift_y");
    }
  for (const auto& [pair, rows] : run.contact_log.pairs) {
    if (run.site.struck(pair)) continue;  // a slab against a struck column's section
    std::string a, b;
    if (!split_pair(pair, a, b) || run.site.find(a) < 0 || run.site.find(b) < 0)
      run.notes.push_back("contact pair '" + pair +
                          "' of contact_events.csv: its bodies are not in the model; not drawn");
  }
}

// Walls and neighbour placement from the model file, or inferred from the contact histories.
void find_geometry(RunData& run, const std::string& model_override) {
  const std::string model_path = locate_model(run, model_override);
  if (run.three_d) {
    find_geometry3d(run, model_path);
    return;
  }
  const Structure& main = run.structures.front();
  if (!model_path.empty()) {
    ModelConfig config;
    try {
      config = load_model_file(model_path);
    } catch (const std::exception& e) {
      throw RunDataError(std::string("model file of the run: ") + e.what());
    }
    for (const WallConfig& w : config.building.walls) {
      if (w.level < 0 || w.level >= static_cast<int>(main.levels.size())) continue;
      // Labels as the solver writes them (structures/pounding2d.cpp).
      const std::string where = is_base_level(config.building, w.level)
                                    ? std::string("base")
                                    : "level " + std::to_string(w.level);
      const double z = main.levels[w.level].elevation;
      if (w.left)
        run.walls.push_back({main.name + "/wall left (" + where + ")", -1, w.gap_left, z});
      if (w.right)
        run.walls.push_back({main.name + "/wall right (" + where + ")", +1, w.gap_right, z});
    }
    for (const NeighbourConfig& n : config.neighbours)
      for (Structure& s : run.structures)
        if (s.name == n.building.name) {
          s.neighbour = true;
          s.side = n.right ? +1 : -1;
          s.gap = n.gap;
        }
    for (Wall& w : run.walls) w.u = run.find(w.label + " structure", "u");
    return;
  }
  run.notes.push_back("model file not found: wall gaps inferred from the contact histories");
  // A wall contact "<main>/wall <side> (<level>)": gap = side * u - penetration while in contact.
  for (const ElementColumns& c : run.contacts) {
    const auto pos = c.label.find("/wall ");
    if (pos == std::string::npos) continue;
    Wall w;
    w.label = c.label;
    w.side = c.label.find("/wall left", pos) != std::string::npos ? -1 : +1;
    const auto open = c.label.find('(', pos), close = c.label.find(')', pos);
    const std::string level = open != std::string::npos && close != std::string::npos
                                  ? c.label.substr(open + 1, close - open - 1)
                                  : "base";
    const Structure* s = structure_named(run, c.label.substr(0, pos));
    const Level* lv = nullptr;
    if (s) {
      for (const Level& l : s->levels)
        if (l.label == s->name + "/" + level) lv = &l;
      // "level k" (walls of a fixed-base building): the k-th level from the bottom.
      const int k = level.rfind("level ", 0) == 0 ? std::atoi(level.c_str() + 6) : -1;
      if (!lv && k >= 0 && k < static_cast<int>(s->levels.size())) lv = &s->levels[k];
    }
    if (!lv) continue;
    w.u = run.find(c.label + " structure", "u");
    w.elevation = lv->elevation;
    double best = -1.0;
    for (std::size_t r = 0; r < run.rows(); ++r) {
      const double pen = run.values[c.penetration][r];
      if (pen > best) {
        best = pen;
        const double u_wall = w.u >= 0 ? run.values[w.u][r] : 0.0;
        w.gap = w.side * (run.values[lv->u][r] - u_wall) - pen;
      }
    }
    if (best <= 0.0) {
      double peak = 0.0;
      for (double u : run.values[lv->u]) peak = std::max(peak, std::abs(u));
      w.gap = 1.2 * peak;
      w.gap_known = false;
      run.notes.push_back(c.label +
                          ": never in contact and no model file: drawn at 1.2 x the peak");
    }
    run.walls.push_back(w);
  }
  for (Structure& s : run.structures)
    if (&s != &run.structures.front()) {
      s.neighbour = true;
      s.side = +1;
      s.gap = 0.1;
      run.notes.push_back(s.name +
                          ": neighbour side and gap unknown (no model file): right, 10 cm");
    }
}

}  // namespace

// A bumper's rubber is that of the moat wall, or of the structure whose slab face, is <face>.
std::optional<RunData::Friction> pair_friction(const ModelConfig& config,
                                               const std::string& labelled_pair) {
  if (!config.contact3d.law.friction) return std::nullopt;
  RunData::Friction f{config.contact3d.law.mu_static, config.contact3d.law.mu_kinetic};
  std::string a, b;  // a second contact of the same pair ("... bumper #2"): the same rubber
  if (!split_pair(labelled_pair, a, b)) return f;
  const std::string pair = a + "|" + b;
  const auto bar = pair.find('|');
  for (const std::string& end :
       {std::string(" ") + kBottomedLabel, std::string(" ") + kBumperLabel}) {
    if (bar == std::string::npos || pair.size() < bar + 1 + end.size() ||
        pair.compare(pair.size() - end.size(), end.size(), end) != 0)
      continue;
    const std::string face = pair.substr(bar + 1, pair.size() - end.size() - bar - 1);
    for (const SiteBody& w : site_bodies(config))
      if (w.role == "wall" && w.label() == face && w.building >= 0)
        return RunData::Friction{config.structures3d[w.building].walls.bumper.mu_static,
                                 config.structures3d[w.building].walls.bumper.mu_kinetic};
    for (const Building3DConfig& b : config.structures3d)
      if (face.rfind(b.name + "/", 0) == 0)
        return RunData::Friction{b.bumper.mu_static, b.bumper.mu_kinetic};
    break;
  }
  return f;
}

ColumnName parse_column_name(const std::string& header) {
  ColumnName n;
  std::string rest = header;
  const auto open = rest.rfind(" [");
  if (open != std::string::npos && rest.back() == ']') {
    n.unit = rest.substr(open + 2, rest.size() - open - 3);
    rest = rest.substr(0, open);
  }
  const auto space = rest.rfind(' ');
  if (space == std::string::npos) {
    n.quantity = rest;
  } else {
    n.label = rest.substr(0, space);
    n.quantity = rest.substr(space + 1);
  }
  return n;
}

int RunData::find(const std::string& label, const std::string& quantity) const {
  for (std::size_t c = 0; c < columns.size(); ++c) {
    const ColumnName n = parse_column_name(columns[c]);
    if (n.label == label && n.quantity == quantity) return static_cast<int>(c);
  }
  return -1;
}

RunData read_run(const fs::path& dir, const std::string& model_file) {
  if (!fs::is_directory(dir)) throw RunDataError(dir.string() + ": run directory not found");
  RunData run;
  run.dir = dir;
  const fs::path summary = dir / "summary.json";
  if (fs::exists(summary)) {
    std::ifstream in(summary);
    try {
      run.summary = nlohmann::json::parse(in);
    } catch (const nlohmann::json::exception& e) {
      throw RunDataError(summary.string() + ": " + e.what());
    }
  } else {
    run.notes.push_back("summary.json absent: story heights of 3 m assumed");
  }
  read_histories(run, dir / "histories.csv");
  find_structures(run);
  find_elements(run);
  find_geometry(run, model_file);
  return run;
}

std::optional<StepTable> read_step_accelerations(const RunData& run) {
  const fs::path path = run.dir / "step-accelerations.csv";
  if (!fs::exists(path)) return std::nullopt;
  StepTable table;
  read_table(path, table.columns, table.values);
  const std::vector<double>& t = table.values[0];
  for (std::size_t k = 1; k < t.size(); ++k)
    if (t[k] < t[k - 1])
      throw RunDataError(path.string() + ":" + std::to_string(k + 2) +
                         ": time goes back (steps must be in order)");
  return table;
}

int StepTable::find(const std::string& column) const {
  for (std::size_t c = 0; c < columns.size(); ++c)
    if (columns[c] == column) return static_cast<int>(c);
  return -1;
}

double value_at(const RunData& run, int column, double t) {
  const std::vector<double>& time = run.time();
  const std::vector<double>& v = run.values.at(column);
  if (t <= time.front()) return v.front();
  if (t >= time.back()) return v.back();
  const auto it = std::upper_bound(time.begin(), time.end(), t);
  const std::size_t i = static_cast<std::size_t>(it - time.begin());
  const double f = (t - time[i - 1]) / (time[i] - time[i - 1]);
  return v[i - 1] + f * (v[i] - v[i - 1]);
}

}  // namespace isopound::post
