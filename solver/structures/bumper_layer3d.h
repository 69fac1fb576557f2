// The rubber layer of a 3D moat wall in plan (issue 27; docs/impact-laws.md, "Bumpers on moat
// walls (3D)"): a strip `thickness` deep in front of the wall's inner face, over [from, to].
#pragma once

#include <limits>
#include <memory>
#include <vector>

#include "geometry/convex_polygon.h"
#include "solver/materials/bumper_law.h"
#include "solver/structures/config3d.h"

namespace isopound {

// Where from/to are measured from on a straight face in the building frame: its end of least y,
// then of least x (a box wall's lower x or y). True when p is that end rather than q.
inline bool starts_face_before(Vec2 p, Vec2 q) {
  return p.y < q.y || (p.y == q.y && p.x < q.x);
}

// Where the rubber sits along the face: metres from the face's start (its lower x for the
// north and south walls, its lower y for the east and west walls); `to` = +inf: to the end.
struct BumperSpan {
  double from = 0.0;
  double to = std::numeric_limits<double>::infinity();
};

// The strip's outline (counter-clockwise rectangle, building frame like the wall's) in front of
// the inner face of `wall`, the outline moat_wall_outline() gives for `side`
// (MoatWalls3DConfig::Side: 0 east, 1 west, 2 north, 3 south). The inner face is the one towards
// the slab; the strip occupies [face − setback − thickness, face − setback] on the slab's side.
// Throws std::invalid_argument for thickness <= 0, from < 0, to > the face's length or
// from >= to.
std::vector<Vec2> bumper_layer_outline(const std::vector<Vec2>& wall, int side, double thickness,
                                       BumperSpan span = {}, double setback = 0.0);

// A bumper in plan is two strips on the wall's DOFs (docs/impact-laws.md, "Bumpers on moat
// walls (3D)"): the rubber, max_strain t deep at the front, and behind it the bottomed-out
// rubber, (1 − max_strain) t deep against the wall face, which acts as concrete.
struct BumperStrips {
  std::vector<Vec2> rubber, bottomed;  // building frame, as bumper_layer_outline
  // The direction the rubber is compressed along (unit, building frame): from the slab that
  // strikes it into the wall or slab face that carries it
  // (PolygonContactConfig::strip_compression_W).
  Vec2 n;
};
BumperStrips bumper_strips(const std::vector<Vec2>& wall, int side, const Bumper3DConfig& bumper);

// The same two strips in front of the inner face of any straight wall (a wall that follows the
// slab's outline, geometry/moat.h): `wall` its convex outline, `n` the unit normal from the slab
// into it. The inner face is the wall's edge of least n·x; from/to are measured along it from its
// end of least y (then least x), as a box wall's from its lower x or y. Throws
// std::invalid_argument when from/to lie beyond that face.
BumperStrips face_bumper_strips(const std::vector<Vec2>& wall, Vec2 n,
                                const Bumper3DConfig& bumper);

// The same two strips on a slab's own face (a neighbour's rubber, Building3DConfig::bumper): in
// front of the straight edge the slab `plan` (building frame) has on side `side` of its bounding
// box (0 east ... 3 south), max_strain t of rubber outermost, over [from, to] along that edge from
// its start (lower y for east and west, lower x for north and south). Throws
// std::invalid_argument when the slab has no edge on that side (a vertex only) or from/to lie
// beyond it.
BumperStrips slab_bumper_strips(const std::vector<Vec2>& plan, int side,
                                const Bumper3DConfig& bumper);

// The laws of the two strips per unit contact length L_c (polygon_contact.h, length_law).
// Rubber: a BumperLaw of thickness t with k = E h / t (linear: F_N/L_c = k δ_N) or E h / t^1.5
// (hertz: F_N/L_c = k δ_N^1.5) and Hunt–Crossley damping from e (its δ_N never passes
// max_strain t: the strip is that deep). Bottomed: elastic k_N δ_N (N/m², F_N = k_N A_c).
// Throws std::invalid_argument for an invalid bumper.
std::shared_ptr<const ImpactLaw> bumper_rubber_law(const Bumper3DConfig& bumper, double k_normal);
std::shared_ptr<const ImpactLaw> bumper_bottomed_law(double k_normal);

}  // namespace isopound
