// A PNG read back into RGB pixels (VTK's PNG reader), for the pixel tests of isopound-post and
// isopound-pre. Rows from the top; at(x, y_up) addresses them from the bottom as the figures do.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace isopound::test {

struct Image {
  int width = 0, height = 0;
  std::vector<unsigned char> rgb;  // row 0 = top
  const unsigned char* at(int x, int y_up) const {
    return &rgb[3 * (static_cast<std::size_t>(height - 1 - y_up) * width + x)];
  }
  // Variance of the grey level: 0 for a blank image.
  double variance() const;
};

Image read_png(const std::string& path);  // throws std::runtime_error

}  // namespace isopound::test
