// 3D pounding set-up (THEORY §6, issue 16): the site's polygon bodies at rest (floors, base slabs,
// moat walls) and the automatic pair search that turns every pair able to meet into a
// PolygonContact. Pairs: floors of different structures at equal elevation, walls with the base
// slab they surround; n_AB points from body A (the first named) into body B.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "geometry/convex_polygon.h"
#include "geometry/simple_polygon.h"
#include "solver/core/model.h"
#include "solver/structures/bumper_layer3d.h"
#include "solver/structures/config.h"
#include "solver/structures/config3d.h"

namespace isopound {

// One polygon body at rest, in the model's plan frame W (SI).
struct SiteBody {
  std::string structure;  // "building", "east-neighbour", "wall east"
  std::string level;      // "base", "floor 1", ..., "wall"
  std::string role;       // "slab" | "wall"
  // m: a slab's level above the ground (levels3d.h); a wall's top, flush with the level it faces
  double elevation = 0.0;
  double height = 0.0;   // m: a wall's height; a slab 0
  ConvexPolygon plan_W;  // outline at rest (a non-convex slab: its convex hull)
  // A non-convex slab's outline at rest (L, T, U: issue 40); empty (size 0) for a convex body.
  SimplePolygon outline_W;
  Vec2 p_WO;  // DOF origin at rest (every 3D DOF sits at the plan origin)
  // Prefixes of the DOF labels and history columns, "building/floor 1 (x)"; "" for a fixed body.
  std::string dof_label_u, dof_label_v, dof_label_theta;
  double mass = 0.0;   // kg: the floor's mass, or the wall's (enters m_eff only)
  int building = -1;   // index into ModelConfig::structures3d (a wall: the one it surrounds)
  int wall_side = -1;  // MoatWalls3DConfig::Side of a box wall, else -1 (an outline wall too)
  // A wall: the unit normal from the slab's face it faces into the wall (plan frame W), its
  // declared gap (m) and the face's name ("east", "north-east 2", ...: building frame).
  Vec2 wall_normal_W;
  double wall_gap = 0.0;
  std::string wall_face;
  double wall_length = 0.0;  // m, a wall's extent along its face (its mass, a flexible wall's L)
  std::string label() const { return role == "wall" ? structure : structure + "/" + level; }
  bool convex() const { return outline_W.size() == 0; }
  // The outline as a simple polygon, convex or not.
  SimplePolygon outline() const { return convex() ? SimplePolygon(plan_W.vertices()) : outline_W; }
};

// Every slab (base slabs and floors, bottom to top per structure) and every moat wall.
std::vector<SiteBody> site_bodies(const ModelConfig& config);

// A straight run of a plan's outline (collinear vertices dropped), counter-clockwise, the plan on
// its left, named by its outward normal's compass point: "east", "north-east", ...; a second run
// facing the same way "east 2", and so on in the order of the runs (geometry/moat.h,
// outline_runs). The names of a following moat's walls and of a slab's rubber.
struct OutlineFace {
  std::string name;
  Vec2 start, end;  // m, the plan's frame
};
std::vector<OutlineFace> outline_faces(const SimplePolygon& plan);

// The rubber on one slab's faces (Building3DConfig::bumper; plan_B its outline in the building
// frame), per face: a convex plan's bumpered box sides ("east": bumper_layer3d.h,
// slab_bumper_strips); a non-convex plan's bumpered outline faces (outline_faces; every face when
// bumper.faces is empty), each strip in front of its run over [from, to] measured from the run's
// end of least y (then least x). At a re-entrant corner between two bumpered faces the face that
// starts there (counter-clockwise) begins its rubber t from the corner, where the other's ends.
// Throws std::invalid_argument when from/to lie beyond a bumpered face (or a box side is a corner).
struct FaceStrips {
  std::string face;
  BumperStrips strips;
};
std::vector<FaceStrips> slab_face_strips(const std::vector<Vec2>& plan_B,
                                         const Bumper3DConfig& bumper);

// The faces of a building's walls by face, every run's whether or not `sides` selects it, in the
// order they are listed. walls: {follow: outline} (also what a box moat's would be): "east",
// "west", "north", "south", then the others along the outline ("north-east", a second east face
// "east 2", ...), each at its declared gap. follow: polyline: in the order drawn, named by the
// compass point of the normal into the wall, each at its clearance from the slab at rest.
// Throws InvalidPolygon when no such walls can be built (geometry/moat.h).
struct MoatFace {
  std::string name;
  double gap = 0.0;  // m
};
std::vector<MoatFace> moat_faces(const Building3DConfig& building);

// The rubber strips (building frame, bumper_layer3d.h) of the moat wall of `building` on box side
// `side` (>= 0) or, for walls by face (outline, polyline; side < 0), facing `face`; nullopt when it
// has no rubber. Throws std::invalid_argument when the bumper's from/to lie beyond its face.
std::optional<BumperStrips> wall_bumper_strips(const Building3DConfig& building, int side,
                                               const std::string& face);

// A box wall's outline in the building frame (before the building's placement), around the plan
// of the level it faces.
std::vector<Vec2> moat_wall_outline(const Building3DConfig& building, int side);
// The level (levels3d.h index) the building's moat walls face: walls.level, else the base slab.
int walls_level3d(const Building3DConfig& building);

// Contacts of a pair with a non-convex plan: one per part of the overlap, this many at most
// (solver/elements/plan_pair.h; a slab across both wings of a U meets its neighbour twice; more
// parts at once get no force and are counted in most_components).
inline constexpr int kPlanContactSlots = 3;
// A second or third slot's label is the first's with " #2", " #3" (the same two bodies, or the
// same bumper strip): the label without that number.
inline std::string_view without_slot(std::string_view label) {
  const auto hash = label.rfind(" #");
  if (hash != std::string_view::npos && hash + 2 < label.size() &&
      label.find_first_not_of("0123456789", hash + 2) == std::string_view::npos)
    return label.substr(0, hash);
  return label;
}

// A pair of bodies that may meet: indices into site_bodies(); label "A|B".
struct ContactPair3D {
  int a = -1, b = -1;
  std::string label;
  double separation = 0.0;  // m, signed distance at rest (> 0 apart, < 0 overlapping)
};

// Floors of different structures with |Δz| <= elevation_tolerance and walls with the base slab
// of their building, kept when their rest separation is below search_distance.
std::vector<ContactPair3D> contact_pairs3d(const std::vector<SiteBody>& bodies,
                                           const ModelConfig::Contact3D& contact);

// Adds the DOFs, mass, stiffness and damping of every flexible moat wall (not in
// Model::structures: no storeys or probes; their histories carry "wall east (x) u" etc.).
void add_flexible_walls(Model& model, const ModelConfig& config);

// The end of the labels of a bumper's two contacts (issue 27): the rubber's, "<slab>|<wall>
// bumper", and the bottomed-out rubber's, "<slab>|<wall> bumper bottomed"; on a slab's face,
// "<other slab>|<face> bumper" and "... bumper bottomed", the face as slab_face_label names it.
inline constexpr const char* kBumperLabel = "bumper";
inline constexpr const char* kBottomedLabel = "bumper bottomed";

// The index of the DOF labelled `label` ("" gives -1: a fixed body); throws if there is none.
int find_dof(const Model& model, const std::string& label);
// The contact law of a pair of bodies of masses mass_a, mass_b (contact.law, or the impact law
// along the normal with those masses), with the analysis' steps per contact.
PolygonContactConfig pair_law(const ModelConfig& config, double mass_a, double mass_b);
// Marks `element`, acting on the level whose x DOF is u, as not part of an isolated structure's
// base shear unless u is its base slab (and, on a raised base slab, the element a wall's).
void note_upper_contact(Model& model, int u, int element, bool with_wall);
// A slab's face with rubber (Building3DConfig::bumper): "<slab label> <face>", e.g.
// "east-neighbour/floor 1 west", "podium/base east 2" (building frame).
std::string slab_face_label(const std::string& slab_label, const std::string& face);

// Adds a PolygonContact per pair (the model must hold the structures' DOFs already), and after a
// pair's contact the two of each bumper it has (issue 27): a bumpered wall's, and those of each
// bumpered slab face (Building3DConfig::bumper) within the search distance of the other slab.
void add_pounding3d(Model& model, const ModelConfig& config);

// For the unobstructed comparison: per moat wall, the coordinates whose peaks give the critical
// gap (the gap below which the wall is hit): for each slab vertex, its displacement along the
// wall's outward normal, and the vertex's offset from the wall face's rest position minus the gap.
struct WallClosing {
  std::string label;  // the contact's label, "building/base|wall east"
  double gap = 0.0;   // m as modelled
  // vertex k of the slab: its closing = offset[k] + n · (u − yθ, v + xθ) at the vertex.
  std::vector<double> offset;                       // m, <= 0
  std::vector<std::array<double, 3>> coefficients;  // on (u, v, θ) of the base slab
  std::array<std::string, 3> dof_labels;
};
std::vector<WallClosing> wall_closings(const ModelConfig& config);

}  // namespace isopound
