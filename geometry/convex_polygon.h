// ConvexPolygon: a convex polygon in plan (a floor diaphragm, a wall), its validation, rigid
// placement by (u, v, θ) and mass properties. Vertices counter-clockwise, in metres, plan frame W.
#pragma once

#include <array>
#include <initializer_list>
#include <span>
#include <stdexcept>
#include <string>

namespace isopound {

// A point or vector in plan (metres for points).
struct Vec2 {
  double x = 0.0;
  double y = 0.0;
};

inline Vec2 operator+(Vec2 a, Vec2 b) {
  return {a.x + b.x, a.y + b.y};
}
inline Vec2 operator-(Vec2 a, Vec2 b) {
  return {a.x - b.x, a.y - b.y};
}
inline Vec2 operator*(double s, Vec2 a) {
  return {s * a.x, s * a.y};
}
inline double dot(Vec2 a, Vec2 b) {
  return a.x * b.x + a.y * b.y;
}
// z-component of a × b: > 0 when b is counter-clockwise from a.
inline double cross(Vec2 a, Vec2 b) {
  return a.x * b.y - a.y * b.x;
}

// Fixed storage for up to N plan points that is not zeroed when constructed: a polygon or an
// overlap reads only its first `count` entries, and zeroing the rest (Vec2's members start at 0)
// cost a few per cent of a 3D wall run (512-byte arrays per overlap, 256 bytes per placed
// polygon: perf, issue 39). A copy copies the bytes as they are.
template <int N>
class VertexArray {
 public:
  VertexArray() {}  // deliberately leaves the points unset
  Vec2& operator[](int i) { return points_[i]; }
  const Vec2& operator[](int i) const { return points_[i]; }
  Vec2* data() { return points_; }
  const Vec2* data() const { return points_; }

 private:
  union {
    Vec2 points_[N];
  };
};

// Most vertices a ConvexPolygon may have. Two of them intersect in at most 2·kMax vertices, so
// every overlap fits in fixed arrays (no allocation in the contact loop).
inline constexpr int kMaxPolygonVertices = 16;

// Thrown by ConvexPolygon's validation. `vertex()` is the 0-based index of the offending vertex
// in the order given, or -1 when the fault is the polygon as a whole (too few vertices, zero area).
class InvalidPolygon : public std::invalid_argument {
 public:
  InvalidPolygon(int vertex, const std::string& what)
      : std::invalid_argument(what), vertex_(vertex) {}
  int vertex() const { return vertex_; }

 private:
  int vertex_;
};

// Rigid motion in plan: rotation θ (rad, counter-clockwise) about a point, then translation (u, v).
// The DOFs (u, v, θ) of a diaphragm are taken at the point `about` (the global origin for floors).
struct Placement2 {
  double u = 0.0;      // m, translation along x
  double v = 0.0;      // m, translation along y
  double theta = 0.0;  // rad, counter-clockwise
};

// A strictly convex polygon, vertices counter-clockwise. Invariants (checked on construction):
// 3..kMaxPolygonVertices finite vertices, no two equal, every turn strictly left (no vertex on
// the line through its neighbours), turning once around (no star shapes), area > 0.
// Clockwise input is FIXED (the order is reversed), not rejected: the same outline, either way.
class ConvexPolygon {
 public:
  // Validates; throws InvalidPolygon with a message naming the vertex (index in `vertices`).
  explicit ConvexPolygon(std::span<const Vec2> vertices);
  ConvexPolygon(std::initializer_list<Vec2> vertices);
  // Copies the vertices there are, not the whole storage (a fixed wall's shape is copied at
  // every contact evaluation).
  ConvexPolygon(const ConvexPolygon& other) { *this = other; }
  ConvexPolygon& operator=(const ConvexPolygon& other) {
    count_ = other.count_;
    reversed_ = other.reversed_;
    box_min_ = other.box_min_;
    box_max_ = other.box_max_;
    for (int i = 0; i < count_; ++i) vertices_[i] = other.vertices_[i];
    return *this;
  }

  int size() const { return count_; }
  const Vec2& operator[](int i) const { return vertices_[i]; }  // i in [0, size())
  std::span<const Vec2> vertices() const { return {vertices_.data(), size_t(count_)}; }
  // Axis-aligned bounding box (kept with the vertices: the rejection test reads it).
  Vec2 box_min() const { return box_min_; }
  Vec2 box_max() const { return box_max_; }
  // True when the input was clockwise and has been reversed.
  bool was_reversed() const { return reversed_; }

  // This polygon moved rigidly: each vertex p ↦ about + R(θ)(p − about) + (u, v).
  // No validation and no allocation (a rigid motion keeps a valid polygon valid, up to round-off).
  ConvexPolygon placed(const Placement2& x, Vec2 about = {0.0, 0.0}) const;
  // The same with cos θ and sin θ given (a caller that places at one θ often keeps them): the
  // same vertices, bit for bit, when they are std::cos(x.theta) and std::sin(x.theta).
  ConvexPolygon placed(const Placement2& x, Vec2 about, double cos_theta, double sin_theta) const;

 private:
  ConvexPolygon() = default;
  void update_box();

  VertexArray<kMaxPolygonVertices> vertices_;
  int count_ = 0;
  bool reversed_ = false;
  Vec2 box_min_;
  Vec2 box_max_;
};

// Area properties of a plane figure (what a rigid diaphragm's mass matrix needs).
struct AreaProperties {
  double area = 0.0;            // m², > 0
  Vec2 p_WC;                    // centroid C in the plan frame W, m
  double polar_moment_c = 0.0;  // J_c = ∫ |p − C|² dA, m⁴, about the centroid
  // Polar radius of gyration squared about the centroid, r_g² = J_c / A (m²).
  double radius_of_gyration_sq() const { return polar_moment_c / area; }
};

// Area, centroid and polar second moment about the centroid, computed about a vertex-mean origin
// (less round-off far from W's origin). A rectangle b×h: A = bh, J_c = bh(b² + h²)/12.
AreaProperties area_properties(const ConvexPolygon& polygon);
// The same for any simple outline given counter-clockwise (SimplePolygon's, or a piece's).
AreaProperties outline_area_properties(std::span<const Vec2> outline);

}  // namespace isopound
