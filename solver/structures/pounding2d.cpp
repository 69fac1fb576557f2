// Pounding set-ups in 2D. Sign convention: +x is "right". A right wall at gap g is hit when the
// level moves by +g: delta = u_level - u_wall - g; a left wall: delta = u_wall - u_level - g.
#include "solver/structures/pounding2d.h"

#include <cmath>
#include <limits>
#include <stdexcept>

#include "solver/elements/contact.h"
#include "solver/structures/building2d.h"

namespace isopound {

namespace {

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

}  // namespace

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
  const std::vector<double> z_other = level_elevations(neighbour.building);
  const double s = neighbour.right ? 1.0 : -1.0;
  int pairs = 0;
  for (std::size_t i = 0; i < z_main.size(); ++i) {
    for (std::size_t j = 0; j < z_other.size(); ++j) {
      if (std::abs(z_main[i] - z_other[j]) > 1e-3) continue;
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
  if (pairs == 0)
    throw std::invalid_argument("neighbour '" + neighbour.building.name +
                                "' has no floor at the "
                                "elevation of a level of '" +
                                main_building.name + "'");
}

}  // namespace isopound
