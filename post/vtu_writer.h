// Writing a FrameMesh as a VTK XML unstructured grid (.vtu, Float64 points and arrays, binary
// appended, zlib). The only place that includes VTK's data-model headers for output.
#pragma once

#include <string>

#include "post/animation.h"

namespace isopound::post {

// Throws std::runtime_error when the file cannot be written.
void write_vtu(const FrameMesh& mesh, const std::string& path);

}  // namespace isopound::post
