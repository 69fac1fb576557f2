// The contact-event log of a 3D run (contact_events.csv): one row per accepted step while a pair
// is in contact, plus the separation row after. Rule: a pair is in contact at time t iff its last
// row with time <= t has in_contact 1 (rows of one pair are in time order).
#pragma once

#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace isopound::post {

// The cells of one CSV line split at commas (no quoting: the files isopound writes need none);
// a trailing comma gives a last empty cell.
std::vector<std::string> split_csv(const std::string& line);

struct ContactEvent {
  double time = 0.0;  // s
  std::string event;  // onset | contact | separation
  bool in_contact = false, slipping = false;
  double area = 0.0, indentation = 0.0;               // m2, m
  double normal_force = 0.0, tangential_force = 0.0;  // N; the force on B: F_N n_AB − F_T t_AB
  double x_C = 0.0, y_C = 0.0;                        // m, centroid of the overlap (plan W)
  double n_x = 0.0, n_y = 0.0;                        // unit normal n_AB, from A into B
};

struct ContactLog {
  // Per pair label "<A>|<B>" (A, B: "<structure>/<level>" or "wall <side>"), rows in time order.
  std::map<std::string, std::vector<ContactEvent>> pairs;

  // The pair's last row with time <= t (nullptr: none yet, or no such pair).
  const ContactEvent* state_at(const std::string& pair, double t) const;
  bool in_contact(const std::string& pair, double t) const {
    const ContactEvent* e = state_at(pair, t);
    return e && e->in_contact;
  }
};

// Reads the log; columns by their header names. An absent file gives an empty log; a malformed
// one throws std::runtime_error naming file, line and column.
ContactLog read_contact_log(const std::filesystem::path& path);

// "<A>|<B>" split at the bar; false when there is none.
bool split_pair(const std::string& pair, std::string& a, std::string& b);

}  // namespace isopound::post
