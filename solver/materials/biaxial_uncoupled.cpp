// Uncoupled biaxial bearing: ownership of the two uniaxial laws (copy clones them).
// F_x depends on d_x only and F_y on d_y only.
#include "solver/materials/biaxial_uncoupled.h"

#include <stdexcept>

namespace isopound {

UncoupledBiaxialMaterial::UncoupledBiaxialMaterial(std::unique_ptr<UniaxialMaterial> law_x,
                                                   std::unique_ptr<UniaxialMaterial> law_y)
    : x_(std::move(law_x)), y_(std::move(law_y)) {
  if (!x_ || !y_) throw std::invalid_argument("uncoupled bearing: missing uniaxial law");
}

UncoupledBiaxialMaterial::UncoupledBiaxialMaterial(const UncoupledBiaxialMaterial& other)
    : BiaxialMaterial(other), x_(other.x_->clone()), y_(other.y_->clone()) {}

}  // namespace isopound
