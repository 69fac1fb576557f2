// The 3D polygon contact's tangent by forward-mode differentiation (solver/core/dual.h): the
// force law of PolygonContact::evaluate, on the trial's branch, written once more in dual numbers.
// The overlap's topology is the trial's (which vertex of A or B, which crossing of an A edge with
// a B edge): its vertices follow the bodies, so the area A_c, centroid C and chord P1P2 are
// smooth functions of the placement, and so is the force
//   F_N = k_N A_c + 2ξ √(k_N w_s m_eff) δ̇_N (clamped at 0 as the trial is),
//   F_T = s_c + k_T Δu_T + c_T u̇_T (stick) or ± μ F_N (slip, sign of the trial's f_tr),
//   on B: F_N n_AB − F_T t_AB at C; on A its opposite; torques about each body's moving O.
// The same law as the differences of evaluate() without their truncation error (~1e-8 relative)
// and in one pass instead of two evaluations per DOF. THEORY-notes.md, "3D contact tangent".
#include "solver/core/dual.h"
#include "solver/elements/polygon_contact.h"

namespace isopound {

template <int N>
bool PolygonContact::differentiate(const std::array<Vec6, N>& dq, const std::array<Vec6, N>& dqdot,
                                   std::array<Vec6, N>& df) const {
  const State& T = trial_;
  const State& C = committed_;
  if (!T.differentiable || !T.closed) return false;
  using D = Dual<N>;
  using V = DualVec2<N>;
  std::array<D, kDofs> q, qdot;
  for (int k = 0; k < kDofs; ++k) {
    q[k].v = T.q[k];
    qdot[k].v = T.qdot[k];
    for (int n = 0; n < N; ++n) {
      q[k].d[n] = dq[n][k];
      qdot[k].d[n] = dqdot[n][k];
    }
  }
  // Coordinates relative to the trial's centroid (small numbers near the overlap).
  const Vec2 origin = T.p_WC;
  const auto constant = [](Vec2 p) { return V{D::constant(p.x), D::constant(p.y)}; };
  struct Placement {
    bool fixed;
    D cos, sin;
  };
  const auto placement_of = [&](const PolygonBody& body, int k) {
    const bool fixed = body.dof_u < 0 && body.dof_v < 0 && body.dof_theta < 0;
    return Placement{fixed, fixed ? D::constant(1.0) : cos(q[k + 2]),
                     fixed ? D::constant(0.0) : sin(q[k + 2])};
  };
  const Placement place_A = placement_of(a_, 0), place_B = placement_of(b_, 3);
  // The placed vertex i of a body (ConvexPolygon::placed), relative to origin.
  const auto vertex = [&](const PolygonBody& body, const Placement& x, int k, int i) {
    const Vec2 p = body.shape[i];
    if (x.fixed) return constant(p - origin);
    const Vec2 r = p - body.p_WO;
    const Vec2 o = body.p_WO - origin;
    return V{x.cos * r.x - x.sin * r.y + q[k] + o.x, x.sin * r.x + x.cos * r.y + q[k + 1] + o.y};
  };
  const int n_a = a_.shape.size(), n_b = b_.shape.size();
  const int count = T.topology_count;
  std::array<V, kMaxOverlapVertices> p;
  for (int k = 0; k < count; ++k) {
    const OverlapVertexSource s = T.topology[k];
    switch (s.kind) {
      case OverlapVertexKind::kVertexOfA:
        p[k] = vertex(a_, place_A, 0, s.a);
        break;
      case OverlapVertexKind::kVertexOfB:
        p[k] = vertex(b_, place_B, 3, s.b);
        break;
      case OverlapVertexKind::kCrossing: {
        // As overlap.cpp's crossing_point: the parameter along A's edge from the turns of its
        // ends about B's edge line.
        const V a0 = vertex(a_, place_A, 0, s.a), a1 = vertex(a_, place_A, 0, (s.a + 1) % n_a);
        const V b0 = vertex(b_, place_B, 3, s.b), b1 = vertex(b_, place_B, 3, (s.b + 1) % n_b);
        const V d = b1 - b0;
        const D h0 = cross(d, a0 - b0), h1 = cross(d, a1 - b0);
        p[k] = a0 + (h0 / (h0 - h1)) * (a1 - a0);
        break;
      }
    }
  }
  // Area and centroid by the triangle fan about vertex 0 (overlap.cpp's); every fan triangle
  // positive (else the fast path's clamped weights: not differentiated here).
  D twice_area;
  V moment{};
  for (int k = 1; k + 1 < count; ++k) {
    const V d1 = p[k] - p[0], d2 = p[k + 1] - p[0];
    const D w = cross(d1, d2);
    if (!(w.v > 0.0)) return false;
    twice_area = twice_area + w;
    moment = moment + w * (d1 + d2);
  }
  const D area = 0.5 * twice_area;
  const V p_C = p[0] + (1.0 / 3.0 * (D::constant(1.0) / twice_area)) * moment;
  const V chord = p[T.chord_exit] - p[T.chord_entry];
  const D width = sqrt(dot(chord, chord));
  const V t_AB{chord.x / width, chord.y / width};
  const V n_AB{t_AB.y, -t_AB.x};
  const D secant_width =
      cfg_.indentation == IndentationRule::kThesis && T.triangle ? 0.5 * width : width;

  const V o_A{q[0] + (a_.p_WO.x - origin.x), q[1] + (a_.p_WO.y - origin.y)};
  const V o_B{q[3] + (b_.p_WO.x - origin.x), q[4] + (b_.p_WO.y - origin.y)};
  const V r_A = p_C - o_A, r_B = p_C - o_B;
  const V v_A{qdot[0] - qdot[2] * r_A.y, qdot[1] + qdot[2] * r_A.x};
  const V v_B{qdot[3] - qdot[5] * r_B.y, qdot[4] + qdot[5] * r_B.x};
  const D rate_n = dot(v_A - v_B, n_AB);
  const D rate_t = dot(v_B - v_A, t_AB);

  const D elastic = cfg_.k_normal * area;
  const D c_n = 2 * xi_ * sqrt(cfg_.k_normal * m_eff_ * secant_width);
  const D raw = elastic + c_n * rate_n;
  // The clamp as evaluate's max(raw, 0): the branch of the trial's value.
  const D normal = cfg_.keep_tension || !(raw.v < 0.0) ? raw : D::constant(0.0);
  D tangential;
  if (cfg_.friction) {
    // Material displacement, committed → trial, of each body's point now at C.
    const auto displacement = [&](int k, const V& o_now, Vec2 p_WO) {
      const Vec2 o_then = p_WO + Vec2{C.q[k], C.q[k + 1]} - origin;
      const D angle = C.q[k + 2] - q[k + 2];
      const D c = cos(angle), s = sin(angle);
      const V r = p_C - o_now;
      return V{p_C.x - (c * r.x - s * r.y + o_then.x), p_C.y - (s * r.x + c * r.y + o_then.y)};
    };
    const D du_t = dot(displacement(3, o_B, b_.p_WO) - displacement(0, o_A, a_.p_WO), t_AB);
    const double s_c = T.started ? 0.0 : C.spring;
    const D f_tr = s_c + cfg_.k_tangential * du_t + c_tangential_ * rate_t;
    if (T.slipping) {
      const bool from_stick = T.started || !C.slipping;
      const double mu = cfg_.continuous_force && from_stick ? cfg_.mu_static : cfg_.mu_kinetic;
      const D limit = normal.v > 0.0 ? mu * normal : D::constant(0.0);
      const double sign = T.tangential_trial > 0 ? 1.0 : (T.tangential_trial < 0 ? -1.0 : 0.0);
      tangential = sign * limit;
    } else {
      tangential = f_tr;
    }
  }
  const V f_B = normal * n_AB - tangential * t_AB;
  const std::array<D, kDofs> force = {f_B.x,  f_B.y,  cross(r_A, f_B),
                                      -f_B.x, -f_B.y, -cross(r_B, f_B)};
  for (int n = 0; n < N; ++n)
    for (int k = 0; k < kDofs; ++k) df[n][k] = force[k].d[n];
  return true;
}

template bool PolygonContact::differentiate<1>(const std::array<Vec6, 1>&,
                                               const std::array<Vec6, 1>&,
                                               std::array<Vec6, 1>&) const;
template bool PolygonContact::differentiate<3>(const std::array<Vec6, 3>&,
                                               const std::array<Vec6, 3>&,
                                               std::array<Vec6, 3>&) const;

}  // namespace isopound
