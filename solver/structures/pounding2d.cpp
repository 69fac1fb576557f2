// Pounding set-ups in 2D. Sign convention: +x is "right". A right wall at gap g is hit when the
// level moves by +g: delta = u_level - u_wall - g; a left wall: delta = u_wall - u_level - g.
#include "solver/structures/pounding2d.h"

#include <cmath>
#include <limits>
#include <stdexcept>

#include "solver/elements/contact.h"
#include "solver/elements/struck_column.h"
#include "solver/materials/bumper_law.h"
#include "solver/structures/building2d.h"

namespace isopound {

namespace {

constexpr double kLevelTolerance2D = 1e-3;  // m: levels closer than this pound slab to slab

bool is_base_dof(const Model& model, int structure, int dof) {
  const StructureInfo& info = model.structures[static_cast<std::size_t>(structure)];
  return info.has_base && info.base_dof() == dof;
}

// Adds a single-DOF wall oscillator (mass, spring and dashpot to the ground); returns its DOF.
int add_wall_structure(Model& model, const std::string& name, const WallConfig& wall) {
  const int dof = model.size();
  const int n = dof + 1;
  model.grow(n);
  model.influence[dof] = 1.0;
  model.mass(dof, dof) = wall.mass;
  model.stiffness(dof, dof) = wall.stiffness;
  model.damping(dof, dof) = 2.0 * wall.damping_ratio * std::sqrt(wall.stiffness * wall.mass);
  StructureInfo info;
  info.name = name;
  info.level_dofs = {dof};
  model.dofs.push_back({name, static_cast<int>(model.structures.size()), 0});
  model.structures.push_back(std::move(info));
  return dof;
}

// A bumper of thickness t > 0 moves the contact surface t closer (the gap to the rubber's face)
// and wraps the wall's law; t = 0 is the bare wall, untouched.
void add_contact(Model& model, const std::string& label, ContactBody a, ContactBody b, double gap,
                 ImpactLawConfig impact, double mass_a, double mass_b, double steps_per_contact,
                 const BumperConfig& bumper = {}) {
  if (!(gap >= 0)) throw std::invalid_argument(label + ": gap must be >= 0");
  if (!(bumper.thickness >= 0 && (bumper.thickness == 0 || bumper.thickness < gap)))
    throw std::invalid_argument(label + ": bumper thickness must be 0 or in (0, gap)");
  impact.mass_1 = mass_a;
  impact.mass_2 = mass_b;
  std::unique_ptr<ImpactLaw> law = make_impact_law(impact);
  if (bumper.thickness > 0) law = make_bumper_law(bumper, std::move(law));
  model.elements.push_back(
      std::make_unique<Contact1D>(label, a, b, gap - bumper.thickness, std::move(law),
                                  effective_mass(mass_a, mass_b), steps_per_contact));
}

// Levels of structure `striker` (elevations z_a) facing a storey of structure `struck` (its
// levels at z_b) strictly between its floors strike its column line: a StruckColumn each, the
// columns' share n 12 E I / L^3 taken out of the storey's spring. side: +1 when the striker
// closes the gap moving +x.
int add_struck_columns(Model& model, int striker, const std::vector<double>& z_a, int struck,
                       const BuildingConfig& b, const std::vector<double>& z_b,
                       const NeighbourConfig& neighbour, double side, double steps_per_contact) {
  const StructureInfo info = model.structures[struck];
  const double ground = z_b.empty() ? 0.0 : z_b[0] - level_elevations(b)[0];
  int added = 0;
  std::vector<int> struck_storeys;
  for (std::size_t i = 0; i < z_a.size(); ++i) {
    const FacedPart part = faced_part(b, z_b, ground, z_a[i]);
    if (part.kind != FacedPart::Kind::kStorey) continue;
    const int f = part.floor;
    const int upper_level = info.floor_level(f), lower_level = info.below_floor_level(f);
    const double z_lower = part.z_lower;
    const std::string& striker_name = model.structures[striker].name;
    const std::string label =
        striker_name + "~" + b.name + "/" +
        model.dofs[model.structures[striker].level_dofs[i]].label.substr(striker_name.size() + 1) +
        " on " + b.name + " story " + std::to_string(f);
    // Without columns: such a level is left without contact, as before issue 26 (the input
    // check refuses it where the storey heights show it).
    if (!b.columns.given) continue;
    if (info.story_elements[f - 1] >= 0)
      throw std::invalid_argument(label + ": the struck storey must be elastic");
    for (const int done : struck_storeys)
      if (done == f) throw std::invalid_argument(label + ": a storey struck by two levels");
    struck_storeys.push_back(f);
    ++added;
    // The façade the striker faces: its left one when it closes the gap moving +x.
    const int line = info.facade_columns[static_cast<std::size_t>(f - 1)][side > 0 ? 0 : 1];
    if (!neighbour.pounding) continue;
    StruckColumnSpec spec;
    const StruckColumnsConfig& c = b.columns;
    const double L = b.floors[f - 1].height, a = z_a[i] - z_lower, bb = L - a;
    spec.column = {c.E, c.I, L, a, c.yield_moment, c.hardening_ratio * 6.0 * c.E * c.I / L};
    spec.count = c.count;
    spec.shear_capacity = c.shear_check ? c.shear_capacity : 0.0;
    spec.slab = model.structures[striker].level_dofs[i];
    spec.side = side;
    spec.upper = info.level_dofs[static_cast<std::size_t>(upper_level)];
    spec.lower = lower_level >= 0 ? info.level_dofs[static_cast<std::size_t>(lower_level)] : -1;
    // m_eff: the slab against the floors' masses shared as the reactions of a point load on
    // a column fixed at both ends (the ground: immovable).
    const double r_lower = bb * bb * (L + 2 * a) / (L * L * L);
    const double r_upper = a * a * (L + 2 * bb) / (L * L * L);
    const double m_struck = spec.lower >= 0 ? r_lower * model.mass(spec.lower, spec.lower) +
                                                  r_upper * model.mass(spec.upper, spec.upper)
                                            : std::numeric_limits<double>::infinity();
    const double m_slab = model.mass(spec.slab, spec.slab);
    ImpactLawConfig impact = neighbour.impact;
    impact.mass_1 = m_slab;
    impact.mass_2 = m_struck;
    std::unique_ptr<ImpactLaw> law = make_impact_law(impact);
    if (neighbour.bumper.thickness > 0) law = make_bumper_law(neighbour.bumper, std::move(law));
    if (is_base_dof(model, striker, spec.slab))
      model.structures[striker].base_contact_elements.push_back(line);
    // The struck line takes the place of the façade's ColumnLine (the storey spring already
    // keeps k less both lines' share): the same columns, now with their node at the slab.
    model.elements[static_cast<std::size_t>(line)] = std::make_unique<StruckColumn>(
        label, spec, neighbour.gap - neighbour.bumper.thickness, std::move(law),
        effective_mass(m_slab, m_struck), steps_per_contact);
  }
  return added;
}

}  // namespace

FacedPart faced_part(const BuildingConfig& b, const std::vector<double>& z_b, double ground,
                     double z) {
  FacedPart out;
  for (std::size_t j = 0; j < z_b.size(); ++j)
    if (std::abs(z - z_b[j]) <= kLevelTolerance2D) {
      out.kind = FacedPart::Kind::kLevel;
      out.level = static_cast<int>(j);
      return out;
    }
  if (std::abs(z - ground) <= kLevelTolerance2D) return out;  // b's ground: nothing to strike
  if (z < ground) {
    out.kind = FacedPart::Kind::kBelowGround;
    return out;
  }
  const int k = b.isolated ? b.isolation_level : 0;
  for (int f = 1; f <= static_cast<int>(b.floors.size()); ++f) {
    // Floor f's level index (a slab isolated above floor k comes between k and k + 1); the
    // level below its storey is the one before it (the ground for index 0).
    const int upper = b.isolated && f > k ? f : f - 1;
    const double z_upper = z_b[static_cast<std::size_t>(upper)];
    const double z_lower = upper > 0 ? z_b[static_cast<std::size_t>(upper) - 1] : ground;
    if (z > z_lower && z < z_upper) {
      out.kind = FacedPart::Kind::kStorey;
      out.floor = f;
      out.z_lower = z_lower;
      out.z_upper = z_upper;
      return out;
    }
  }
  // Between floor k and the slab isolated above it: the isolators, not a storey.
  if (b.isolated && k > 0 && z > z_b[static_cast<std::size_t>(k) - 1] &&
      z < z_b[static_cast<std::size_t>(k)])
    out.kind = FacedPart::Kind::kIsolationGap;
  return out;
}

std::vector<double> level_elevations(const BuildingConfig& building) {
  std::vector<double> z;
  double elevation = 0.0;
  const std::size_t k = static_cast<std::size_t>(building.isolation_level);
  for (std::size_t i = 0; i < building.floors.size(); ++i) {
    if (building.isolated && i == k) {  // the isolated slab, on the ground or above floor k
      if (k > 0) elevation += building.isolation_height;
      z.push_back(elevation);
    }
    elevation += building.floors[i].height;
    z.push_back(elevation);
  }
  return z;
}

bool is_base_level(const BuildingConfig& building, int level) {
  return building.isolated && level == building.isolation_level;
}

void add_walls(Model& model, int structure, const BuildingConfig& building,
               double steps_per_contact) {
  // A copy: a flexible wall adds a structure (push_back), which may move model.structures, so
  // a reference into it would dangle for the next walls entry.
  const std::vector<int> level_dofs = model.structures.at(structure).level_dofs;
  for (const WallConfig& wall : building.walls) {
    if (wall.level < 0 || wall.level >= static_cast<int>(level_dofs.size()))
      throw std::invalid_argument("walls: level " + std::to_string(wall.level) +
                                  " does not exist in '" + building.name + "'");
    const int level_dof = level_dofs[wall.level];
    const double level_mass = model.mass(level_dof, level_dof);
    const std::string where =
        is_base_level(building, wall.level) ? "base" : "level " + std::to_string(wall.level);
    for (const bool right : {false, true}) {
      if (right ? !wall.right : !wall.left) continue;
      const std::string side = right ? "right" : "left";
      const std::string name = building.name + "/wall " + side + " (" + where + ")";
      const double s = right ? 1.0 : -1.0;
      ContactBody wall_body;  // rigid wall: the ground
      if (wall.stiffness > 0)
        wall_body = {add_wall_structure(model, name + " structure", wall), -s};
      if (is_base_level(building, wall.level))
        model.structures[structure].base_contact_elements.push_back(
            static_cast<int>(model.elements.size()));
      add_contact(model, name, {level_dof, s}, wall_body, right ? wall.gap_right : wall.gap_left,
                  wall.impact, level_mass, wall.mass, steps_per_contact, wall.bumper);
    }
  }
}

void add_neighbour(Model& model, int main, const BuildingConfig& main_building,
                   const NeighbourConfig& neighbour, double steps_per_contact) {
  add_building(model, neighbour.building);
  const int other = static_cast<int>(model.structures.size()) - 1;
  add_walls(model, other, neighbour.building, steps_per_contact);
  const std::vector<double> z_main = level_elevations(main_building);
  std::vector<double> z_other = level_elevations(neighbour.building);
  for (double& z : z_other) z += neighbour.ground_level;
  const double s = neighbour.right ? 1.0 : -1.0;
  int pairs = 0;
  for (std::size_t i = 0; i < z_main.size(); ++i) {
    for (std::size_t j = 0; j < z_other.size(); ++j) {
      if (std::abs(z_main[i] - z_other[j]) > kLevelTolerance2D) continue;
      const int dof_main = model.structures[main].level_dofs[i];
      const int dof_other = model.structures[other].level_dofs[j];
      const std::string label = main_building.name + "~" + neighbour.building.name + "/" +
                                model.dofs[dof_main].label.substr(main_building.name.size() + 1);
      ++pairs;
      if (!neighbour.pounding) continue;
      // Base slab against base slab: the contact is part of both structures' base shear.
      const int element = static_cast<int>(model.elements.size());
      if (is_base_level(main_building, static_cast<int>(i)))
        model.structures[main].base_contact_elements.push_back(element);
      if (is_base_level(neighbour.building, static_cast<int>(j)))
        model.structures[other].base_contact_elements.push_back(element);
      add_contact(model, label, {dof_main, s}, {dof_other, -s}, neighbour.gap, neighbour.impact,
                  model.mass(dof_main, dof_main), model.mass(dof_other, dof_other),
                  steps_per_contact, neighbour.bumper);
    }
  }
  // Levels between the other's floors strike its columns.
  pairs += add_struck_columns(model, main, z_main, other, neighbour.building, z_other, neighbour, s,
                              steps_per_contact);
  pairs += add_struck_columns(model, other, z_other, main, main_building, z_main, neighbour, -s,
                              steps_per_contact);
  if (pairs == 0)
    throw std::invalid_argument("neighbour '" + neighbour.building.name +
                                "' has no floor at the "
                                "elevation of a level of '" +
                                main_building.name + "'");
}

}  // namespace isopound
