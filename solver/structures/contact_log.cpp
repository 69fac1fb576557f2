// contact_events.csv: written while the analysis runs, each row formatted into a fixed buffer
// with std::to_chars (as printf's %.9g, a third of its cost) — no allocation per row.
#include "solver/structures/contact_log.h"

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cstring>
#include <stdexcept>

#include "solver/elements/polygon_contact.h"
#include "solver/elements/struck_column3d.h"

namespace isopound {

const char* ContactEventLog::header() {
  return "time [s],pair,event,in_contact,slipping,area [m2],indentation [m],normal_force [N],"
         "tangential_force [N],x_C [m],y_C [m],n_x [-],n_y [-]";
}

ContactEventLog::ContactEventLog(const Model& model, const std::string& path) : path_(path) {
  for (std::size_t e = 0; e < model.elements.size(); ++e)
    if (const auto* c = dynamic_cast<const PolygonContact*>(model.elements[e].get()))
      contacts_.push_back({static_cast<int>(e), c});
    else if (const auto* s = dynamic_cast<const StruckColumn3D*>(model.elements[e].get()))
      contacts_.push_back({static_cast<int>(e), &s->contact()});  // a slab on a column (issue 26)
  if (path.empty() || contacts_.empty()) return;
  file_ = std::fopen(path.c_str(), "w");
  if (!file_) throw std::runtime_error("cannot write " + path + ": " + std::strerror(errno));
  std::fprintf(file_, "%s\n", header());
}

ContactEventLog::~ContactEventLog() {
  if (file_) std::fclose(file_);
}

void ContactEventLog::after_step(double t, const Model&) {
  for (Watched& w : contacts_) {
    const ContactSnapshot s = w.contact->snapshot();
    const int impacts = w.contact->impacts();
    if (impacts > w.impacts && w.first_impact < 0) w.first_impact = t;
    w.impacts = impacts;
    if (!s.in_contact && !w.was_in_contact) continue;
    const char* event = !w.was_in_contact ? "onset" : s.in_contact ? "contact" : "separation";
    w.was_in_contact = s.in_contact;
    if (!file_) continue;
    const bool on = s.in_contact;
    // The same text as "%.10g,%s,%s,%d,%d" then eight ",%.9g" and "\n" (to_chars with a
    // precision formats as printf does); the label goes out as it is, however long.
    char row[256];
    char* const end = row + sizeof row;
    char* p = std::to_chars(row, end, t, std::chars_format::general, 10).ptr;
    *p++ = ',';
    std::fwrite(row, 1, static_cast<std::size_t>(p - row), file_);
    std::fputs(w.contact->label().c_str(), file_);
    p = row;
    for (const char* x : {event, on ? "1" : "0", on && s.slipping ? "1" : "0"}) {
      *p++ = ',';
      const std::size_t n = std::strlen(x);  // at most "separation"
      std::memcpy(p, x, n);
      p += n;
    }
    for (const double x : {on ? s.area : 0.0, on ? s.indentation : 0.0, on ? s.normal_force : 0.0,
                           on ? s.tangential_force : 0.0, s.p_WC.x, s.p_WC.y, s.n_AB.x, s.n_AB.y}) {
      *p++ = ',';
      p = std::to_chars(p, end, x, std::chars_format::general, 9).ptr;  // <= 16 characters
    }
    *p++ = '\n';
    std::fwrite(row, 1, static_cast<std::size_t>(p - row), file_);
    ++rows_;
  }
}

void ContactEventLog::close() {
  if (!file_) return;
  const bool failed = std::ferror(file_) != 0;
  const bool close_failed = std::fclose(file_) != 0;
  file_ = nullptr;
  if (failed || close_failed) throw std::runtime_error("cannot write " + path_);
}

std::vector<double> ContactEventLog::first_impact_times(const Model& model) const {
  std::vector<double> out(model.elements.size(), -1.0);
  for (const Watched& w : contacts_) out[static_cast<std::size_t>(w.element)] = w.first_impact;
  return out;
}

}  // namespace isopound
