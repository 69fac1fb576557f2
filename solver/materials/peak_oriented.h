// Peak-oriented hysteresis with a capped backbone and cyclic deterioration, after Ibarra, Medina
// & Krawinkler (2005), "Hysteretic models that incorporate strength and stiffness deterioration",
// Earthquake Engng Struct. Dyn. 34:1489-1511 (IMK), for a storey of a reinforced-concrete frame.
//
// Backbone (each side, in magnitudes x = |d|, f = |F|; k the elastic stiffness):
//   f = k x up to the yield point (d_y, F_y), F_y = k d_y;
//   hardening f = F_y + K_s (x - d_y), K_s = alpha k, up to the capping point (d_c, F_c);
//   post-capping f = F_ref - K_c x, K_c = post_capping_ratio k, F_ref = F_c + K_c d_c;
//   residual plateau f = F_r = residual_strength_ratio F_y (the floor of the backbone).
// Hysteresis rules (IMK section 3, peak-oriented):
//   unloading with the unloading stiffness K_u (initially k) until the force crosses zero;
//   reloading from that zero-force point d_0 along a straight line towards the target point of
//   the side being loaded, (d_t, backbone(d_t)), where d_t is the largest deformation reached
//   on that side (initially the yield point), then along the backbone; a partial unloading
//   reloads with K_u until it meets the same reloading line. The force is the smallest of the
//   elastic (K_u) trial, the reloading line and the backbone, so the path is piecewise linear.
// Cyclic deterioration (IMK eq. 2-4), c = 1: an excursion i ends where the force crosses zero;
// with E_i the energy it dissipated and E_t = lambda F_y d_y the reference hysteretic energy,
//   beta_i = E_i / (E_t - sum_{j<=i} E_j), clipped to [0, 1] (1 once E_t is spent);
// one beta for the four IMK modes, applied when the excursion ends to the side loaded next
// (basic strength: F_y and K_s; post-capping strength: F_ref; accelerated reloading: the target
// d_t *= 1 + beta) and to the unloading stiffness: K_u *= 1 - beta (not below 1 % of k).
// lambda = 0: no cyclic deterioration. Not modelled: an ultimate deformation (the residual
// plateau continues), separate lambdas and exponents c per mode.
// Energy: the work along the path is integrated exactly over its linear pieces; the recoverable
// energy is F^2 / (2 K_u), so E_i is the work between two zero-force crossings.
#pragma once

#include "solver/materials/hysteresis.h"

namespace isopound {

struct PeakOrientedParameters {
  double elastic_stiffness = 0.0;        // k, N/m
  double yield_deformation = 0.0;        // d_y, m
  double post_yield_ratio = 0.0;         // alpha = K_s / k, in [0, 1)
  double capping_deformation = 0.0;      // d_c > d_y, m
  double post_capping_ratio = 0.0;       // K_c / k > 0
  double residual_strength_ratio = 0.0;  // F_r / F_y in [0, 1]
  double deterioration = 0.0;            // lambda >= 0 (0: none)
};

class PeakOrientedMaterial final : public UniaxialMaterial {
 public:
  explicit PeakOrientedMaterial(const PeakOrientedParameters& p);

  void set_trial(double d) override;
  double force() const override { return trial_.force; }
  double tangent() const override { return trial_.tangent; }
  double internal() const override { return trial_.force / yield_force_; }  // F / F_y
  double stored_energy() const override;
  double deformation() const override { return trial_.d; }
  void commit() override { committed_ = trial_; }
  void revert() override { trial_ = committed_; }
  std::unique_ptr<UniaxialMaterial> clone() const override {
    return std::make_unique<PeakOrientedMaterial>(*this);
  }

  // The current backbone force magnitude at deformation magnitude x on side +1 or -1 (tests).
  double backbone(int side, double x) const;
  double unloading_stiffness() const { return trial_.unloading_stiffness; }
  double dissipated_energy() const { return trial_.work - stored_energy(); }

 private:
  struct Side {
    double yield_force;  // F_y of this side (deteriorates), N
    double hardening;    // K_s, N/m
    double capping_ref;  // F_ref, N
    double target;       // d_t, magnitude, m
    double zero_point;   // d_0 (signed) where the current reloading towards it began, m
  };
  struct State {
    double d = 0.0, force = 0.0, tangent = 0.0;
    double unloading_stiffness = 0.0;
    double work = 0.0;                // int F dd along the path, J
    double energy_at_crossing = 0.0;  // sum of E_j of the finished excursions, J
    Side side[2];                     // [0]: positive, [1]: negative
  };
  // Force magnitude on the loading branch of side s from (x_c, f_c) to x (x_c <= x), with the
  // exact integral of f over [x_c, x] and the slope at x.
  double load(const State& s, int side, double x_c, double f_c, double x, double& integral,
              double& slope) const;
  void deteriorate(State& s, int side, double excursion_energy) const;

  PeakOrientedParameters p_;
  double yield_force_;       // F_y of the initial backbone, N
  double residual_force_;    // F_r, N
  double capping_slope_;     // K_c, N/m
  double reference_energy_;  // E_t = lambda F_y d_y, J (0: no deterioration)
  State trial_, committed_;
};

}  // namespace isopound
