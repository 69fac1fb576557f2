// Yielding 3D columns: the yield point per section axis and ColumnLink with a unit law
// (K_el = F_y = u_y = 1) of the column's model, from the hysteresis table's biaxial factory.
#include "solver/structures/column_element.h"

#include <stdexcept>

#include "solver/elements/column_link.h"
#include "solver/materials/hysteresis_law.h"

namespace isopound {

ColumnYield column_yield(const Column3DConfig& c, double h) {
  const double h3 = h * h * h;
  const double k[2] = {12.0 * c.E * c.I22 / h3, 12.0 * c.E * c.I11 / h3};
  const ColumnHysteresisConfig& y = c.hysteresis;
  ColumnYield r{};
  for (int i = 0; i < 2; ++i) {
    if (y.yield_drift_ratio > 0) {
      r.drift[i] = y.yield_drift_ratio * h;
      r.shear[i] = k[i] * r.drift[i];
    } else {
      r.shear[i] = 2.0 * y.yield_moment / h;
      r.drift[i] = r.shear[i] / k[i];
    }
  }
  return r;
}

std::string column_element_label(const std::string& building, int storey,
                                 const std::string& label) {
  return building + "/story " + std::to_string(storey + 1) + "/column " + label;
}

std::string hinged_column_label(const std::string& building, int storey, const std::string& label) {
  return building + "/story " + std::to_string(storey + 1) + "/hinged column " + label;
}

std::unique_ptr<Element> make_column_element(const std::string& label, const Column3DConfig& c,
                                             double height, DiaphragmDofs upper,
                                             DiaphragmDofs lower) {
  const ColumnHysteresisConfig& y = c.hysteresis;
  if (!(y.yield_drift_ratio > 0) && !(y.yield_moment > 0))
    throw std::invalid_argument("column " + c.label + ": needs yield_drift_ratio or yield_moment");
  if (!y.yields())
    throw std::invalid_argument("column " + c.label + ": an elastic column has no element");
  const double alpha = y.post_yield_ratio;
  // The unit law (K_el = F_y = u_y = 1, deformation d / d_y: no length): ColumnLink scales each
  // axis by its yield point.
  std::unique_ptr<BiaxialMaterial> law =
      make_biaxial_hysteresis(y.law, {1.0, 1.0, 1.0, alpha, 0.0});
  const ColumnYield yield = column_yield(c, height);
  ColumnLinkGeometry g;
  g.p_O = Eigen::Vector2d(c.position.x, c.position.y);
  g.orientation = c.orientation;
  g.yield_drift = Eigen::Vector2d(yield.drift[0], yield.drift[1]);
  g.yield_shear = Eigen::Vector2d(yield.shear[0], yield.shear[1]);
  return std::make_unique<ColumnLink>(label, upper, lower, g, std::move(law), alpha);
}

}  // namespace isopound
