// A figure as plain data: filled convex polygons, lines, markers and text in pixel coordinates,
// drawn in that order. Origin at the bottom-left corner, x to the right, y up (VTK's convention).
#pragma once

#include <array>
#include <string>
#include <vector>

namespace isopound::post {

struct Rgb {
  unsigned char r = 0, g = 0, b = 0;
  bool operator==(const Rgb&) const = default;
};

struct Point2 {
  double x = 0.0, y = 0.0;
};

struct Polyline {
  std::vector<Point2> points;
  Rgb colour;
  double width = 1.0;  // px
};

// Convex polygon (a fan from the first point is drawn), filled.
struct FilledPolygon {
  std::vector<Point2> points;
  Rgb colour;
};

// A plot marker: a filled convex polygon with an outline, drawn above every line.
struct Marker {
  std::vector<Point2> points;  // convex, in order round it
  Rgb fill, edge;
  double edge_width = 1.0;  // px; 0: no outline
};

enum class HAlign { kLeft, kCentre, kRight };
enum class VAlign { kBottom, kCentre, kTop };

struct Text {
  Point2 at;
  std::string text;  // UTF-8 (Greek letters and units render with DejaVu Sans)
  double size = 14;  // pt
  Rgb colour;
  HAlign h = HAlign::kCentre;
  VAlign v = VAlign::kCentre;
  double angle_deg = 0.0;  // counter-clockwise
  bool bold = false;
};

struct Figure {
  int width = 900, height = 600;  // px
  Rgb background{255, 255, 255};
  // Drawn in this order: polygons, then lines, then markers, then text.
  std::vector<FilledPolygon> polygons;
  std::vector<Polyline> lines;
  std::vector<Text> texts;
  std::vector<Marker> markers;  // drawn before the texts (listed last for brace-initialisers)
};

// Colours for series (distinct, print-friendly) and the colour map of contour plots.
Rgb series_colour(int index);
// Viridis-like map of s in [0, 1] (clamped): dark purple at 0, yellow at 1.
Rgb colour_map(double s);

// "Nice" axis ticks covering [lo, hi]: 1, 2 or 5 times a power of ten, about `target` of them.
std::vector<double> nice_ticks(double lo, double hi, int target = 6);
// Ticks at powers of ten (and 2, 5 between when the range is short) for a log axis, lo, hi > 0.
std::vector<double> log_ticks(double lo, double hi);
// A tick label: shortest of %g forms that keeps the tick distinguishable.
std::string tick_label(double value);

}  // namespace isopound::post
