// step-accelerations.csv: the time, the ground's acceleration and every DOF's absolute acceleration
// at every accepted analysis step (output.floor_spectra: true). Joined by straight lines, these are
// the accelerations the solver's own peaks see; isopound-post floor-spectra integrates its
// oscillators over them exactly (docs/floor-spectra.md), where histories.csv's rows would put a
// 3 ms impact into one or two samples.
//
// Columns: "time [s]", "ground_acceleration [m/s2]" (3D also "ground_acceleration_y [m/s2]"),
// then the "<dof> a_abs [...]" columns of histories.csv, same names. Values in the shortest text
// that reads back to the same double (std::to_chars): the file is the solver's numbers. Steps
// cut at an event may repeat a time (the state before and after a contact's force jumps).
#pragma once

#include <cstdio>
#include <string>
#include <vector>

#include "solver/core/analysis.h"

namespace isopound {

class StepAccelerationWriter : public HistorySink {
 public:
  static constexpr const char* kFileName = "step-accelerations.csv";
  // Opens the file (throws std::runtime_error "cannot write PATH: reason").
  explicit StepAccelerationWriter(std::string path);
  ~StepAccelerationWriter() override;
  StepAccelerationWriter(const StepAccelerationWriter&) = delete;
  StepAccelerationWriter& operator=(const StepAccelerationWriter&) = delete;
  void begin(const std::vector<std::string>& columns) override;
  void row(const double* values, std::size_t count) override;
  // Flushes; throws std::runtime_error on a write error.
  void close();
  std::size_t steps() const { return steps_; }

 private:
  std::string path_;
  std::FILE* file_ = nullptr;
  std::vector<std::size_t> kept_;  // indices of the kept columns in a history row
  std::vector<char> line_;         // one row's text, sized in begin(): row() allocates nothing
  std::size_t steps_ = 0;
};

}  // namespace isopound
