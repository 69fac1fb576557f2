// Rendering a Figure to a PNG file with VTK's 2D context (the only file that includes VTK's
// rendering headers). Needs an X display: construct a PrivateDisplay first (headless.h).
#pragma once

#include <string>

#include "post/figure.h"

namespace isopound::post {

// The font for every text: DejaVu Sans (units such as [m/s²] and Greek letters render).
constexpr const char* kFontFile = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";
constexpr const char* kBoldFontFile = "/usr/share/fonts/truetype/dejavu/DejaVuSans-Bold.ttf";

// Writes `figure` as a PNG of exactly figure.width x figure.height pixels. Throws
// std::runtime_error when the file cannot be written or the font is missing.
void render_png(const Figure& figure, const std::string& path);

}  // namespace isopound::post
