// Level order of 3D buildings isolated at any storey (levels3d.h).
#include "solver/structures/levels3d.h"

namespace isopound {

int base_level3d(const Building3DConfig& b) {
  return b.isolated ? b.isolation_level : -1;
}

int floor_level3d(const Building3DConfig& b, int floor) {
  return b.isolated && floor > b.isolation_level ? floor : floor - 1;
}

int storey_lower_level3d(const Building3DConfig& b, int storey) {
  if (b.isolated && storey == b.isolation_level + 1) return b.isolation_level;
  return storey == 1 ? -1 : floor_level3d(b, storey - 1);
}

int bearing_lower_level3d(const Building3DConfig& b) {
  return b.isolation_level > 0 ? floor_level3d(b, b.isolation_level) : -1;
}

bool storey_on_ground3d(const Building3DConfig& b, int storey) {
  return storey_lower_level3d(b, storey + 1) < 0;
}

std::vector<Level3D> levels3d(const Building3DConfig& b) {
  std::vector<Level3D> levels;
  double z = 0.0;
  const auto add_base = [&] {
    // The base slab sits isolation_height above floor k (at the ground when k = 0).
    if (b.isolation_level > 0) z += b.isolation_height;
    levels.push_back({"base", &b.base, z, 0});
  };
  if (b.isolated && b.isolation_level == 0) add_base();
  for (std::size_t s = 0; s < b.storeys.size(); ++s) {
    z += b.storeys[s].height;
    const int floor = static_cast<int>(s) + 1;
    levels.push_back({"floor " + std::to_string(floor), &b.storeys[s].floor, z, floor});
    if (b.isolated && b.isolation_level == floor) add_base();
  }
  return levels;
}

Building3DConfig superstructure3d(const Building3DConfig& b) {
  Building3DConfig s = b;
  s.isolated = false;
  s.isolation_level = 0;
  s.isolation_height = 0.0;
  if (b.isolated && b.isolation_level > 0)
    s.storeys.erase(s.storeys.begin(), s.storeys.begin() + b.isolation_level);
  return s;
}

Building3DConfig substructure3d(const Building3DConfig& b) {
  Building3DConfig s = b;
  s.isolated = false;
  s.isolation_level = 0;
  s.isolation_height = 0.0;
  s.storeys.resize(b.isolated ? static_cast<std::size_t>(b.isolation_level) : 0);
  return s;
}

}  // namespace isopound
