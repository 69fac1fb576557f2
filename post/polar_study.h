// A study's results (read as a plain table, solver/study/study_table.h) arranged for polar
// figures: a quantity's peak against the incidence-angle axis per record or case, and on an
// angle x gap grid.
// Angles are stored in SI (rad) like every numeric axis; values above 2 pi are taken as degrees.
// Ensemble statistics of a quantity Q are output columns beside Q: Q_ens_min, Q_ens_mean,
// Q_ens_max, Q_ens_std as `ensemble: N` studies write them (docs/studies.md); Q_min, Q.min,
// Q_ensemble_min are read too: see ensemble_columns.
#pragma once

#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "post/polar_plot.h"

namespace isopound::post {

class PolarStudyError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct PolarStudyOptions {
  std::string quantity;        // an output column of the runs table
  std::string angle_axis;      // "" = the axis named angle / incidence / *angle
  std::string per = "record";  // curves per this axis ("case": per other-axes combination)
  std::vector<std::pair<std::string, std::string>> where;  // axis = level label filters
  std::string contour_axis;  // "" = envelope; else the radial axis (e.g. "gap")
  // Display unit of the quantity (m, cm, mm, m/s, g, m/s2, N, kN, MN, %, -, J, kJ); "" = from the
  // study file's selector when the file can still be read, else SI values labelled "SI".
  std::string unit;
};

// Display unit of a study output column: from the selector's quantity in the study file when it
// can be read, else SI ("m", "N", ...) guessed from nothing: "" when unknown.
struct DisplayUnit {
  std::string unit;      // e.g. "cm"
  double divisor = 1.0;  // SI value / divisor = displayed value
};
// The display unit of a selector's quantity ("displacement": cm, ...); {"SI", 1} when unknown.
DisplayUnit display_unit_of(const std::string& quantity);
// The display unit of a numeric axis from its name (axes hold SI, docs/studies.md): cm for gaps,
// thicknesses and uy, deg for angles, % for QW and xi*, s for Tb, period and duration; else SI.
DisplayUnit axis_display_unit(const std::string& axis);

struct PolarStudyResult {
  PolarEnvelopeData envelope;  // when contour_axis is ""
  PolarContourData contour;    // otherwise
  std::string csv;             // the plotted numbers
  std::vector<std::string> notes;
};

// Where a quantity's ensemble statistics are among the output columns (-1: absent). A band needs
// both min and max. Tried in order for each statistic S: Q_ens_S, Q_S, Q.S, Q_ensemble_S.
struct EnsembleColumns {
  int min = -1, mean = -1, max = -1, std = -1;
  bool band() const { return min >= 0 && max >= 0; }
};
EnsembleColumns ensemble_columns(const std::vector<std::string>& outputs,
                                 const std::string& quantity);

// The divisor from SI to a display unit name; throws PolarStudyError for an unknown name.
double unit_divisor(const std::string& unit);

// Throws PolarStudyError with one clear message: no such database, no angle axis (listing the
// axes), quantity not in the table (listing the quantities), no rows after the filters.
PolarStudyResult read_polar_study(const std::string& db_path, const PolarStudyOptions& options);

}  // namespace isopound::post
