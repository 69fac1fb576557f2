// The element of a yielding 3D column (issue 23): ColumnLink with a unit law from the column's
// `hysteresis:` and its yield point per section axis from the column's elastic stiffness.
#pragma once

#include <memory>
#include <string>

#include "solver/core/element.h"
#include "solver/elements/bearing_link.h"
#include "solver/structures/config3d.h"

namespace isopound {

// Per section axis: k_1 = 12 E I22 / h^3, k_2 = 12 E I11 / h^3 (THEORY eq. 5.1-5.2);
// yield_drift_ratio: d_y,i = ratio h and V_y,i = k_i d_y,i; yield_moment (double curvature):
// V_y,i = 2 M_y / h and d_y,i = V_y,i / k_i.
struct ColumnYield {
  double drift[2];  // m
  double shear[2];  // N
};
ColumnYield column_yield(const Column3DConfig& column, double height);

// The element's label: "<building>/story <s + 1>/column <label>".
std::string column_element_label(const std::string& building, int storey, const std::string& label);
// "<building>/story <k>/hinged column <label>": the ColumnLine (column_line.h) of a column of a
// structure with struck_columns:, which a struck column replaces (struck_columns3d.cpp).
std::string hinged_column_label(const std::string& building, int storey, const std::string& label);

// The column (position and orientation in the plan frame, relative to the DOFs' origin) between
// the upper diaphragm and the lower one (DiaphragmDofs{}: the ground). Throws
// std::invalid_argument for a column without a yielding law.
std::unique_ptr<Element> make_column_element(const std::string& label,
                                             const Column3DConfig& column_W, double height,
                                             DiaphragmDofs upper, DiaphragmDofs lower);

}  // namespace isopound
