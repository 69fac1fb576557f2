// Plain configuration of 3D buildings (THEORY section 5): rigid-diaphragm floors with convex
// plans, columns per storey, bearings under the base slab. SI; plan coordinates in the building's
// own frame, placed in the model's plan frame by (position, rotation).
#pragma once

#include <algorithm>
#include <array>
#include <limits>
#include <map>
#include <string>
#include <vector>

#include "geometry/convex_polygon.h"
#include "solver/structures/bearing.h"

namespace isopound {

// A rigid floor (or the base slab): plan outline, mass at the centroid + eccentricity.
struct Diaphragm3DConfig {
  std::vector<Vec2> plan;  // convex outline, m (building frame)
  double mass = 0.0;       // kg
  Vec2 eccentricity;       // (e_x, e_y): centre of mass = centroid + eccentricity, m
  // Polar moment about the centre of mass, kg m^2; 0: from the plan (THEORY eq. 5.9).
  double polar_moment = 0.0;
};

// A yielding column's lateral law (issue 23): a biaxial law in the column's section axes
// (1, 2), each axis normalised by its yield drift d_y,i and yield shear V_y,i = k_i d_y,i
// (k_1 = 12 E I22 / h^3, k_2 = 12 E I11 / h^3), so the interaction is circular in
// (V_1 / V_y,1, V_2 / V_y,2). Torsion (G J / h) stays elastic.
struct ColumnHysteresisConfig {
  // kElastic: no law, the column stays in the stiffness matrix (today's model); kBilinear:
  // biaxial bilinear, circular yield surface; kBoucWen: the bearings' coupled law (THEORY eq.
  // 5.27-5.29). No peak_oriented: it has no biaxial form.
  HysteresisLawConfig law;
  // Exactly one of the two is > 0: d_y = yield_drift_ratio h in both axes, or
  // V_y = 2 M_y / h (double curvature) in both axes and d_y,i = V_y / k_i.
  double yield_drift_ratio = 0.0;
  double yield_moment = 0.0;      // N m
  double post_yield_ratio = 0.0;  // alpha in [0, 1)
  bool yields() const { return law.model != HysteresisModel::kElastic; }
};

// A column of one storey (THEORY eq. 5.1-5.2): principal axis 1 at `orientation` from x.
struct Column3DConfig {
  std::string label;  // e.g. "A1" (grid: letter along x, number along y)
  Vec2 position;      // m (building frame)
  double I11 = 0.0;   // m^4, about axis 1 (resists motion along axis 2): k_2 = 12 E I11 / h^3
  double I22 = 0.0;   // m^4, about axis 2: k_1 = 12 E I22 / h^3
  double J = 0.0;     // m^4, torsion constant: k_theta = G J / h
  double orientation = 0.0;           // rad
  double E = 0.0;                     // Pa
  double G = 0.0;                     // Pa
  ColumnHysteresisConfig hysteresis;  // model kElastic: elastic in the stiffness matrix
};

// One storey: its columns and the floor on top of it.
struct Storey3DConfig {
  double height = 0.0;  // m
  std::vector<Column3DConfig> columns;
  Diaphragm3DConfig floor;
};

struct Bearing3DConfig {
  std::string label;
  Vec2 position;              // m (building frame)
  double carried_mass = 0.0;  // kg; 0: total mass / number of bearings
};

struct Damping3DConfig {
  // kRayleigh: C = a0 M + a1 K of the whole model (bearings at K_post or K_el) with ratio_a at
  // mode_a and ratio_b at mode_b of that model (thesis: 5 % at mode 1, 2 % at mode 4).
  // kNonClassical: as the 2D default: Rayleigh of the fixed-base superstructure at its modes
  // mode_a, mode_b (ratio_a, ratio_b) relative to the base slab, plus an isolation dashpot
  // c_b = 2 xi_b m_tot omega_b shared by the bearings in proportion to their carried mass.
  enum class Type { kRayleigh, kNonClassical, kNone };
  Type type = Type::kRayleigh;
  double ratio_a = 0.05, ratio_b = 0.02;
  int mode_a = 1, mode_b = 4;
  bool initial_bearing_stiffness = false;  // kRayleigh: bearings at K_el instead of K_post
  double isolation_ratio = 0.05;           // kNonClassical: xi_b
};

// THEORY eq. 5.9: the polar moment about the centre of mass of an eccentric floor.
enum class EccentricPolarMoment {
  kThesis,    // J_CM = m r_g^2 + m (e_x^2 + e_y^2) (thesis eq. 5.9, the default)
  kCentroid,  // J_CM = m r_g^2 (the slab's own polar moment, unchanged by the eccentricity)
};

// Column stiffness of a column with rotated principal axes (THEORY eq. 5.1-5.2).
enum class ColumnCoupling {
  kThesis,  // diag(k^I, k^II): the (k_1 - k_2) sin r cos r coupling is dropped (thesis)
  kFull,    // R diag(k_1, k_2) R^T: the full rotated stiffness
};

// Rubber bumpers (issue 27; docs/impact-laws.md, "Bumpers on moat walls (3D)", "Bumpers on a
// neighbour's face (3D)") on the inner faces of the moat walls or on the faces of a building's
// slabs: a strip `thickness` deep over [from, to] along each bumpered face, pressed by the other
// slab's edge over `height`. Linear F_N = (E h / t) A_c, Hertz-type F_N = E L_c h (d_N/t)^1.5,
// times (1 + zeta d'_N / v_imp)+; bottoming out at max_strain t onto the concrete k_N.
struct Bumper3DConfig {
  std::array<bool, 4> on{};  // sides with rubber (MoatWalls3DConfig::Side); none: no bumpers
  // Walls that follow the outline: the faces with rubber ("east", "north-east 2"); empty with
  // any(): every wall.
  std::vector<std::string> faces;
  double thickness = 0.0;                    // m, t
  std::string law = "linear";                // "linear" or "hertz"
  double modulus = 0.0;                      // Pa, the rubber's E
  double height = 0.0;                       // m, h: rubber height in contact with the slab edge
  double e = 0.8;                            // coefficient of restitution of the rubber, (0, 1]
  double max_strain = 0.6;                   // bottoming out at max_strain t
  double mu_static = 0.8, mu_kinetic = 0.6;  // rubber on the slab edge
  double from = 0.0;                         // m along the face from its start
  double to = std::numeric_limits<double>::infinity();  // m; +inf: to the face's end
  bool any() const { return on[0] || on[1] || on[2] || on[3]; }
  // Walls named by face (outline, polyline): whether the wall facing `face` has rubber.
  bool on_outline_face(const std::string& face) const {
    return any() && (faces.empty() || std::find(faces.begin(), faces.end(), face) != faces.end());
  }
};

// Moat walls around the base slab of an isolated building (issue 16 item 3): one straight wall
// per side, parallel to the side of the slab's bounding box in the building frame, at the side's
// gap, extending `extension` beyond the slab at each end. Rigid and immovable; the wall's mass
// (mass_per_length x its length) enters only the contact's m_eff.
struct MoatWalls3DConfig {
  enum Side { kEast, kWest, kNorth, kSouth };  // +x, -x, +y, -y of the building frame
  static constexpr std::array<const char*, 4> kSideNames = {"east", "west", "north", "south"};
  // `follow: box` (default): one straight wall per side of the slab's bounding box in the
  // building frame (sides, gap per side). `follow: outline`: one wall per straight run of the
  // slab's outline at `gap` (geometry/moat.h: convex corners extended, re-entrant ones mitred);
  // a rectangular slab's are the four box walls. `follow: polyline`: one wall per straight run of
  // `polyline`, on its side away from the slab, mitred where runs meet; each wall's gap is its
  // clearance at rest (measured, not declared). Rigid or flexible, with bumpers by face.
  enum class Follow { kBox, kOutline, kPolyline };
  Follow follow = Follow::kBox;
  // Walls named by face ("east", "north-east", "east 2"), not by box side: outline and polyline.
  bool by_face() const { return follow != Follow::kBox; }
  // follow: polyline: the walls' faces in the building frame, m, in the order drawn (at least two
  // points; oriented away from the slab by the model: pounding3d.cpp, all_wall_shapes).
  std::vector<Vec2> polyline;
  // follow: outline or polyline: the faces `sides` lists ("east", "north-east", "east 2":
  // pounding3d.h, moat_faces), a partial moat; empty: a wall on every run.
  std::vector<std::string> outline_sides;
  // follow: outline with `gap: {east: .., north-east: ..}`: each face's gap (every wall's face is
  // given: check_moat_faces; a face without a wall may be left out, its neighbours' mitres
  // then take the least given gap); empty: gap[0] for every wall.
  std::map<std::string, double> outline_gaps;
  std::array<bool, 4> present{};                  // no side: no walls
  std::array<double, 4> gap{0.2, 0.2, 0.2, 0.2};  // m, clear distance at rest
  double thickness = 1.0;                         // m, every wall's unless by face:
  // thickness: {east: 1 m, north-east: 60 cm}: each wall's by its face (box walls by side; every
  // wall's face given: checked with the plan); empty: `thickness` for every wall.
  std::map<std::string, double> thicknesses;
  double height = 1.0;              // m (drawing only)
  double extension = 1.0;           // m beyond the slab at each end
  double mass_per_length = 5000.0;  // kg/m, backfill included
  // Flexible walls (THEORY §7: a single-storey 3-DOF structure): each wall a rigid diaphragm
  // (u, v, θ) on a cantilever of height `height` with the wall's section (thickness x length),
  // concrete E, nu; stiffness-proportional damping with `damping_ratio` at the out-of-plane
  // mode. Rigid (false): immovable, its mass enters m_eff only.
  bool flexible = false;
  // model: {west: rigid, north: flexible}: each wall's model by its face (every wall's face
  // given); empty: `flexible` for every wall.
  std::map<std::string, bool> flexible_faces;
  double E = 30e9;  // Pa
  double nu = 0.2;
  double damping_ratio = 0.05;
  Bumper3DConfig bumper;  // rubber on the inner faces (issue 27); none by default
  bool any() const { return present[0] || present[1] || present[2] || present[3]; }
  // The wall facing `face` (a box side's name, or an outline's or polyline's face): its
  // thickness, and whether it is flexible; whether any wall is.
  double thickness_of(const std::string& face) const {
    const auto t = thicknesses.find(face);
    return t == thicknesses.end() ? thickness : t->second;
  }
  bool flexible_of(const std::string& face) const {
    if (flexible_faces.empty()) return flexible;
    const auto f = flexible_faces.find(face);
    return f != flexible_faces.end() && f->second;
  }
  bool any_flexible() const {
    return flexible || std::any_of(flexible_faces.begin(), flexible_faces.end(),
                                   [](const auto& f) { return f.second; });
  }
  // By face: whether the face has a wall (`sides` lists it, or there is no `sides`) ...
  bool has_outline_wall(const std::string& face) const {
    return outline_sides.empty() ||
           std::find(outline_sides.begin(), outline_sides.end(), face) != outline_sides.end();
  }
  // ... and its gap: given by face, else the one gap; a face without a wall left out of a gap
  // map takes the least given (its neighbours' mitres need one).
  double outline_gap(const std::string& face) const {
    if (outline_gaps.empty()) return gap[0];
    if (const auto g = outline_gaps.find(face); g != outline_gaps.end()) return g->second;
    double least = std::numeric_limits<double>::infinity();
    for (const auto& [name, g] : outline_gaps) least = std::min(least, g);
    return least;
  }
};

// How a building was placed next to another (`adjacent:`), kept for reports and checks.
struct Adjacency3DConfig {
  std::string to;    // the other structure's name ("": placed by position)
  int side = 0;      // MoatWalls3DConfig::Side of `to` on which this building stands
  double gap = 0.0;  // m, declared clear distance
};

// Issue 26, 3D (solver/structures/struck_columns3d.h, docs/floor-to-column.md): this building's
// columns where another structure's slab strikes a storey between its floors. Each facing column
// gets a lateral node at the slab's elevation: per principal axis a HingedColumn (E and I11 or
// I22 from the storey's column) with plastic hinges of moment M_y at both ends and at the node.
// given false: a slab between this building's floors is refused (site_checks.cpp).
struct StruckColumns3DConfig {
  bool given = false;
  // N m: M_y of the hinges bending along axis 1 (about axis 2, I22) and along axis 2 (I11).
  std::array<double, 2> yield_moment{0.0, 0.0};
  double hardening_ratio = 0.01;  // hinge hardening H = ratio x 6 E I / h, per axis
  bool shear_check = false;       // report the resultant |V| against V_n
  double shear_capacity = 0.0;    // V_n, N (shear_check only)
};

struct Building3DConfig {
  std::string name = "building";
  Vec2 position;          // m: where the building frame's origin sits in the model's plan frame
  double rotation = 0.0;  // rad, counter-clockwise, of the building frame
  bool isolated = true;
  // Isolation at any storey (issue 27 item 2, solver/structures/levels3d.h): the bearings sit on
  // floor isolation_level (0: on the ground), the base slab isolation_height above that floor;
  // storeys 1..isolation_level are the fixed-base substructure. Isolated only.
  int isolation_level = 0;
  double isolation_height = 0.0;  // m, > 0 when isolation_level > 0
  Diaphragm3DConfig base;         // isolated only: the isolated slab
  std::vector<Storey3DConfig> storeys;
  BearingConfig bearing;  // the law of every bearing
  // Isolated only; empty: one under each column of storey isolation_level + 1.
  std::vector<Bearing3DConfig> bearings;
  Damping3DConfig damping;
  EccentricPolarMoment polar_moment_rule = EccentricPolarMoment::kThesis;
  ColumnCoupling column_coupling = ColumnCoupling::kThesis;
  MoatWalls3DConfig walls;  // isolated only
  // Index (levels3d order, 0 = lowest) of the level the moat walls face; -1: the base slab.
  int walls_level = -1;
  Adjacency3DConfig adjacent;
  // Rubber on the faces of every slab of this building (bumper_layer3d.h, slab_bumper_strips):
  // it meets the slabs of other structures at the levels that pound; none by default.
  Bumper3DConfig bumper;
  // Storey geometric stiffness from the gravity load above (building3d.h, p_delta_stiffness).
  bool p_delta = false;
  // An elastic storey whose peak drift ratio exceeds this is flagged: the elastic model is
  // outside its range (summary elastic_limit_exceeded).
  double elastic_limit_drift_ratio = 0.01;
  StruckColumns3DConfig struck_columns;  // issue 26: when another slab strikes its columns
};

}  // namespace isopound
