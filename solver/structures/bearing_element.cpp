// Bearing elements of 3D buildings: BearingLink with make_bearing_material's law, and the
// bearing's linear stiffnesses for damping and modes (bearing_properties, the 2D rules).
#include "solver/structures/bearing_element.h"

namespace isopound {

BearingStiffness bearing_stiffness(const BearingConfig& c, double m) {
  const IsolatorProperties p = bearing_properties(c, m);
  return {p.post_yield_stiffness,
          c.model == BearingConfig::Model::kLinear ? p.post_yield_stiffness : p.elastic_stiffness};
}

std::unique_ptr<Element> make_bearing_element(const std::string& label, DiaphragmDofs dofs,
                                              const Eigen::Vector2d& p_OB,
                                              const BearingConfig& config, double carried_mass,
                                              DiaphragmDofs lower) {
  return std::make_unique<BearingLink>(label, dofs, p_OB,
                                       make_bearing_material(config, carried_mass), lower);
}

}  // namespace isopound
