// view.py from its template (see paraview_view.h; the template is post/view_script.py).
#include "post/paraview_view.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "post/view_script_text.h"

namespace isopound::post {
namespace {

std::string number(double x) {
  char text[40];
  std::snprintf(text, sizeof text, "%.17g", x);
  return text;
}

// A Python string literal's body: the directory may hold quotes or backslashes.
std::string python_escaped(const std::string& s) {
  std::string out;
  for (char c : s) {
    if (c == '\\' || c == '"') out += '\\';
    out += c;
  }
  return out;
}

void replace_all(std::string& text, const std::string& key, const std::string& value) {
  std::size_t found = 0, at = 0;
  while ((at = text.find(key, at)) != std::string::npos) {
    text.replace(at, key.size(), value);
    at += value.size();
    ++found;
  }
  if (found == 0) throw std::logic_error("view_script.py has no " + key);
}

}  // namespace

ContactPeaks contact_peaks(const RunData& run) {
  ContactPeaks p;
  if (run.three_d) {
    for (const auto& [pair, rows] : run.contact_log.pairs)
      for (const ContactEvent& e : rows) {
        p.normal_force = std::max(p.normal_force, std::abs(e.normal_force));
        p.penetration = std::max(p.penetration, e.indentation);
      }
    return p;
  }
  for (const ElementColumns& c : run.contacts) {
    if (c.force >= 0)
      for (double f : run.column(c.force)) p.normal_force = std::max(p.normal_force, std::abs(f));
    if (c.penetration >= 0)
      for (double d : run.column(c.penetration)) p.penetration = std::max(p.penetration, d);
  }
  return p;
}

double nice_factor_below(double wanted) {
  if (!(wanted > 1.0) || !std::isfinite(wanted)) return 1.0;
  const double decade = std::pow(10.0, std::floor(std::log10(wanted)));
  for (double m : {5.0, 2.0, 1.0})
    if (m * decade <= wanted) return m * decade;
  return decade;
}

double automatic_scale(double largest, double extent) {
  if (!(largest > 0.0) || !(extent > 0.0)) return 1.0;
  return nice_factor_below(0.1 * extent / largest);
}

double automatic_exaggeration(const ContactPeaks& peaks, double drawn_depth_per_metre,
                              double extent) {
  const double drawn = peaks.penetration * drawn_depth_per_metre;
  if (!(drawn > 0.0) || !(extent > 0.0)) return 1.0;
  return nice_factor_below(0.05 * extent / drawn);
}

ForceUnit force_unit(const ContactPeaks& peaks) {
  return peaks.normal_force >= 1e6 ? ForceUnit{"MN", 1e6} : ForceUnit{"kN", 1e3};
}

std::string view_script(const ViewScriptOptions& o) {
  std::string text = kViewScriptTemplate;
  replace_all(text, "@PVD@", python_escaped(o.pvd_file));
  replace_all(text, "@ABSOLUTE_DIR@", python_escaped(o.absolute_dir));
  replace_all(text, "@THREE_D@", o.three_d ? "True" : "False");
  replace_all(text, "@SCALE@", number(o.scale));
  replace_all(text, "@FRAME_SCALE@", number(o.frame_scale));
  replace_all(text, "@FRAME_GAP_SCALE@", number(o.frame_gaps_scaled ? o.frame_scale : 1.0));
  replace_all(text, "@FPS@", number(o.fps));
  replace_all(text, "@EXAGGERATION@", number(o.exaggeration));
  replace_all(text, "@PEAK_NORMAL_FORCE@", number(o.peaks.normal_force));
  replace_all(text, "@PEAK_PENETRATION@", number(o.peaks.penetration));
  replace_all(text, "@FORCE_LENGTH@", number(o.force_length));
  const ForceUnit unit = force_unit(o.peaks);
  replace_all(text, "@FORCE_UNIT@", unit.name);
  replace_all(text, "@NEWTONS_PER_UNIT@", number(unit.newtons));
  return text;
}

}  // namespace isopound::post
