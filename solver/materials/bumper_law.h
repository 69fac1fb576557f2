// A rubber bumper on a wall face in series with the wall's own impact law (issue 27).
// Rubber: F_r = K(x) (1 + zeta x'/v_imp)+, K = k x^n (n = 1 linear, 3/2 Hertz-type; Hunt and
// Crossley 1975), zeta from e by the exact restitution of that law; bottomed out at
// x = max_strain t, the wall law acts on the rest of the penetration (docs/impact-laws.md).
#pragma once

#include <cstddef>
#include <memory>
#include <string>

#include "solver/materials/impact_law.h"

namespace isopound {

// How the wall's law takes over where the rubber bottoms out (docs/impact-laws.md).
enum class BumperBottoming {
  kContinuous,  // F_w(delta - s) - F_w(0+): continuous force; a Kelvin-Voigt dashpot is dropped
  kJump,        // F_w(delta - s): the wall's own onset jump (c rate for the Kelvin-Voigt family)
};

struct BumperConfig {
  double thickness = 0.0;      // m, rubber layer on the wall face; 0: no bumper (bare wall)
  std::string law = "linear";  // rubber's elastic part: "linear" k x, "hertz" k x^1.5
  // Stiffness: k (N/m, or N/m^1.5 for hertz), or from the rubber's modulus and contact area
  // when k = 0: linear k = E A / t (eq. 3.28), hertz k = E A / t^1.5 (F = E A (x/t)^1.5).
  double k = 0.0;
  double modulus = 0.0;     // Pa
  double area = 0.0;        // m^2
  double e = 0.8;           // rubber's coefficient of restitution in (0, 1]
  double max_strain = 0.6;  // compression at which the rubber bottoms out, fraction of t, (0, 1)
  double min_impact_velocity = 1e-3;  // m/s, floor of v_imp (the damping divides by it)
  BumperBottoming bottoming = BumperBottoming::kContinuous;
};

// The rubber's stiffness from the configuration (k, or E A / t, E A / t^1.5).
double bumper_stiffness(const BumperConfig& bumper);

// zeta(e): the damping factor for which the free impact x'' = -x^n (1 + zeta x') (the law
// made dimensionless with v_imp and its own length scale) rebounds at e times the approach
// speed: the root of ln((1 + zeta)/(1 - e zeta)) = (1 + e) zeta, the same for every n;
// zeta(1) = 0. Throws std::invalid_argument for e outside (0, 1].
double hunt_crossley_factor(double e);

// The bumper law. delta is the penetration past the bumper's face (gap - thickness);
// the rubber's compression is x = min(delta, s), s = max_strain thickness.
//   delta <= s: F = F_r(delta, rate)
//   delta >  s: F = F_r(s, rate) + F_w(delta - s, rate) - F_w(0+, rate)
// F_w the wall's law, begun with the same v_imp as the rubber. Subtracting its value at zero
// penetration (c rate for the Kelvin-Voigt family, 0 for the others) makes F continuous at the
// bottoming out. F is clamped at 0: a bumper does not pull.
// With BumperBottoming::kJump the subtraction is left out and the concrete stage is on while
// phase.bottomed (set by the contact element at the crossing, an event where F jumps).
class BumperLaw final : public ImpactLaw {
 public:
  BumperLaw(const BumperConfig& bumper, std::unique_ptr<ImpactLaw> wall);

  void begin_contact(double impact_velocity, ImpactPhase& phase) const override;
  ImpactResponse respond(double delta, double rate, const ImpactPhase& phase) const override;
  bool tension_allowed() const override { return true; }
  std::string_view name() const override { return "bumper"; }
  std::unique_ptr<ImpactLaw> clone() const override;
  double stored_energy(double delta, const ImpactPhase& phase) const override;
  double stage_penetration() const override { return bottom_; }
  bool bottoming_jumps() const { return jump_; }

  // The rubber's compression (m) and the force of its damping part, F_r - K(x) (N).
  double compression(double delta) const;
  double rubber_damping_force(double delta, double rate, const ImpactPhase& phase) const;
  double thickness() const { return thickness_; }
  double zeta() const { return zeta_; }
  double stiffness() const { return k_; }
  const ImpactLaw& wall() const { return *wall_; }

 private:
  BumperLaw(const BumperLaw& other, std::nullptr_t);  // copies all but the wall law (clone)
  ImpactPhase wall_phase(const ImpactPhase& phase) const;

  double thickness_, bottom_, k_, n_, e_, zeta_, min_impact_velocity_;
  bool jump_;
  std::unique_ptr<ImpactLaw> wall_;
};

// Validates the bumper (std::invalid_argument naming the field) and wraps the wall's law.
std::unique_ptr<ImpactLaw> make_bumper_law(const BumperConfig& bumper,
                                           std::unique_ptr<ImpactLaw> wall);

}  // namespace isopound
