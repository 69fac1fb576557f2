// Assembly of a 2D shear building into a Model. Superstructure damping is built for the
// fixed-base stick in base-relative coordinates w = T u, T = [-1 | I], and mapped C = T^T C_s T.
#include "solver/structures/building2d.h"

#include <numbers>
#include <stdexcept>

#include "solver/core/modes.h"
#include "solver/elements/bearing_link.h"
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

ShearStick fixed_base_superstructure(const BuildingConfig& b) {
  const int n = static_cast<int>(b.floors.size());
  ShearStick s{Eigen::MatrixXd::Zero(n, n), Eigen::MatrixXd::Zero(n, n)};
  for (int i = 0; i < n; ++i) {
    s.mass(i, i) = b.floors[i].mass;
    const double k = b.floors[i].stiffness;
    s.stiffness(i, i) += k;
    if (i > 0) {
      s.stiffness(i - 1, i - 1) += k;
      s.stiffness(i - 1, i) -= k;
      s.stiffness(i, i - 1) -= k;
    }
  }
  return s;
}

Eigen::MatrixXd superstructure_damping(const BuildingConfig& b) {
  const int n = static_cast<int>(b.floors.size());
  const SuperstructureDamping& d = b.damping;
  if (d.type == SuperstructureDamping::Type::kNone || d.ratio == 0.0)
    return Eigen::MatrixXd::Zero(n, n);
  const ShearStick s = fixed_base_superstructure(b);
  const Modes modes = compute_modes(s.stiffness, s.mass, Eigen::VectorXd::Ones(n));
  if (d.type == SuperstructureDamping::Type::kModal) {
    // C = M Phi diag(2 xi omega) Phi^T M for mass-normalised Phi.
    const Eigen::MatrixXd mphi = s.mass * modes.shape;
    return mphi * (2.0 * d.ratio * modes.omega).asDiagonal() * mphi.transpose();
  }
  if (d.mode_a < 1 || d.mode_b < 1 || d.mode_a > n || d.mode_b > n || d.mode_a == d.mode_b)
    throw std::invalid_argument("Rayleigh damping needs two distinct modes in 1.." +
                                std::to_string(n) + " of the fixed-base superstructure");
  require_distinct_modes(modes.omega, d.mode_a, d.mode_b, "the fixed-base superstructure");
  const double wa = modes.omega[d.mode_a - 1];
  const double wb = modes.omega[d.mode_b - 1];
  const double a0 = 2.0 * d.ratio * wa * wb / (wa + wb);
  const double a1 = 2.0 * d.ratio / (wa + wb);
  return a0 * s.mass + a1 * s.stiffness;
}

void add_building(Model& model, const BuildingConfig& b) {
  const int floors = static_cast<int>(b.floors.size());
  if (floors < 1) throw std::invalid_argument("building '" + b.name + "' has no floors");
  const int offset = model.size();
  const int base = b.isolated ? offset : -1;
  const int first_floor = b.isolated ? offset + 1 : offset;
  const int n = first_floor + floors;

  model.grow(n);
  model.influence.tail(n - offset).setOnes();

  StructureInfo info;
  info.name = b.name;
  info.has_base = b.isolated;
  const int structure = static_cast<int>(model.structures.size());
  if (b.isolated) {
    model.dofs.push_back({b.name + "/base", structure, 0});
    info.level_dofs.push_back(base);
    model.mass(base, base) = b.base_mass;
  }
  for (int i = 0; i < floors; ++i) {
    const int dof = first_floor + i;
    model.dofs.push_back({b.name + "/floor " + std::to_string(i + 1), structure, i + 1});
    info.level_dofs.push_back(dof);
    info.story_heights.push_back(b.floors[i].height);
    model.mass(dof, dof) = b.floors[i].mass;
    const int below = i > 0 ? dof - 1 : base;  // -1: ground (fixed base)
    // A linear term of the story in K: its elastic spring (unless the story yields) and, with
    // P-Delta, the geometric stiffness -P/h of the weight above.
    double k = 0.0;
    if (b.floors[i].hysteresis.model == StoryHysteresisConfig::Model::kElastic) {
      k = b.floors[i].stiffness;
      info.story_elements.push_back(-1);
    } else {
      info.story_elements.push_back(static_cast<int>(model.elements.size()));
      model.elements.push_back(std::make_unique<StoryLink>(
          b.name + "/story " + std::to_string(i + 1) + "/hysteretic", below, dof,
          make_story_material(b, i), story_yield_drift(b, i)));
    }
    if (b.p_delta) k -= weight_above_story(b, i) / b.floors[i].height;
    if (k != 0.0) {
      model.stiffness(dof, dof) += k;
      if (below >= 0) {
        model.stiffness(below, below) += k;
        model.stiffness(below, dof) -= k;
        model.stiffness(dof, below) -= k;
      }
    }
  }
  info.elastic_limit_drift_ratio = b.elastic_limit_drift_ratio;

  // Superstructure damping, relative to the base slab (or the ground if fixed).
  const Eigen::MatrixXd c_s = superstructure_damping(b);
  Eigen::MatrixXd T = Eigen::MatrixXd::Zero(floors, n - offset);
  T.rightCols(floors).setIdentity();
  if (b.isolated) T.col(0).setConstant(-1.0);
  model.damping.bottomRightCorner(n - offset, n - offset) += T.transpose() * c_s * T;

  if (b.isolated) {
    const double m_total = building_mass(b);
    const double carried = b.isolator.carried_mass > 0 ? b.isolator.carried_mass : m_total;
    info.isolator_element = static_cast<int>(model.elements.size());
    if (b.isolator.model == IsolatorConfig::Model::kFrictionPendulum) {
      // Rate dependent, so not a uniaxial law: the biaxial bearing acting along x only.
      DiaphragmDofs dofs;
      dofs.ux = base;
      model.elements.push_back(std::make_unique<BearingLink>(
          b.name + "/isolator", dofs, Eigen::Vector2d::Zero(),
          make_bearing_material(bearing_config(b.isolator), carried)));
    } else {
      model.elements.push_back(std::make_unique<UniaxialLink>(
          b.name + "/isolator", kGround, base, make_isolator_material(b.isolator, carried)));
    }
    const double omega_b = 2.0 * std::numbers::pi / isolation_period(b.isolator);
    model.damping(base, base) += 2.0 * b.isolation_damping_ratio * m_total * omega_b;
  }
  model.structures.push_back(std::move(info));
}

Model make_model(const BuildingConfig& building) {
  Model model;
  add_building(model, building);
  return model;
}

}  // namespace isopound
