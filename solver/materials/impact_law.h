// 2D impact (penalty) laws of THEORY section 4 as pure functions of the penetration and its
// rate: delta > 0 is penetration (m), rate = d delta/dt > 0 while the bodies approach (m/s).
#pragma once

#include <memory>
#include <span>
#include <string>
#include <string_view>

namespace isopound {

// What a law remembers of the current contact, set once at its onset by begin_contact().
struct ImpactPhase {
  double impact_velocity = 0.0;  // v_imp > 0: approach rate at delta = 0 (floored, see config)
  double restitution = 0.0;      // e used for this contact (constant, or from v_imp by material)
  double damping = 0.0;          // the law's damping coefficient for this contact (c, xi_hat,
                                 // c_h factor or xi_h; meaning per law, documented in each)
  // Behind a bumper (bumper_law.h): the wall law's own phase, begun with the same v_imp.
  double wall_impact_velocity = 0.0;
  double wall_restitution = 0.0;
  double wall_damping = 0.0;
  // Behind a bumper whose bottoming out jumps the force: the concrete stage is on. It changes
  // only at an event (the contact element's settle_event), so a step cut there keeps its side.
  bool bottomed = false;
};

// Force of a law and its partial derivatives at (delta, rate).
struct ImpactResponse {
  double force = 0.0;      // N; > 0 pushes the bodies apart, < 0 is tension (KV only)
  double stiffness = 0.0;  // dF/d delta, N/m
  double damping = 0.0;    // dF/d rate, N s/m
};

// Material for velocity-dependent restitution, e = a v^3 + b v^2 + c v + d (eq. 3.23).
enum class ImpactMaterial { kNone, kConcrete, kSteel, kTimber, kCeramic };

struct ImpactLawConfig {
  std::string law = "kelvin_voigt";  // see make_impact_law for the names
  double k = 2.5e9;                  // N/m, linear-type laws (1-6)
  double k_h = 2.5e9;                // N/m^n, Hertz-type laws (7-10)
  double n = 1.5;                    // Hertz exponent (laws 7, 9, 10; law 8 uses 1.5 by definition)
  double e = 0.7;                    // coefficient of restitution in (0, 1] (constant e)
  ImpactMaterial material = ImpactMaterial::kNone;  // velocity-dependent e instead of e
  double mass_1 = 0.0;  // kg, the two colliding masses -> m_eff = m1 m2 / (m1 + m2)
  double mass_2 = 0.0;  // kg (a rigid wall: its given mass, thesis 500 t)
  // Mahmoud-Jankowski xi: "eq_3_12" (default) xi = (1-e^2)/(e(e(pi-2)+2)); "eq_3_11" (1-e^2)/(pi
  // e).
  std::string xi_formula = "eq_3_12";
  // Laws dividing by v_imp (4, 6, 9, 10): approach speeds below this are raised to it (m/s).
  double min_impact_velocity = 1e-3;
};

class ImpactLaw {
 public:
  virtual ~ImpactLaw() = default;
  // Called when a contact starts, with the approach rate at delta = 0 (m/s, > 0).
  virtual void begin_contact(double impact_velocity, ImpactPhase& phase) const = 0;
  // Force for delta > 0 (the caller gives 0 for delta <= 0).
  virtual ImpactResponse respond(double delta, double rate, const ImpactPhase& phase) const = 0;
  // false: a tensile force is set to 0 and the contact ends there, leaving a permanent
  // indentation (modified Kelvin-Voigt); true: tension is kept until delta returns to 0.
  virtual bool tension_allowed() const = 0;
  // Recoverable energy at penetration delta (J): the integral of the elastic part
  // F_e = F(delta, 0). The default is exact for a power law F_e = K delta^n:
  // F_e delta / (n + 1) with n = delta F_e' / F_e. 0 outside contact.
  virtual double stored_energy(double delta, const ImpactPhase& phase) const;
  // Penetration at which the force changes its form (a bumper bottoming out), or +inf: the
  // contact element ends a step there, as at the approach/restitution switch.
  virtual double stage_penetration() const;
  virtual std::string_view name() const = 0;
  virtual std::unique_ptr<ImpactLaw> clone() const = 0;
};

// Names: linear, kelvin_voigt, modified_kelvin_voigt, ye, mahmoud_jankowski,
// pant_wijeyewickrema, hertz, jankowski, hertz_damp_muthukumar, hertz_damp_ye.
// Throws std::invalid_argument for an unknown name or invalid parameters.
std::unique_ptr<ImpactLaw> make_impact_law(const ImpactLawConfig& config);

// --- restitution and stiffness helpers (THEORY section 4) ---
double effective_mass(double m1, double m2);  // m1 m2/(m1+m2); m2 = inf -> m1
double kelvin_voigt_xi(double e);             // -ln e / sqrt(pi^2 + ln^2 e)   (eq. 3.7)
double restitution_of_material(ImpactMaterial m, double impact_velocity);  // eq. 3.23
double restitution_of_pair(double e1, double E1, double e2, double E2);    // eq. 3.22
// Hertz stiffness of two spheres (eq. 3.24-3.25), N/m^1.5; R2 = inf gives sphere-plane.
double hertz_stiffness_spheres(double R1, double E1, double nu1, double R2, double E2, double nu2);
double equivalent_radius(double mass, double density);  // (3m/(4 pi rho))^(1/3) (eq. 3.27)
double axial_stiffness(double E, double A, double L);   // EA/L (eq. 3.28)

// --- added with solver/impact_law.cpp ---
// The ten law names in THEORY order (laws 1-10), as accepted by make_impact_law.
std::span<const std::string_view> impact_law_names();
// Damping ratio of Mahmoud-Jankowski (law 5): "eq_3_12" (1-e^2)/(e(e(pi-2)+2)), the default,
// or "eq_3_11" (1-e^2)/(pi e). Throws std::invalid_argument for e outside (0, 1] or another name.
double mahmoud_jankowski_xi(double e, std::string_view formula = "eq_3_12");
// xi_h of Jankowski's nonlinear viscoelastic law (law 8, eq. 3.17):
// (9 sqrt5 / 2) (1-e^2) / (e (e (9 pi - 16) + 16)).
double jankowski_xi(double e);
// Which ImpactLawConfig fields a law reads (the input reader asks only for those).
struct ImpactLawUses {
  bool k = false, k_h = false, n = false, e = false, mass = false;
  bool min_impact_velocity = false;  // laws dividing by v_imp (4, 6, 9, 10)
  bool xi_formula = false;           // mahmoud_jankowski
};
// Throws std::invalid_argument for an unknown name.
ImpactLawUses impact_law_uses(std::string_view name);
// "none", "concrete", "steel", "timber", "ceramic" <-> ImpactMaterial (throws for other names).
ImpactMaterial impact_material_from_name(std::string_view name);
std::string_view impact_material_name(ImpactMaterial m);

}  // namespace isopound
