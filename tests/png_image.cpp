// PNG reading for the pixel tests (VTK's PNG reader; VTK images start at the bottom row).
#include "png_image.h"

#include <vtkDataArray.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPNGReader.h>
#include <vtkPointData.h>

#include <algorithm>
#include <filesystem>
#include <stdexcept>

namespace isopound::test {

Image read_png(const std::string& path) {
  if (!std::filesystem::exists(path)) throw std::runtime_error(path + ": no such PNG");
  vtkNew<vtkPNGReader> reader;
  reader->SetFileName(path.c_str());
  reader->Update();
  vtkImageData* img = reader->GetOutput();
  int dims[3];
  img->GetDimensions(dims);
  Image out;
  out.width = dims[0];
  out.height = dims[1];
  vtkDataArray* s = img->GetPointData()->GetScalars();
  const int nc = s->GetNumberOfComponents();
  out.rgb.resize(3 * static_cast<std::size_t>(out.width) * out.height);
  for (int y = 0; y < out.height; ++y)
    for (int x = 0; x < out.width; ++x)
      for (int c = 0; c < 3; ++c)
        out.rgb[3 * (static_cast<std::size_t>(out.height - 1 - y) * out.width + x) + c] =
            static_cast<unsigned char>(s->GetComponent(y * out.width + x, std::min(c, nc - 1)));
  return out;
}

double Image::variance() const {
  double sum = 0, sum2 = 0;
  const std::size_t n = rgb.size() / 3;
  for (std::size_t i = 0; i < n; ++i) {
    const double g = (rgb[3 * i] + rgb[3 * i + 1] + rgb[3 * i + 2]) / 3.0;
    sum += g;
    sum2 += g * g;
  }
  return sum2 / n - (sum / n) * (sum / n);
}

}  // namespace isopound::test
