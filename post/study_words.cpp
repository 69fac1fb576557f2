// Study columns in words (see study_words.h).
#include "post/study_words.h"

#include <algorithm>
#include <cctype>
#include <map>

#include "solver/study/study_table.h"

namespace isopound::post {
namespace {

std::string spaced(std::string s) {
  std::replace(s.begin(), s.end(), '_', ' ');
  return s;
}

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::tolower(c); });
  return s;
}

// The number after `prefix` in text ("floor3": "3"), "" when text is not prefix + digits.
std::string number_after(const std::string& text, const std::string& prefix) {
  if (text.size() <= prefix.size() || text.compare(0, prefix.size(), prefix) != 0) return "";
  const std::string n = text.substr(prefix.size());
  return std::all_of(n.begin(), n.end(), [](unsigned char c) { return std::isdigit(c); }) ? n : "";
}

// Quantities whose value is not a peak over time (counts, times, values at the end, energies).
bool is_peak(const std::string& q) {
  static const char* const kNotPeaks[] = {"impacts",
                                          "first_impact_time",
                                          "time_in_stick",
                                          "time_in_slip",
                                          "yielded",
                                          "input",
                                          "kinetic",
                                          "elastic",
                                          "viscous",
                                          "hysteretic",
                                          "error",
                                          "relative_error",
                                          "max_relative_error",
                                          "friction_dissipated_energy",
                                          "impact_dissipated_energy",
                                          "dissipated_energy",
                                          "pga",
                                          "pgv",
                                          "pgd"};
  if (q.rfind("residual_", 0) == 0) return false;
  return std::none_of(std::begin(kNotPeaks), std::end(kNotPeaks),
                      [&](const char* n) { return q == n; });
}

std::string quantity_words(const StudyTableSelector& s) {
  static const std::map<std::string, std::string> kWords = {
      {"displacement_x", "x displacement"},
      {"displacement_y", "y displacement"},
      {"absolute_acceleration_x", "x absolute acceleration"},
      {"absolute_acceleration_y", "y absolute acceleration"},
      {"drift_x", "x drift"},
      {"drift_y", "y drift"},
      {"theta", "rotation θ"},
      {"u", "x displacement u (plan origin)"},
      {"v", "y displacement v (plan origin)"},
      {"pga", "PGA"},
      {"pgv", "PGV"},
      {"pgd", "PGD"},
      {"yielded", "yielded columns"},
      {"ductility", "ductility demand"}};
  if (s.kind == "energy") {
    if (s.quantity.find("error") != std::string::npos)
      return "energy balance " + spaced(s.quantity);
    return spaced(s.quantity) + " energy";
  }
  const auto it = kWords.find(s.quantity);
  return it != kWords.end() ? it->second : spaced(s.quantity);
}

// The place ("base", "storey 2", "wall") and, for a group or a plan point, which of it is
// taken ("largest storey", "corner 3").
void place_words(const StudyTableSelector& s, std::string& place, std::string& which) {
  if (s.kind == "level") {
    if (s.where == "floors" || s.where == "levels") {
      place = s.where.substr(0, s.where.size() - 1);
      which = "largest " + place;
    } else if (const std::string n = number_after(s.where, "floor"); !n.empty()) {
      place = "floor " + n;
    } else {
      place = s.where;  // base, roof
    }
    if (s.point == "corners" || s.point == "points")
      which = std::string("largest ") + (which.empty() ? "" : place + " ") +
              (s.point == "corners" ? "corner" : "of CM and corners");
    else if (const std::string k = number_after(s.point, "corner"); !k.empty())
      which = "corner " + k;
    return;
  }
  if (s.kind == "story") {
    const bool all = s.where == "stories";
    place = all ? "storey" : "storey " + number_after(s.where, "story");
    if (s.point == "corners")
      which = all ? "largest corner column of any storey" : "largest corner column";
    else if (!s.point.empty())
      which = "column " + s.point + (all ? ", largest storey" : "");
    else if (all)
      which = "largest storey";
    return;
  }
  if (s.kind == "element") {
    // "wall*": wall, "*~*" (pairs of structures) and "contacts": contact; wildcards make a group.
    std::string name = s.where;
    const bool group = name.find_first_of("*?|") != std::string::npos || name == "contacts";
    std::erase_if(name, [](char c) { return c == '*' || c == '?'; });
    if (name.find('~') != std::string::npos || name == "contacts" || name.empty()) name = "contact";
    place = spaced(name);
    if (s.sum)
      which = "sum over " + place + "s";
    else if (group)
      which = "largest " + place;
  }
}

}  // namespace

std::string output_words(const std::string& selector) {
  if (selector.empty()) return "";
  const StudyTableSelector s = parse_table_selector(selector);
  if (s.kind.empty()) return "";
  std::string place, which;
  place_words(s, place, which);
  // A sum names its place after the comma; impacts are counted, not peaks.
  std::string words = s.quantity == "impacts" ? "number of impacts" : quantity_words(s);
  if (!place.empty() && !s.sum && s.quantity != "impacts") words = place + " " + words;
  if (s.quantity == "impacts" && which.empty() && !place.empty()) which = place;
  if (is_peak(s.quantity) && !s.sum) words = "peak " + words;
  return which.empty() ? words : words + " (" + which + ")";
}

std::string output_title(const std::string& selector, const std::string& column,
                         const std::string& unit) {
  std::string words = output_words(selector);
  if (words.empty()) words = "peak " + column;
  if (unit.empty() || unit == "-") return words;
  return words + " [" + unit + "]";
}

std::string axis_words(const std::string& axis) {
  const std::string n = lower(axis);
  if (n == "angle" || n == "incidence" || n == "theta") return "incidence angle";
  if (n == "tb") return "isolation period T_b";
  if (n == "qw") return "Q/W";
  if (n == "xi") return "damping ratio ξ";
  return spaced(axis);
}

std::string capitalised(std::string text) {
  if (!text.empty()) text[0] = static_cast<char>(std::toupper(static_cast<unsigned char>(text[0])));
  return text;
}

}  // namespace isopound::post
