// Assembly of 3D buildings (THEORY section 5) into a Model: rigid diaphragms with DOFs (u, v,
// theta) at the plan origin, storey matrices k = T^T diag(k^I, k^II, k^theta) T (eq. 5.1-5.6),
// eccentric masses (eq. 5.7-5.10), bearings under the base slab, Rayleigh or non-classical damping.
#pragma once

#include <Eigen/Dense>
#include <vector>

#include "solver/core/model.h"
#include "solver/structures/config3d.h"

namespace isopound {

// A building frame placed in the model's plan frame: p_W = position + R(rotation) p_B.
Vec2 to_plan(const Building3DConfig& b, Vec2 p_B);
// A diaphragm (plan, eccentricity) of the building placed in the model's plan frame.
Diaphragm3DConfig diaphragm_in_plan(const Building3DConfig& b, const Diaphragm3DConfig& d_B);
// Columns of the building placed in the plan frame (position and orientation).
std::vector<Column3DConfig> columns_in_plan(const Building3DConfig& b,
                                            const std::vector<Column3DConfig>& columns_B);
// Centre of mass (centroid + eccentricity) of a diaphragm, in the frame of its plan.
Vec2 centre_of_mass(const Diaphragm3DConfig& diaphragm);

// Storey stiffness (3 x 3, DOFs at the plan origin) of the columns of one storey of height h;
// positions and orientations in the plan frame.
Eigen::Matrix3d storey_stiffness(const std::vector<Column3DConfig>& columns_W, double height,
                                 ColumnCoupling coupling);

// Polar moment of a diaphragm about its centre of mass, kg m^2: the given one, else from its
// plan (THEORY eq. 5.9; `rule` says whether the eccentricity's m e^2 is added).
double polar_moment_about_cm(const Diaphragm3DConfig& diaphragm, EccentricPolarMoment rule);

// The same split for the model: `matrix` holds the elastic columns and the torsion of the
// columns whose shear is an element (yielding ones, column_element.h, and with `hinged` every
// column: a building with struck_columns:, column_line.h); `initial` every column elastic (= the
// storey_stiffness above), for damping and modes.
struct StoreyStiffness {
  Eigen::Matrix3d matrix, initial;
};
StoreyStiffness storey_stiffness_split(const std::vector<Column3DConfig>& columns_W, double height,
                                       ColumnCoupling coupling, bool hinged = false);

// P-Delta (p_delta_stiffness.cpp): storey s's geometric stiffness about the plan origin.
Eigen::Matrix3d p_delta_stiffness(const Building3DConfig& building, std::size_t storey);

// Mass matrix (3 x 3, DOFs at the plan origin) of a diaphragm whose plan and eccentricity are
// in the plan frame.
Eigen::Matrix3d diaphragm_mass(const Diaphragm3DConfig& diaphragm_W, EccentricPolarMoment rule);

// The plan probes of storey shears (N, x and y) are labelled "<building>/" kStoreyShearPart
// "/story <k>"; a building gets them when a column yields or with P-Delta.
inline constexpr const char* kStoreyShearPart = "storey shear";

// Adds one building: DOFs (u, v, theta) per level (base slab first if isolated), matrices,
// bearings, damping and output probes (centre of mass and corners of each floor, every column's
// drift). Throws std::invalid_argument on an inconsistent building.
void add_building3d(Model& model, const Building3DConfig& building);

// The modes needed by `isopound modes`: the building's linear model with its bearings replaced by
// linear springs of the given stiffness (post-yield or initial), and the fixed-base
// superstructure. M and K over the building's DOFs.
struct LinearModel3D {
  Eigen::MatrixXd mass, stiffness, influence;
  std::vector<Dof> dofs;
};
LinearModel3D linear_model3d(const Building3DConfig& building, bool initial_bearing_stiffness,
                             bool fixed_base_superstructure);

// Refuses (RayleighModesError, rayleigh_modes.h) Rayleigh or non-classical damping at two
// modes of equal or nearly equal frequency, for the model input to report at its key.
void check_damping_modes(const Building3DConfig& building);

}  // namespace isopound
