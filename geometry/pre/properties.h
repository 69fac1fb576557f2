// Section and stiffness properties of 3D structures (issue 12 item 2): per diaphragm area,
// centroid, polar radius of gyration, centre of mass; per storey the centre of stiffness (the
// point where a translation of the storey's columns makes no torsion), the eccentricity e = CM - CS
// and the torsional radii r_x = sqrt(K_theta,S / K_y), r_y = sqrt(K_theta,S / K_x) (EC8 4.2.3.2).
#pragma once

#include <Eigen/Dense>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "geometry/convex_polygon.h"
#include "solver/structures/config.h"

namespace isopound::pre {

struct DiaphragmProperties {
  std::string level;  // "base", "floor 1", ...
  double elevation = 0.0;
  double mass = 0.0;                     // kg
  AreaProperties exact;                  // polygon formulas (plan frame W)
  double radius_of_gyration = 0.0;       // m, sqrt(J_c / A) of the plan area about its centroid
  Vec2 p_WM;                             // centre of mass = centroid + eccentricity
  double mass_radius_of_gyration = 0.0;  // l_s = sqrt(J_CM / m), J_CM as the solver takes it
  // The same integrals over a Gmsh triangle mesh of the slab (filled by mesh_check()).
  bool meshed = false;
  AreaProperties mesh;
  int triangles = 0;
  double relative_difference = 0.0;  // max of |dA|/A, |dC|/sqrt(A), |dJ|/J
};

// One storey's columns (storey >= 1), or the isolation layer's bearings (storey 0) at K_post.
struct StoreyProperties {
  int storey = 0;
  std::string label;            // "storey 1", ..., "isolation"
  double k_x = 0.0, k_y = 0.0;  // N/m, lateral stiffness along x and y
  double k_theta = 0.0;         // N m/rad, torsional stiffness about the centre of stiffness
  Vec2 p_WS;                    // centre of stiffness
  Vec2 p_WM;                    // centre of the mass it carries (the floor above; isolation:
                                // everything above the bearings)
  Vec2 eccentricity;            // e = CM - CS, m
  double r_x = 0.0, r_y = 0.0;  // torsional radii, m
  double l_s = 0.0;             // radius of gyration of that mass about its CM, m
};

struct StructureProperties {
  std::string name;
  bool isolated = true;
  std::vector<DiaphragmProperties> diaphragms;  // base first (isolated), then floors
  std::vector<StoreyProperties> storeys;        // isolation first (isolated), then storeys
};

// Centre of stiffness of a 3 x 3 storey stiffness (DOFs u, v, theta at the plan origin, a point p
// moving by (u - theta p_y, v + theta p_x)): the point S where the coupling between translation
// and rotation vanishes; k_theta about S.
void centre_of_stiffness(const Eigen::Matrix3d& k, Vec2& p_WS, double& k_theta_S);

std::vector<StructureProperties> structure_properties(const ModelConfig& config);

nlohmann::ordered_json properties_json(const std::vector<StructureProperties>& p);
std::string properties_text(const std::vector<StructureProperties>& p);

}  // namespace isopound::pre
