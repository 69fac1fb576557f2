// Assembly of 3D buildings: storey matrices summed over columns and placed tridiagonally over the
// levels, diaphragm masses about the plan origin, bearings at their plan positions, damping.
#include "solver/structures/building3d.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>
#include <utility>

#include "geometry/plan_shape.h"
#include "solver/core/modes.h"
#include "solver/elements/column_line.h"
#include "solver/structures/bearing_element.h"
#include "solver/structures/column_element.h"
#include "solver/structures/levels3d.h"
#include "solver/structures/rayleigh_modes.h"

namespace isopound {

namespace {

// Rows of T = [[1, 0, -y], [0, 1, x], [0, 0, 1]]: a point p of a diaphragm moves by T q.
Eigen::Matrix3d point_transform(Vec2 p) {
  Eigen::Matrix3d T = Eigen::Matrix3d::Identity();
  T(0, 2) = -p.y;
  T(1, 2) = p.x;
  return T;
}

Vec2 rotate(double angle, Vec2 v) {
  const double c = std::cos(angle), s = std::sin(angle);
  return {c * v.x - s * v.y, s * v.x + c * v.y};
}

// One building's levels (levels3d.h order), three DOFs each, in the plan frame.
struct Assembly {
  // Over the building's DOFs. stiffness: what the model's matrix holds (yielding columns' shear
  // is in their elements, P-Delta included); initial_stiffness: every column elastic, no P-Delta
  // (damping and modes).
  Eigen::MatrixXd mass, stiffness, initial_stiffness, influence;
  std::vector<Dof> dofs;
  std::vector<Diaphragm3DConfig> levels_W;  // per level, plan frame
  std::vector<Vec2> bearing_positions_W;
  std::vector<std::string> bearing_labels;
  std::vector<double> bearing_masses;
  double total_mass = 0.0;
  double isolated_mass = 0.0;                 // the base slab and the levels above it
  int bearing_upper = 0, bearing_lower = -1;  // building DOF of the base slab, of the level under
};

// A storey's 3 x 3 matrix k between levels upper and lower (< 0: the ground): [k, -k; -k, k].
void add_storey(Eigen::MatrixXd& K, int upper, int lower, const Eigen::Matrix3d& k) {
  K.block<3, 3>(upper, upper) += k;
  if (lower >= 0) {
    K.block<3, 3>(lower, lower) += k;
    K.block<3, 3>(lower, upper) -= k;
    K.block<3, 3>(upper, lower) -= k;
  }
}

// The building's levels (levels3d.h order), storeys and bearing positions. A fixed-base building
// (isolated false) has no base slab: superstructure3d() and substructure3d() give its parts.
Assembly assemble(const Building3DConfig& b) {
  if (b.storeys.empty()) throw std::invalid_argument("building '" + b.name + "' has no storeys");
  Assembly a;
  const std::vector<Level3D> levels_B = levels3d(b);
  for (const Level3D& level : levels_B)
    a.levels_W.push_back(diaphragm_in_plan(b, *level.diaphragm));
  const int levels = static_cast<int>(a.levels_W.size());
  const int n = 3 * levels;
  const int base = base_level3d(b);
  a.mass.setZero(n, n);
  a.stiffness.setZero(n, n);
  a.initial_stiffness.setZero(n, n);
  a.influence.setZero(n, 2);
  for (int l = 0; l < levels; ++l) {
    const Eigen::Matrix3d m = diaphragm_mass(a.levels_W[l], b.polar_moment_rule);
    a.mass.block<3, 3>(3 * l, 3 * l) = m;
    a.total_mass += m(0, 0);
    a.influence(3 * l, 0) = 1.0;
    a.influence(3 * l + 1, 1) = 1.0;
    const std::string level = b.name + "/" + levels_B[l].name;
    a.dofs.push_back({level + " (x)", 0, l, DofKind::kTranslationX, 1.0});
    a.dofs.push_back({level + " (y)", 0, l, DofKind::kTranslationY, 1.0});
    a.dofs.push_back({level + " (theta)", 0, l, DofKind::kRotation, std::sqrt(m(2, 2) / m(0, 0))});
  }
  // The mass the bearings carry: the base slab and the levels above it.
  if (base >= 0)
    for (int l = base; l < levels; ++l) a.isolated_mass += a.mass(3 * l, 3 * l);
  for (std::size_t s = 0; s < b.storeys.size(); ++s) {
    const Storey3DConfig& storey = b.storeys[s];
    if (!(storey.height > 0))
      throw std::invalid_argument("storey " + std::to_string(s + 1) + ": height must be > 0");
    const StoreyStiffness k =
        storey_stiffness_split(columns_in_plan(b, storey.columns), storey.height, b.column_coupling,
                               b.struck_columns.given);
    const int storey_number = static_cast<int>(s) + 1;
    const int upper = 3 * floor_level3d(b, storey_number);
    const int lower = 3 * storey_lower_level3d(b, storey_number);  // < 0: the ground
    add_storey(a.stiffness, upper, lower, k.matrix);
    add_storey(a.initial_stiffness, upper, lower, k.initial);
    if (b.p_delta) add_storey(a.stiffness, upper, lower, p_delta_stiffness(b, s));
  }
  if (base >= 0) {
    a.bearing_upper = 3 * base;
    a.bearing_lower = 3 * bearing_lower_level3d(b);
    if (b.bearings.empty()) {
      for (const Column3DConfig& c : b.storeys.at(static_cast<std::size_t>(base)).columns) {
        a.bearing_positions_W.push_back(to_plan(b, c.position));
        a.bearing_labels.push_back(c.label);
        a.bearing_masses.push_back(0.0);
      }
    } else {
      for (const Bearing3DConfig& c : b.bearings) {
        a.bearing_positions_W.push_back(to_plan(b, c.position));
        a.bearing_labels.push_back(c.label);
        a.bearing_masses.push_back(c.carried_mass);
      }
    }
    if (a.bearing_positions_W.empty())
      throw std::invalid_argument("building '" + b.name + "': an isolated building needs bearings");
    const double share = a.isolated_mass / static_cast<double>(a.bearing_positions_W.size());
    for (double& m : a.bearing_masses)
      if (m == 0.0) m = b.bearing.carried_mass > 0 ? b.bearing.carried_mass : share;
  }
  return a;
}

// A column of a building with struck_columns: as a ColumnLine, per section axis a column fixed
// at both ends with hinges at M_y along that axis (axis 1 from x at its orientation: I22 and
// M_y[0]; axis 2: I11 and M_y[1]); its drift along the axis from both diaphragms' (u, v, theta)
// at the column's plan position (lower < 0: the ground).
ColumnLineSpec hinged_column_line(const StruckColumns3DConfig& sc, const Column3DConfig& c,
                                  double height, int upper, int lower) {
  ColumnLineSpec spec;
  spec.direction_count = 2;
  spec.count = 1;
  spec.shear_capacity = sc.shear_check ? sc.shear_capacity : 0.0;
  const double cr = std::cos(c.orientation), sr = std::sin(c.orientation);
  const Vec2 axis[2] = {{cr, sr}, {-sr, cr}};
  const double I[2] = {c.I22, c.I11};
  for (std::size_t i = 0; i < 2; ++i) {
    ColumnLineSpec::Direction& d = spec.directions[i];
    d.column = {c.E,
                I[i],
                height,
                0.5 * height,
                sc.yield_moment[i],
                sc.hardening_ratio * 6.0 * c.E * I[i] / height};
    // The point p's displacement (u - p_y theta, v + p_x theta) along the axis.
    const double ct = -c.position.y * axis[i].x + c.position.x * axis[i].y;
    for (const auto& [dofs, sign] : {std::pair{upper, 1.0}, std::pair{lower, -1.0}}) {
      if (dofs < 0) continue;
      d.add_term(dofs, sign * axis[i].x);
      d.add_term(dofs + 1, sign * axis[i].y);
      d.add_term(dofs + 2, sign * ct);
    }
  }
  return spec;
}

// Linear springs (k in x and y) at the bearings, between the base slab's block and the block of
// the level under the bearings (the ground when that is < 0): B^T k B with B = [T, -T].
void add_bearing_springs(Eigen::MatrixXd& K, const Assembly& a,
                         const std::vector<double>& stiffness) {
  for (std::size_t j = 0; j < a.bearing_positions_W.size(); ++j) {
    const Eigen::Matrix3d T = point_transform(a.bearing_positions_W[j]);
    const Eigen::Vector3d k(stiffness[j], stiffness[j], 0.0);
    add_storey(K, a.bearing_upper, a.bearing_lower, T.transpose() * k.asDiagonal() * T);
  }
}

std::vector<double> bearing_stiffnesses(const Building3DConfig& b, const Assembly& a,
                                        bool initial) {
  std::vector<double> k;
  for (double m : a.bearing_masses) {
    const BearingStiffness s = bearing_stiffness(b.bearing, m);
    k.push_back(initial ? s.initial : s.post_yield);
  }
  return k;
}

// Rayleigh C = a0 M + a1 K with ratio_a at mode_a and ratio_b at mode_b of (K, M).
Eigen::MatrixXd rayleigh(const Eigen::MatrixXd& K, const Eigen::MatrixXd& M,
                         const Eigen::MatrixXd& influence, const Damping3DConfig& d,
                         const std::string& what) {
  const Modes modes = compute_modes(K, M, influence.col(0));
  const int count = static_cast<int>(modes.omega.size());
  if (d.mode_a < 1 || d.mode_b < 1 || d.mode_a > count || d.mode_b > count || d.mode_a == d.mode_b)
    throw std::invalid_argument("Rayleigh damping needs two distinct modes in 1.." +
                                std::to_string(count) + " of " + what);
  require_distinct_modes(modes.omega, d.mode_a, d.mode_b, what);
  const double wa = modes.omega[d.mode_a - 1], wb = modes.omega[d.mode_b - 1];
  // xi = a0 / (2 omega) + a1 omega / 2 at both modes.
  Eigen::Matrix2d A;
  A << 0.5 / wa, 0.5 * wa, 0.5 / wb, 0.5 * wb;
  const Eigen::Vector2d coef = A.partialPivLu().solve(Eigen::Vector2d(d.ratio_a, d.ratio_b));
  return coef[0] * M + coef[1] * K;
}

}  // namespace

Vec2 to_plan(const Building3DConfig& b, Vec2 p_B) {
  return b.position + rotate(b.rotation, p_B);
}

Diaphragm3DConfig diaphragm_in_plan(const Building3DConfig& b, const Diaphragm3DConfig& d) {
  Diaphragm3DConfig w = d;
  for (Vec2& p : w.plan) p = to_plan(b, p);
  w.eccentricity = rotate(b.rotation, d.eccentricity);
  return w;
}

std::vector<Column3DConfig> columns_in_plan(const Building3DConfig& b,
                                            const std::vector<Column3DConfig>& columns) {
  std::vector<Column3DConfig> w = columns;
  for (Column3DConfig& c : w) {
    c.position = to_plan(b, c.position);
    c.orientation += b.rotation;
  }
  return w;
}

Vec2 centre_of_mass(const Diaphragm3DConfig& d) {
  return plan_area_properties(d.plan).p_WC + d.eccentricity;
}

Eigen::Matrix3d storey_stiffness(const std::vector<Column3DConfig>& columns, double h,
                                 ColumnCoupling coupling) {
  return storey_stiffness_split(columns, h, coupling).initial;
}

StoreyStiffness storey_stiffness_split(const std::vector<Column3DConfig>& columns, double h,
                                       ColumnCoupling coupling, bool hinged) {
  StoreyStiffness k{Eigen::Matrix3d::Zero(), Eigen::Matrix3d::Zero()};
  for (const Column3DConfig& c : columns) {
    if (!(c.I11 > 0) || !(c.I22 > 0) || !(c.J > 0) || !(c.E > 0) || !(c.G > 0))
      throw std::invalid_argument("column " + c.label + ": section and moduli must be > 0");
    const double h3 = h * h * h;
    const double k1 = 12.0 * c.E * c.I22 / h3, k2 = 12.0 * c.E * c.I11 / h3;
    const double cr = std::cos(c.orientation), sr = std::sin(c.orientation);
    Eigen::Matrix3d local = Eigen::Matrix3d::Zero();
    local(0, 0) = k1 * cr * cr + k2 * sr * sr;  // k^I
    local(1, 1) = k1 * sr * sr + k2 * cr * cr;  // k^II
    // A yielding or hinged column's element acts in its section axes: the full rotated stiffness.
    const bool in_element = c.hysteresis.yields() || hinged;
    if (coupling == ColumnCoupling::kFull || in_element)
      local(0, 1) = local(1, 0) = (k1 - k2) * sr * cr;
    local(2, 2) = c.G * c.J / h;  // k^theta
    const Eigen::Matrix3d T = point_transform(c.position);
    const Eigen::Matrix3d k_c = T.transpose() * local * T;
    k.initial += k_c;
    if (in_element)
      k.matrix(2, 2) += local(2, 2);  // T^T diag(0, 0, k_theta) T: torsion only
    else
      k.matrix += k_c;
  }
  return k;
}

namespace {

double polar_moment_about_cm(const Diaphragm3DConfig& d, const AreaProperties& area, double e2,
                             EccentricPolarMoment rule) {
  double j_cm = d.polar_moment;
  if (j_cm <= 0) {
    j_cm = d.mass * area.radius_of_gyration_sq();
    if (rule == EccentricPolarMoment::kThesis) j_cm += d.mass * e2;
  }
  return j_cm;
}

}  // namespace

double polar_moment_about_cm(const Diaphragm3DConfig& d, EccentricPolarMoment rule) {
  return polar_moment_about_cm(d, plan_area_properties(d.plan), dot(d.eccentricity, d.eccentricity),
                               rule);
}

Eigen::Matrix3d diaphragm_mass(const Diaphragm3DConfig& d, EccentricPolarMoment rule) {
  if (!(d.mass > 0)) throw std::invalid_argument("diaphragm mass must be > 0");
  const AreaProperties area = plan_area_properties(d.plan);
  const Vec2 cm = area.p_WC + d.eccentricity;
  const double e2 = dot(d.eccentricity, d.eccentricity);
  const double j_cm = polar_moment_about_cm(d, area, e2, rule);
  const Eigen::Matrix3d T = point_transform(cm);
  return T.transpose() * Eigen::Vector3d(d.mass, d.mass, j_cm).asDiagonal() * T;
}

void add_building3d(Model& model, const Building3DConfig& b) {
  const Assembly a = assemble(b);
  const std::vector<Level3D> levels_B = levels3d(b);
  const int offset = model.size();
  const int nb = static_cast<int>(a.dofs.size());
  const int structure = static_cast<int>(model.structures.size());
  model.grow(offset + nb);
  model.mass.block(offset, offset, nb, nb) = a.mass;
  model.stiffness.block(offset, offset, nb, nb) = a.stiffness;
  model.influence.segment(offset, nb) = a.influence.col(0);
  model.influence_y.segment(offset, nb) = a.influence.col(1);
  StructureInfo info;
  info.name = b.name;
  info.has_base = b.isolated;
  if (b.isolated) {
    info.base_level = b.isolation_level;
    info.isolation_height = b.isolation_height;
  }
  for (Dof d : a.dofs) {
    d.structure = structure;
    model.dofs.push_back(d);
  }
  for (std::size_t l = 0; l < a.levels_W.size(); ++l) {
    info.level_dofs.push_back(offset + 3 * static_cast<int>(l));
    info.level_dofs_y.push_back(offset + 3 * static_cast<int>(l) + 1);
  }
  // story_heights stay empty: storey drifts of a 3D building are the column probes below.

  // Damping.
  Eigen::MatrixXd C = Eigen::MatrixXd::Zero(nb, nb);
  const Damping3DConfig& d = b.damping;
  if (d.type == Damping3DConfig::Type::kRayleigh) {
    Eigen::MatrixXd K = a.initial_stiffness;
    if (b.isolated)
      add_bearing_springs(K, a, bearing_stiffnesses(b, a, d.initial_bearing_stiffness));
    C = rayleigh(K, a.mass, a.influence, d, "building '" + b.name + "'");
  } else if (d.type == Damping3DConfig::Type::kNonClassical) {
    const Assembly s = b.isolated ? assemble(superstructure3d(b)) : a;
    const Eigen::MatrixXd c_s =
        rayleigh(s.initial_stiffness, s.mass, s.influence, d,
                 "the fixed-base superstructure of building '" + b.name + "'");
    if (b.isolated) {
      // Superstructure relative to the base slab: w_i = q_i - q_base, C = T^T C_s T.
      const int nf = static_cast<int>(s.dofs.size()), base = a.bearing_upper;
      Eigen::MatrixXd T = Eigen::MatrixXd::Zero(nf, nb);
      T.rightCols(nf).setIdentity();
      for (int i = 0; i < nf; i += 3) T.block<3, 3>(i, base) = -Eigen::Matrix3d::Identity();
      C = T.transpose() * c_s * T;
      // Substructure (documented choice, docs/isolation-level.md, "3D buildings"): Rayleigh of the
      // fixed-base substructure at the same ratios and modes, clipped to its mode count (1 and 3k
      // if they then coincide).
      if (base > 0) {
        const Assembly sub = assemble(substructure3d(b));
        Damping3DConfig d_sub = d;
        d_sub.mode_a = std::min(d.mode_a, base);  // base = 3k: the substructure's mode count
        d_sub.mode_b = std::min(d.mode_b, base);
        if (d_sub.mode_a == d_sub.mode_b) d_sub.mode_a = 1, d_sub.mode_b = base;
        C.topLeftCorner(base, base) +=
            rayleigh(sub.initial_stiffness, sub.mass, sub.influence, d_sub,
                     "the fixed-base substructure of building '" + b.name + "'");
      }
      double carried = 0.0;
      for (double m : a.bearing_masses) carried += m;
      const double omega_b = 2.0 * std::numbers::pi / b.bearing.period;
      const double c_b = 2.0 * d.isolation_ratio * a.isolated_mass * omega_b;
      std::vector<double> c_j;
      for (double m : a.bearing_masses) c_j.push_back(c_b * m / carried);
      add_bearing_springs(C, a, c_j);
    } else {
      C = c_s;
    }
  }
  model.damping.block(offset, offset, nb, nb) += C;

  // Bearings.
  if (b.isolated) {
    for (std::size_t j = 0; j < a.bearing_positions_W.size(); ++j) {
      const Vec2 p = a.bearing_positions_W[j];
      const int upper = offset + a.bearing_upper, lower = offset + a.bearing_lower;
      model.elements.push_back(make_bearing_element(
          b.name + "/bearing " + a.bearing_labels[j], {upper, upper + 1, upper + 2},
          Eigen::Vector2d(p.x, p.y), b.bearing, a.bearing_masses[j],
          a.bearing_lower >= 0 ? DiaphragmDofs{lower, lower + 1, lower + 2} : DiaphragmDofs{}));
    }
  }

  // Yielding columns: their shear as elements between the levels they join.
  // Building DOF of the level over storey s (0-based) and of the level under it (< 0: ground).
  const auto storey_upper = [&](std::size_t s) {
    return 3 * floor_level3d(b, static_cast<int>(s) + 1);
  };
  const auto storey_lower = [&](std::size_t s) {
    const int l = storey_lower_level3d(b, static_cast<int>(s) + 1);
    return l < 0 ? -1 : offset + 3 * l;
  };
  for (std::size_t s = 0; s < b.storeys.size(); ++s) {
    const int upper = offset + storey_upper(s);
    const int lower = storey_lower(s);
    for (const Column3DConfig& c : columns_in_plan(b, b.storeys[s].columns)) {
      if (b.struck_columns.given) {
        const std::string label = hinged_column_label(b.name, static_cast<int>(s), c.label);
        // Every column with the hinges of struck_columns: (column_line.h), struck or not.
        if (c.hysteresis.yields())
          throw std::invalid_argument(
              label +
              ": with struck_columns: a column yields through its hinges (M_y); give it "
              "no hysteresis:, or drop struck_columns:");
        model.elements.push_back(std::make_unique<ColumnLine>(
            label, hinged_column_line(b.struck_columns, c, b.storeys[s].height, upper, lower)));
        continue;
      }
      if (!c.hysteresis.yields()) continue;
      model.elements.push_back(make_column_element(
          column_element_label(b.name, static_cast<int>(s), c.label), c, b.storeys[s].height,
          {upper, upper + 1, upper + 2},
          lower >= 0 ? DiaphragmDofs{lower, lower + 1, lower + 2} : DiaphragmDofs{}));
    }
  }

  // Output probes: centre of mass and corners of each level; each column's drift.
  const auto point_terms = [](int upper, int lower, Vec2 p, PlanProbe& probe) {
    probe.x_terms = {{upper, 1.0}, {upper + 2, -p.y}};
    probe.y_terms = {{upper + 1, 1.0}, {upper + 2, p.x}};
    if (lower >= 0) {
      probe.x_terms.insert(probe.x_terms.end(), {{lower, -1.0}, {lower + 2, p.y}});
      probe.y_terms.insert(probe.y_terms.end(), {{lower + 1, -1.0}, {lower + 2, -p.x}});
    }
  };
  for (std::size_t l = 0; l < a.levels_W.size(); ++l) {
    const Diaphragm3DConfig& lev = a.levels_W[l];
    const Vec2 cm = centre_of_mass(lev);
    const int dof = offset + 3 * static_cast<int>(l);
    const std::string level = b.name + "/" + levels_B[l].name;
    std::vector<std::pair<std::string, Vec2>> points{{"CM", cm}};
    for (std::size_t k = 0; k < lev.plan.size(); ++k)
      points.push_back({"corner " + std::to_string(k + 1), lev.plan[k]});
    for (const auto& [name, p] : points)
      for (const auto q :
           {PlanProbe::Quantity::kDisplacement, PlanProbe::Quantity::kAbsoluteAcceleration}) {
        PlanProbe probe;
        probe.label = level + "/" + name;
        probe.quantity = q;
        point_terms(dof, -1, p, probe);
        model.probes.push_back(std::move(probe));
      }
  }
  for (std::size_t s = 0; s < b.storeys.size(); ++s) {
    const int upper = offset + storey_upper(s);
    const int lower = storey_lower(s);
    for (const Column3DConfig& c : b.storeys[s].columns) {
      PlanProbe probe;
      probe.label = b.name + "/story " + std::to_string(s + 1) + "/" + c.label;
      probe.length = b.storeys[s].height;
      point_terms(upper, lower, to_plan(b, c.position), probe);
      model.probes.push_back(std::move(probe));
    }
  }
  // Storey shears (yielding columns or P-Delta): V = -sum over the levels above of M a_abs, in x
  // and y (the rows of M of those levels; theta's absolute acceleration is its relative one).
  bool inelastic = b.p_delta;
  for (const Storey3DConfig& storey : b.storeys)
    for (const Column3DConfig& c : storey.columns) inelastic = inelastic || c.hysteresis.yields();
  if (inelastic) {
    for (std::size_t s = 0; s < b.storeys.size(); ++s) {
      const int upper = storey_upper(s);  // building DOF of the level
      PlanProbe probe;
      probe.label = b.name + "/" + kStoreyShearPart + "/story " + std::to_string(s + 1);
      probe.quantity = PlanProbe::Quantity::kAbsoluteAcceleration;
      for (int j = upper; j < nb; ++j) {
        double cx = 0.0, cy = 0.0;
        for (int i = upper; i < nb; i += 3) {
          cx -= a.mass(i, j);
          cy -= a.mass(i + 1, j);
        }
        if (cx != 0.0) probe.x_terms.push_back({offset + j, cx});
        if (cy != 0.0) probe.y_terms.push_back({offset + j, cy});
      }
      model.probes.push_back(std::move(probe));
    }
  }
  info.elastic_limit_drift_ratio = b.elastic_limit_drift_ratio;
  model.structures.push_back(std::move(info));
}

LinearModel3D linear_model3d(const Building3DConfig& b, bool initial, bool fixed_base) {
  const bool with_base = b.isolated && !fixed_base;
  const Assembly a = assemble(with_base ? b : superstructure3d(b));
  LinearModel3D m{a.mass, a.initial_stiffness, a.influence, a.dofs};
  if (with_base) add_bearing_springs(m.stiffness, a, bearing_stiffnesses(b, a, initial));
  return m;
}

void check_damping_modes(const Building3DConfig& b) {
  const Damping3DConfig& d = b.damping;
  if (d.type == Damping3DConfig::Type::kNone) return;
  const bool non_classical = d.type == Damping3DConfig::Type::kNonClassical;
  const LinearModel3D m =
      linear_model3d(b, !non_classical && d.initial_bearing_stiffness, non_classical);
  const Modes modes = compute_modes(m.stiffness, m.mass, m.influence.col(0));
  require_distinct_modes(modes.omega, d.mode_a, d.mode_b,
                         non_classical && b.isolated
                             ? "the fixed-base superstructure of building '" + b.name + "'"
                             : "building '" + b.name + "'");
}

}  // namespace isopound
