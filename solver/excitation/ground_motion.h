// Ground motions: recorded accelerograms (PEER .AT2, plain columns) and the built-in
// near-fault pulse, as uniformly sampled ground acceleration in m/s^2 (linear between samples).
#pragma once

#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace isopound {

// Uniformly sampled ground acceleration. Sample k is at time k*dt; between samples the
// acceleration is linear (the convention of Nigam-Jennings and of PEER processing).
struct GroundMotion {
  std::string name;                  // file stem or "pulse"
  double dt = 0.0;                   // s, > 0
  std::vector<double> acceleration;  // m/s^2, acceleration[0] at t = 0
  // Second horizontal component (the model's y direction), same dt and length; empty: the
  // motion acts along x only.
  std::vector<double> acceleration_y;
  // What the reader assumed or converted about the file's unit, for the console ("RSN1.AT2:
  // header line 3 says UNITS OF CM/S/S: converted to m/s^2"); empty when the header says g.
  std::string unit_note;

  double duration() const { return dt * static_cast<double>(acceleration.size() - 1); }
  // Linear interpolation; 0 outside [0, duration()].
  double at(double t) const;
};

// Peak ground motion parameters. Velocity and displacement are integrated from the
// acceleration exactly for a piecewise-linear acceleration with zero initial velocity
// and displacement, and no baseline correction (the records are already processed).
struct GroundMotionPeaks {
  double pga = 0.0;                              // m/s^2, max |a|
  double pgv = 0.0;                              // m/s
  double pgd = 0.0;                              // m
  double t_pga = 0.0, t_pgv = 0.0, t_pgd = 0.0;  // s, time of each peak
};
GroundMotionPeaks peaks_of(const GroundMotion& motion);

// Input error that names the file and line (1-based; 0 when not tied to a line).
class RecordError : public std::runtime_error {
 public:
  RecordError(const std::string& file, int line, const std::string& what);
  const std::string& file() const { return file_; }
  int line() const { return line_; }

 private:
  std::string file_;
  int line_;
};

enum class AccelerationUnit { kG, kMetrePerSecond2, kCentimetrePerSecond2 };

// How to read a record file. kAuto: PEER .AT2 if an NPTS/DT line is found, else columns.
struct RecordReadOptions {
  enum class Format { kAuto, kPeer, kColumns } format = Format::kAuto;
  // Columns only: which column holds the acceleration (0-based). If the file has a time
  // column, set time_column to its index (dt is then taken from it and must be uniform).
  int column = 0;
  int time_column = -1;
  double dt = 0.0;                               // s; columns without a time column need it (> 0)
  AccelerationUnit unit = AccelerationUnit::kG;  // columns only: PEER files state their unit
  double scale = 1.0;                            // multiplies the acceleration
};

// The format kAuto would pick for this file (PEER if an NPTS/DT line is in its first lines or it
// ends in .AT2, else columns); nullopt if the file cannot be read. Reads only the first lines.
std::optional<RecordReadOptions::Format> sniff_record_format(const std::string& path);

// Reads a record. Throws RecordError (file, line, what) on a truncated file, a non-numeric
// or NaN/inf value, an NPTS mismatch, an empty file, a missing dt.
GroundMotion read_record(const std::string& path, const RecordReadOptions& options = {});

// Mavroeidis & Papageorgiou (2003) near-fault velocity pulse (THEORY section 10):
// v(t) = A/2 [1 + cos(2 pi f_p (t - t0)/gamma)] cos(2 pi f_p (t - t0) + nu)
// for |t - t0| <= gamma/(2 f_p), else 0. Acceleration is its exact derivative.
struct PulseParameters {
  double amplitude = 1.0;  // A, m/s (peak velocity scale)
  double period = 2.0;     // T_p = 1/f_p, s
  double gamma = 2.0;      // oscillatory character, > 1
  double phase = 0.0;      // nu, rad
  double t_peak = 4.0;     // t0, s: time of the envelope peak
  double duration = 20.0;  // s, total length of the generated series (free vibration after)
  double dt = 0.005;       // s, sampling of the generated series
};
double pulse_velocity(const PulseParameters& p, double t);
double pulse_acceleration(const PulseParameters& p, double t);
GroundMotion make_pulse(const PulseParameters& p);

}  // namespace isopound
