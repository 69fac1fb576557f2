// Assembly of a 2D shear building into a Model. Superstructure damping is built for the
// fixed-base stick in base-relative coordinates w = T u, T = [-1 | I], and mapped C = T^T C_s T.
#include "solver/structures/building2d.h"

#include <numbers>
#include <stdexcept>

#include "solver/core/modes.h"
#include "solver/elements/bearing_link.h"
#include "solver/elements/column_line.h"
#include "solver/elements/story_link.h"
#include "solver/elements/uniaxial_link.h"
#include "solver/structures/bearing.h"
#include "solver/structures/isolator.h"
#include "solver/structures/rayleigh_modes.h"
#include "solver/structures/story_hysteresis.h"

namespace isopound {

double building_mass(const BuildingConfig& b) {
  double m = b.isolated ? b.base_mass : 0.0;
  for (const FloorConfig& f : b.floors) m += f.mass;
  return m;
}

double isolated_mass(const BuildingConfig& b) {
  double m = b.base_mass;
  for (std::size_t i = static_cast<std::size_t>(b.isolation_level); i < b.floors.size(); ++i)
    m += b.floors[i].mass;
  return m;
}

namespace {

// The fixed-base stick of floors first..first+count-1 (the lowest on the ground).
ShearStick shear_stick(const BuildingConfig& b, int first, int count) {
  ShearStick s{Eigen::MatrixXd::Zero(count, count), Eigen::MatrixXd::Zero(count, count)};
  for (int i = 0; i < count; ++i) {
    const FloorConfig& f = b.floors[static_cast<std::size_t>(first + i)];
    s.mass(i, i) = f.mass;
    const double k = f.stiffness;
    s.stiffness(i, i) += k;
    if (i > 0) {
      s.stiffness(i - 1, i - 1) += k;
      s.stiffness(i - 1, i) -= k;
      s.stiffness(i, i - 1) -= k;
    }
  }
  return s;
}

// Damping matrix of a fixed-base stick: Rayleigh at two of its modes, or modal with the same
// ratio at every mode.
Eigen::MatrixXd stick_damping(const ShearStick& s, const SuperstructureDamping& d,
                              const std::string& what) {
  const int n = static_cast<int>(s.mass.rows());
  if (d.type == SuperstructureDamping::Type::kNone || d.ratio == 0.0)
    return Eigen::MatrixXd::Zero(n, n);
  const Modes modes = compute_modes(s.stiffness, s.mass, Eigen::VectorXd::Ones(n));
  if (d.type == SuperstructureDamping::Type::kModal) {
    // C = M Phi diag(2 xi omega) Phi^T M for mass-normalised Phi.
    const Eigen::MatrixXd mphi = s.mass * modes.shape;
    return mphi * (2.0 * d.ratio * modes.omega).asDiagonal() * mphi.transpose();
  }
  if (d.mode_a < 1 || d.mode_b < 1 || d.mode_a > n || d.mode_b > n || d.mode_a == d.mode_b)
    throw std::invalid_argument("Rayleigh damping needs two distinct modes in 1.." +
                                std::to_string(n) + " of " + what);
  require_distinct_modes(modes.omega, d.mode_a, d.mode_b, what);
  const double wa = modes.omega[d.mode_a - 1];
  const double wb = modes.omega[d.mode_b - 1];
  const double a0 = 2.0 * d.ratio * wa * wb / (wa + wb);
  const double a1 = 2.0 * d.ratio / (wa + wb);
  return a0 * s.mass + a1 * s.stiffness;
}

}  // namespace

ShearStick fixed_base_superstructure(const BuildingConfig& b) {
  const int k = b.isolated ? b.isolation_level : 0;
  return shear_stick(b, k, static_cast<int>(b.floors.size()) - k);
}

ShearStick fixed_base_substructure(const BuildingConfig& b) {
  return shear_stick(b, 0, b.isolated ? b.isolation_level : 0);
}

Eigen::MatrixXd superstructure_damping(const BuildingConfig& b) {
  return stick_damping(fixed_base_superstructure(b), b.damping, "the fixed-base superstructure");
}

Eigen::MatrixXd substructure_damping(const BuildingConfig& b) {
  return stick_damping(fixed_base_substructure(b), b.substructure_damping,
                       "the fixed-base substructure");
}

namespace {

// The façade column lines of every storey (column_line.h), left and right, and the storey spring
// less their share 2 n 12 E I / h^3. A slab that strikes a line replaces it (pounding2d.cpp).
template <class FloorDof>
void add_facade_columns(Model& model, const BuildingConfig& b, StructureInfo& info,
                        const FloorDof& floor_dof, int base) {
  const StruckColumnsConfig& c = b.columns;
  const int k = b.isolated ? b.isolation_level : 0;
  for (std::size_t i = 0; i < b.floors.size(); ++i) {
    const int f = static_cast<int>(i);
    ColumnLineSpec spec;
    const double L = b.floors[i].height;
    ColumnLineSpec::Direction& x = spec.directions[0];
    x.column = {c.E, c.I, L, 0.5 * L, c.yield_moment, c.hardening_ratio * 6.0 * c.E * c.I / L};
    spec.count = c.count;
    spec.shear_capacity = c.shear_check ? c.shear_capacity : 0.0;
    const int upper = floor_dof(f);
    const int lower = b.isolated && f == k ? base : (f > 0 ? floor_dof(f - 1) : -1);
    x.add_term(upper, 1.0);
    x.add_term(lower, -1.0);
    const double k_lines = 2.0 * c.count * 12.0 * c.E * c.I / (L * L * L);
    model.stiffness(upper, upper) -= k_lines;
    if (lower >= 0) {
      model.stiffness(lower, lower) -= k_lines;
      model.stiffness(lower, upper) += k_lines;
      model.stiffness(upper, lower) += k_lines;
    }
    std::array<int, 2> lines;
    for (int side = 0; side < 2; ++side) {
      lines[static_cast<std::size_t>(side)] = static_cast<int>(model.elements.size());
      model.elements.push_back(std::make_unique<ColumnLine>(
          b.name + "/story " + std::to_string(f + 1) + "/columns " + (side == 0 ? "left" : "right"),
          spec));
    }
    info.facade_columns.push_back(lines);
  }
}

}  // namespace

void add_building(Model& model, const BuildingConfig& b) {
  const int floors = static_cast<int>(b.floors.size());
  if (floors < 1) throw std::invalid_argument("building '" + b.name + "' has no floors");
  // k: the isolators stand on floor k (0: the ground); the DOFs in elevation order.
  const int k = b.isolated ? b.isolation_level : 0;
  if (k < 0 || k >= floors)
    throw std::invalid_argument("building '" + b.name + "': isolation_level " + std::to_string(k) +
                                " must leave a floor above (0.." + std::to_string(floors - 1) +
                                ")");
  const int offset = model.size();
  const int base = b.isolated ? offset + k : -1;
  const auto floor_dof = [&](int i) { return offset + i + (b.isolated && i >= k ? 1 : 0); };
  const int n = offset + floors + (b.isolated ? 1 : 0);

  model.grow(n);
  model.influence.tail(n - offset).setOnes();

  StructureInfo info;
  info.name = b.name;
  info.has_base = b.isolated;
  info.base_level = k;
  if (k > 0) info.isolation_height = b.isolation_height;
  const int structure = static_cast<int>(model.structures.size());
  model.dofs.resize(static_cast<std::size_t>(n));
  info.level_dofs.resize(static_cast<std::size_t>(n - offset));
  if (b.isolated) {
    model.dofs[static_cast<std::size_t>(base)] = {b.name + "/base", structure, 0};
    info.level_dofs[static_cast<std::size_t>(k)] = base;
    model.mass(base, base) = b.base_mass;
  }
  for (int i = 0; i < floors; ++i) {
    const int dof = floor_dof(i);
    model.dofs[static_cast<std::size_t>(dof)] = {b.name + "/floor " + std::to_string(i + 1),
                                                 structure, i + 1};
    info.level_dofs[static_cast<std::size_t>(dof - offset)] = dof;
    info.story_heights.push_back(b.floors[i].height);
    model.mass(dof, dof) = b.floors[i].mass;
    // The level under the storey: the isolated slab, a floor, or -1 (the ground).
    const int below = b.isolated && i == k ? base : (i > 0 ? floor_dof(i - 1) : -1);
    // A linear term of the story in K: its elastic spring (unless the story yields) and, with
    // P-Delta, the geometric stiffness -P/h of the weight above.
    double stiffness = 0.0;
    if (!b.floors[i].hysteresis.yields()) {
      stiffness = b.floors[i].stiffness;
      info.story_elements.push_back(-1);
    } else {
      info.story_elements.push_back(static_cast<int>(model.elements.size()));
      model.elements.push_back(std::make_unique<StoryLink>(
          b.name + "/story " + std::to_string(i + 1) + "/hysteretic", below, dof,
          make_story_material(b, i), story_yield_drift(b, i)));
    }
    if (b.p_delta) stiffness -= weight_above_story(b, i) / b.floors[i].height;
    if (stiffness != 0.0) {
      model.stiffness(dof, dof) += stiffness;
      if (below >= 0) {
        model.stiffness(below, below) += stiffness;
        model.stiffness(below, dof) -= stiffness;
        model.stiffness(dof, below) -= stiffness;
      }
    }
  }
  info.elastic_limit_drift_ratio = b.elastic_limit_drift_ratio;
  if (b.columns.given) add_facade_columns(model, b, info, floor_dof, base);

  // Superstructure damping, relative to the base slab (or the ground if fixed): w = T u.
  const Eigen::MatrixXd c_s = superstructure_damping(b);
  Eigen::MatrixXd T = Eigen::MatrixXd::Zero(floors - k, n - offset);
  for (int i = k; i < floors; ++i) T(i - k, floor_dof(i) - offset) = 1.0;
  if (b.isolated) T.col(base - offset).setConstant(-1.0);
  model.damping.bottomRightCorner(n - offset, n - offset) += T.transpose() * c_s * T;
  // Substructure damping, relative to the ground (its DOFs come first).
  if (k > 0) model.damping.block(offset, offset, k, k) += substructure_damping(b);

  if (b.isolated) {
    // The isolators carry the slab and the floors above it.
    const double m_isolated = isolated_mass(b);
    const double carried = b.isolator.carried_mass > 0 ? b.isolator.carried_mass : m_isolated;
    const int bottom = k > 0 ? floor_dof(k - 1) : -1;  // -1: the ground
    info.isolator_element = static_cast<int>(model.elements.size());
    if (b.isolator.model == IsolatorConfig::Model::kFrictionPendulum) {
      // Rate dependent, so not a uniaxial law: the biaxial bearing acting along x only, on
      // floor k (above a storey) or on the ground.
      DiaphragmDofs dofs, lower;
      dofs.ux = base;
      if (k > 0) lower.ux = bottom;
      model.elements.push_back(std::make_unique<BearingLink>(
          b.name + "/isolator", dofs, Eigen::Vector2d::Zero(),
          make_bearing_material(bearing_config(b.isolator), carried), lower));
    } else {
      model.elements.push_back(
          std::make_unique<UniaxialLink>(b.name + "/isolator", k > 0 ? bottom : kGround, base,
                                         make_isolator_material(b.isolator, carried)));
    }
    // The isolation dashpot, between the slab and what the isolators stand on.
    const double omega_b = 2.0 * std::numbers::pi / isolation_period(b.isolator);
    const double c_b = 2.0 * b.isolation_damping_ratio * m_isolated * omega_b;
    model.damping(base, base) += c_b;
    if (bottom >= 0) {
      model.damping(bottom, bottom) += c_b;
      model.damping(base, bottom) -= c_b;
      model.damping(bottom, base) -= c_b;
    }
  }
  model.structures.push_back(std::move(info));
}

Model make_model(const BuildingConfig& building) {
  Model model;
  add_building(model, building);
  return model;
}

}  // namespace isopound
