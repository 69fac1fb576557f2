// Polar figures of a study as plain-data functions: envelope (peak response against incidence
// angle) and contour (angle around, gap along the radius, colour = response). Angle convention:
// 0 deg along +x (to the right), counter-clockwise positive, as the incidence angle of the record.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "post/figure.h"

namespace isopound::post {

// Where the polar axes are on the figure (for tests and overlays).
struct PolarFrame {
  Point2 centre;                  // px
  double radius_px = 0.0;         // outer circle
  double r_lo = 0.0, r_hi = 1.0;  // data value at the centre and at the outer circle
  Point2 to_pixel(double angle_deg, double r) const;
};

struct PolarCurve {
  std::string label;
  std::vector<double> angle_deg, value;  // closed automatically when it spans 360 deg
  std::optional<Rgb> colour;
  double width = 1.5;
};

// A shaded band between lo and hi per angle (an ensemble's min-max), drawn under the curves.
struct PolarBand {
  std::string label;  // legend text ("" = not in the legend)
  std::vector<double> angle_deg, lo, hi;
  Rgb colour{222, 228, 240};
};

struct PolarEnvelopeData {
  std::string title;
  std::string quantity;            // radial axis title with unit, e.g. "base displacement [cm]"
  std::vector<PolarCurve> curves;  // per record or case
  std::optional<PolarCurve> mean;  // drawn thick and black
  // Optional band (the min-max over the curves), shaded: lower and upper value per band angle.
  std::vector<double> band_angle_deg, band_lo, band_hi;
  // Further bands (ensemble min-max per curve), shaded in their colours under everything.
  std::vector<PolarBand> bands;
  std::string note;  // small, grey, bottom right (the study's column and selector)
};

Figure polar_envelope_figure(const PolarEnvelopeData& data, int width = 800, int height = 700,
                             PolarFrame* frame = nullptr);

struct PolarContourData {
  std::string title;
  std::string radius_title;       // e.g. "gap [cm]"
  std::string value_title;        // colour bar title with unit
  std::vector<double> angle_deg;  // ascending, n_a
  std::vector<double> radius;     // ascending (the gaps), n_r
  std::vector<double> value;      // n_r x n_a, row-major (radius major); NaN = no data (grey)
  std::string note;               // small, grey, bottom right (the study's column and selector)
};

// Cells are centred on the data points (edges half-way between neighbours); a gap range that
// starts at g_lo maps to the centre. The colour bar spans [min, max] of the finite values.
Figure polar_contour_figure(const PolarContourData& data, int width = 860, int height = 700,
                            PolarFrame* frame = nullptr);

}  // namespace isopound::post
