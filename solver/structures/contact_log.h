// The contact-event log of a 3D run (contact_events.csv) and the first-impact time of each pair:
// one row per accepted step while a polygon contact is closed, plus the step after it opens.
// A pair is in contact at time t iff its last row with time <= t has in_contact 1.
#pragma once

#include <cstdio>
#include <string>
#include <vector>

#include "solver/core/analysis.h"

namespace isopound {

class PolygonContact;

class ContactEventLog final : public StepObserver {
 public:
  // Watches the model's PolygonContacts (and those inside StruckColumn3D elements); writes to
  // `path` unless it is empty (then only the first-impact times are kept). Throws
  // std::runtime_error when the file cannot be opened.
  ContactEventLog(const Model& model, const std::string& path);
  ~ContactEventLog() override;
  ContactEventLog(const ContactEventLog&) = delete;
  ContactEventLog& operator=(const ContactEventLog&) = delete;

  void after_step(double t, const Model& model) override;
  // Flushes and closes the file; throws std::runtime_error on a write error.
  void close();

  bool empty() const { return contacts_.empty(); }
  // Per model element: the time of its first counted impact (s), or −1 (none, or not a polygon
  // contact).
  std::vector<double> first_impact_times(const Model& model) const;
  std::size_t rows() const { return rows_; }

  static const char* header();

 private:
  struct Watched {
    int element = -1;
    const PolygonContact* contact = nullptr;
    bool was_in_contact = false;
    int impacts = 0;
    double first_impact = -1.0;
  };
  std::vector<Watched> contacts_;
  std::string path_;
  std::FILE* file_ = nullptr;
  std::size_t rows_ = 0;
};

}  // namespace isopound
