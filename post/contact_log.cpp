// Reading contact_events.csv (see contact_log.h).
#include "post/contact_log.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "solver/structures/pounding3d.h"

namespace isopound::post {

std::vector<std::string> split_csv(const std::string& line) {
  std::vector<std::string> out;
  std::string cell;
  std::stringstream ss(line);
  while (std::getline(ss, cell, ',')) out.push_back(cell);
  if (!line.empty() && line.back() == ',') out.push_back("");
  return out;
}

const ContactEvent* ContactLog::state_at(const std::string& pair, double t) const {
  const auto it = pairs.find(pair);
  if (it == pairs.end()) return nullptr;
  const std::vector<ContactEvent>& rows = it->second;
  const auto after = std::upper_bound(rows.begin(), rows.end(), t,
                                      [](double x, const ContactEvent& e) { return x < e.time; });
  return after == rows.begin() ? nullptr : &*(after - 1);
}

bool split_pair(const std::string& pair, std::string& a, std::string& b) {
  const auto bar = pair.find('|');
  if (bar == std::string::npos) return false;
  a = pair.substr(0, bar);
  b = pair.substr(bar + 1);
  // A second or third contact of the same two bodies (a non-convex plan: one per part of the
  // overlap) is labelled "A|B #2": the same bodies.
  b = std::string(without_slot(b));
  return true;
}

ContactLog read_contact_log(const std::filesystem::path& path) {
  ContactLog log;
  std::ifstream in(path);
  if (!in) return log;
  const std::string file = path.string();
  std::string line;
  if (!std::getline(in, line)) return log;
  const std::vector<std::string> header = split_csv(line);
  const auto column = [&](const std::string& name) {
    const auto it = std::find(header.begin(), header.end(), name);
    if (it == header.end())
      throw std::runtime_error(file + ":1: no column '" + name + "' in the header");
    return static_cast<std::size_t>(it - header.begin());
  };
  const std::size_t c_time = column("time [s]"), c_pair = column("pair"), c_event = column("event"),
                    c_in = column("in_contact"), c_slip = column("slipping"),
                    c_area = column("area [m2]"), c_ind = column("indentation [m]"),
                    c_fn = column("normal_force [N]"), c_ft = column("tangential_force [N]"),
                    c_x = column("x_C [m]"), c_y = column("y_C [m]"), c_nx = column("n_x [-]"),
                    c_ny = column("n_y [-]");
  int line_no = 1;
  while (std::getline(in, line)) {
    ++line_no;
    if (line.empty()) continue;
    const auto cells = split_csv(line);
    const std::string where = file + ":" + std::to_string(line_no) + ": ";
    if (cells.size() != header.size())
      throw std::runtime_error(where + std::to_string(cells.size()) + " values, the header has " +
                               std::to_string(header.size()));
    const auto number = [&](std::size_t c) {
      char* end = nullptr;
      const double v = std::strtod(cells[c].c_str(), &end);
      if (end == cells[c].c_str() || *end != '\0' || !std::isfinite(v))
        throw std::runtime_error(where + "column '" + header[c] + "': not a number: '" + cells[c] +
                                 "'");
      return v;
    };
    ContactEvent e;
    e.time = number(c_time);
    e.event = cells[c_event];
    e.in_contact = number(c_in) != 0.0;
    e.slipping = number(c_slip) != 0.0;
    e.area = number(c_area);
    e.indentation = number(c_ind);
    e.normal_force = number(c_fn);
    e.tangential_force = number(c_ft);
    e.x_C = number(c_x);
    e.y_C = number(c_y);
    e.n_x = number(c_nx);
    e.n_y = number(c_ny);
    std::vector<ContactEvent>& rows = log.pairs[cells[c_pair]];
    if (!rows.empty() && e.time < rows.back().time)
      throw std::runtime_error(where + "time goes back for pair '" + cells[c_pair] + "'");
    rows.push_back(e);
  }
  return log;
}

}  // namespace isopound::post
