// The ten 2D impact laws of THEORY section 4 (eq. 3.3-3.21), their factory, and the restitution
// and stiffness helpers (eq. 3.22-3.28). delta > 0 penetration, rate > 0 approaching, F > 0 repels.
#include "solver/materials/impact_law.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <sstream>
#include <stdexcept>

namespace isopound {

namespace {

constexpr double kPi = std::numbers::pi;

// The cubic fits of eq. 3.23 decrease monotonically with v and reach e = 0 near 7 m/s
// (concrete 7.1, timber 8.0, steel 8.2, ceramic 8.4 m/s); e is held at this value beyond.
constexpr double kMinMaterialRestitution = 0.01;

std::string format_value(double v) {
  std::ostringstream os;
  os.precision(10);
  os << v;
  return os.str();
}

[[noreturn]] void reject(std::string_view law, std::string_view field, double value,
                         std::string_view requirement) {
  throw std::invalid_argument("impact law '" + std::string(law) + "': " + std::string(field) +
                              " = " + format_value(value) + " " + std::string(requirement));
}

void require_restitution(std::string_view where, double e) {
  if (!(e > 0.0 && e <= 1.0))
    throw std::invalid_argument(std::string(where) + ": coefficient of restitution e = " +
                                format_value(e) + " must be in (0, 1]");
}

// k delta^n and its slope n k delta^(n-1) for delta >= 0, with no pow for n = 1.5 and n = 1.
// Where the slope is infinite (delta = 0 with n < 1) it is returned as 0.
struct PowerTerm {
  double value;
  double slope;
};

PowerTerm power_term(double delta, double n) {
  if (n == 1.5) {
    const double s = std::sqrt(delta);
    return {delta * s, 1.5 * s};
  }
  if (n == 1.0) return {delta, 1.0};
  const double value = std::pow(delta, n);
  return {value, delta > 0.0 ? n * value / delta : 0.0};
}

// What every law shares: e for the contact (constant, or from v_imp by material) and the
// floored impact velocity. The law adds its own damping coefficient for the contact.
class LawBase : public ImpactLaw {
 public:
  explicit LawBase(const ImpactLawConfig& c)
      : e_(c.e), material_(c.material), min_impact_velocity_(c.min_impact_velocity) {}

  void begin_contact(double impact_velocity, ImpactPhase& phase) const final {
    // A NaN or grazing (< floor) approach speed is raised to the floor.
    phase.impact_velocity =
        impact_velocity > min_impact_velocity_ ? impact_velocity : min_impact_velocity_;
    phase.restitution = material_ == ImpactMaterial::kNone
                            ? e_
                            : restitution_of_material(material_, phase.impact_velocity);
    phase.damping = contact_damping(phase.restitution, phase.impact_velocity);
  }
  bool tension_allowed() const override { return true; }

 protected:
  // The law's damping coefficient for a contact with restitution e at approach speed v_imp.
  virtual double contact_damping(double e, double v_imp) const = 0;

 private:
  double e_;
  ImpactMaterial material_;
  double min_impact_velocity_;
};

// ---------------------------------------------------------------------------------------------
// Linear-spring family (laws 1-6), stiffness k in N/m.
// ---------------------------------------------------------------------------------------------

// 1. Linear spring (eq. 3.3):  F = k delta.
// Elastic: the apparent restitution is 1 whatever e. phase.damping = 0.
class LinearLaw final : public LawBase {
 public:
  explicit LinearLaw(const ImpactLawConfig& c) : LawBase(c), k_(c.k) {}
  ImpactResponse respond(double delta, double, const ImpactPhase&) const override {
    if (!(delta >= 0.0)) return {};
    return {k_ * delta, k_, 0.0};
  }
  std::string_view name() const override { return "linear"; }
  std::unique_ptr<ImpactLaw> clone() const override { return std::make_unique<LinearLaw>(*this); }

 protected:
  double contact_damping(double, double) const override { return 0.0; }

 private:
  double k_;
};

// 2. Kelvin-Voigt (Anagnostopoulos 1988; eq. 3.5-3.7):  F = k delta + c rate,
//    c = 2 xi sqrt(k m_eff),  xi = -ln e / sqrt(pi^2 + ln^2 e).
// The damped linear oscillator started at delta = 0 with rate v_imp is back at delta = 0 after
// half a damped period with rate -e v_imp: e is reproduced exactly. The price: F jumps to
// c v_imp at onset, and F = c rate < 0 (tension) just before separation, which this law keeps.
// phase.damping = c (N s/m); it depends on the contact only through e (material e).
class KelvinVoigtLaw : public LawBase {
 public:
  explicit KelvinVoigtLaw(const ImpactLawConfig& c)
      : LawBase(c), k_(c.k), sqrt_k_meff_(std::sqrt(c.k * effective_mass(c.mass_1, c.mass_2))) {}
  ImpactResponse respond(double delta, double rate, const ImpactPhase& phase) const override {
    if (!(delta >= 0.0)) return {};
    return {k_ * delta + phase.damping * rate, k_, phase.damping};
  }
  std::string_view name() const override { return "kelvin_voigt"; }
  std::unique_ptr<ImpactLaw> clone() const override {
    return std::make_unique<KelvinVoigtLaw>(*this);
  }

 protected:
  double contact_damping(double e, double) const override {
    return 2.0 * kelvin_voigt_xi(e) * sqrt_k_meff_;
  }

 private:
  double k_;
  double sqrt_k_meff_;  // sqrt(k m_eff)
};

// 3. Modified Kelvin-Voigt (Komodromos et al. 2007; eq. 3.8): the force of law 2, but no
//    tension: where k delta + c rate < 0 the contact element sets F = 0 and ends the contact,
//    leaving a permanent indentation delta_p (the delta there) that widens the gap.
// respond() returns the unclamped law-2 force, so that the element sees where it turns tensile.
class ModifiedKelvinVoigtLaw final : public KelvinVoigtLaw {
 public:
  using KelvinVoigtLaw::KelvinVoigtLaw;
  bool tension_allowed() const override { return false; }
  std::string_view name() const override { return "modified_kelvin_voigt"; }
  std::unique_ptr<ImpactLaw> clone() const override {
    return std::make_unique<ModifiedKelvinVoigtLaw>(*this);
  }
};

// 4. Ye, Li & Zhu 2009 (eq. 3.9):  F = k delta + xi_hat delta rate = delta (k + xi_hat rate),
//    xi_hat = 1.5 k (1 - e) / (e v_imp).
// The dashpot grows with delta: no jump at onset. Tension would need rate < -k / xi_hat,
// i.e. a separation speed above e v_imp / (1.5 (1 - e)), which exceeds v_imp for e >= 0.6.
// phase.damping = xi_hat (N s/m^2).
class YeLaw final : public LawBase {
 public:
  explicit YeLaw(const ImpactLawConfig& c) : LawBase(c), k_(c.k) {}
  ImpactResponse respond(double delta, double rate, const ImpactPhase& phase) const override {
    if (!(delta >= 0.0)) return {};
    const double xi_hat = phase.damping;
    return {delta * (k_ + xi_hat * rate), k_ + xi_hat * rate, xi_hat * delta};
  }
  std::string_view name() const override { return "ye"; }
  std::unique_ptr<ImpactLaw> clone() const override { return std::make_unique<YeLaw>(*this); }

 protected:
  double contact_damping(double e, double v_imp) const override {
    return 1.5 * k_ * (1.0 - e) / (e * v_imp);
  }

 private:
  double k_;
};

// 5. Mahmoud & Jankowski 2011 (eq. 3.10-3.12):
//    approach (rate > 0):        F = k delta + c rate,
//    restitution (rate <= 0):    F = k delta,
//    c = 2 xi sqrt(k m_eff),  xi = (1 - e^2) / (e (e (pi - 2) + 2))   (eq. 3.12, default)
//                         or  xi = (1 - e^2) / (pi e)                 (eq. 3.11, option).
// Never tensile. F is continuous at rate = 0; dF/d rate jumps there from c to 0.
// phase.damping = c (N s/m).
class MahmoudJankowskiLaw final : public LawBase {
 public:
  explicit MahmoudJankowskiLaw(const ImpactLawConfig& c)
      : LawBase(c),
        k_(c.k),
        sqrt_k_meff_(std::sqrt(c.k * effective_mass(c.mass_1, c.mass_2))),
        xi_formula_(c.xi_formula == "eq_3_11" ? "eq_3_11" : "eq_3_12") {}
  ImpactResponse respond(double delta, double rate, const ImpactPhase& phase) const override {
    if (!(delta >= 0.0)) return {};
    if (rate > 0.0) return {k_ * delta + phase.damping * rate, k_, phase.damping};
    return {k_ * delta, k_, 0.0};
  }
  std::string_view name() const override { return "mahmoud_jankowski"; }
  std::unique_ptr<ImpactLaw> clone() const override {
    return std::make_unique<MahmoudJankowskiLaw>(*this);
  }

 protected:
  double contact_damping(double e, double) const override {
    return 2.0 * mahmoud_jankowski_xi(e, xi_formula_) * sqrt_k_meff_;
  }

 private:
  double k_;
  double sqrt_k_meff_;
  std::string_view xi_formula_;  // a literal, so the law stays cheap to copy
};

// 6. Pant & Wijeyewickrema 2012 (eq. 3.13):
//    approach (rate > 0):        F = k delta + xi_hat delta rate,
//    restitution (rate <= 0):    F = k delta,
//    xi_hat = 1.5 k (1 - e^2) / (e^2 v_imp).
// Never tensile. phase.damping = xi_hat (N s/m^2).
class PantWijeyewickremaLaw final : public LawBase {
 public:
  explicit PantWijeyewickremaLaw(const ImpactLawConfig& c) : LawBase(c), k_(c.k) {}
  ImpactResponse respond(double delta, double rate, const ImpactPhase& phase) const override {
    if (!(delta >= 0.0)) return {};
    if (rate > 0.0) {
      const double xi_hat = phase.damping;
      return {delta * (k_ + xi_hat * rate), k_ + xi_hat * rate, xi_hat * delta};
    }
    return {k_ * delta, k_, 0.0};
  }
  std::string_view name() const override { return "pant_wijeyewickrema"; }
  std::unique_ptr<ImpactLaw> clone() const override {
    return std::make_unique<PantWijeyewickremaLaw>(*this);
  }

 protected:
  double contact_damping(double e, double v_imp) const override {
    return 1.5 * k_ * (1.0 - e * e) / (e * e * v_imp);
  }

 private:
  double k_;
};

// ---------------------------------------------------------------------------------------------
// Hertz family (laws 7-10), stiffness k_h in N/m^n.
// ---------------------------------------------------------------------------------------------

// 7. Hertz (eq. 3.14):  F = k_h delta^n, n = 3/2 for elastic spheres.
// Elastic: the apparent restitution is 1 whatever e. phase.damping = 0.
class HertzLaw final : public LawBase {
 public:
  explicit HertzLaw(const ImpactLawConfig& c) : LawBase(c), k_h_(c.k_h), n_(c.n) {}
  ImpactResponse respond(double delta, double, const ImpactPhase&) const override {
    if (!(delta >= 0.0)) return {};
    const PowerTerm p = power_term(delta, n_);
    return {k_h_ * p.value, k_h_ * p.slope, 0.0};
  }
  std::string_view name() const override { return "hertz"; }
  std::unique_ptr<ImpactLaw> clone() const override { return std::make_unique<HertzLaw>(*this); }

 protected:
  double contact_damping(double, double) const override { return 0.0; }

 private:
  double k_h_;
  double n_;
};

// 8. Jankowski 2005, nonlinear viscoelastic (eq. 3.15-3.17), n = 3/2 by definition:
//    approach (rate > 0):        F = k_h delta^1.5 + c_h rate,
//    restitution (rate <= 0):    F = k_h delta^1.5,
//    c_h = 2 xi_h sqrt(k_h sqrt(delta) m_eff) = D delta^(1/4),  D = 2 xi_h sqrt(k_h m_eff),
//    xi_h = (9 sqrt5 / 2) (1 - e^2) / (e (e (9 pi - 16) + 16)).
// phase.damping = D (N s/m^(5/4)).
// Slope in approach: dF/d delta = 1.5 k_h sqrt(delta) + (D / 4) rate delta^(-3/4), infinite
// at delta = 0. respond() returns this exact value for delta > 0 (finite in floating point but
// large near onset: ~3e15 N/m at delta = 1e-12 m, rate = 1 m/s, thesis case e = 0.7) and only the
// finite Hertz part (0) at delta = 0. Never tensile.
class JankowskiLaw final : public LawBase {
 public:
  explicit JankowskiLaw(const ImpactLawConfig& c)
      : LawBase(c),
        k_h_(c.k_h),
        sqrt_kh_meff_(std::sqrt(c.k_h * effective_mass(c.mass_1, c.mass_2))) {}
  ImpactResponse respond(double delta, double rate, const ImpactPhase& phase) const override {
    if (!(delta >= 0.0)) return {};
    const double root = std::sqrt(delta);
    const double elastic = k_h_ * delta * root;
    const double elastic_slope = 1.5 * k_h_ * root;
    if (!(rate > 0.0)) return {elastic, elastic_slope, 0.0};
    const double c_h = phase.damping * std::sqrt(root);  // D delta^(1/4)
    const double c_h_slope = delta > 0.0 ? 0.25 * c_h / delta : 0.0;
    return {elastic + c_h * rate, elastic_slope + c_h_slope * rate, c_h};
  }
  std::string_view name() const override { return "jankowski"; }
  std::unique_ptr<ImpactLaw> clone() const override {
    return std::make_unique<JankowskiLaw>(*this);
  }

 protected:
  double contact_damping(double e, double) const override {
    return 2.0 * jankowski_xi(e) * sqrt_kh_meff_;
  }

 private:
  double k_h_;
  double sqrt_kh_meff_;  // sqrt(k_h m_eff)
};

// Laws 9 and 10 share the Hertz-damp force  F = k_h delta^n + xi_h delta^n rate
// = delta^n (k_h + xi_h rate); they differ in xi_h(e, v_imp). phase.damping = xi_h
// (N s/m^(n+1)). With tension allowed, F -> 0 as delta -> 0, so the contact ends at delta = 0.
class HertzDampLaw : public LawBase {
 public:
  explicit HertzDampLaw(const ImpactLawConfig& c) : LawBase(c), k_h_(c.k_h), n_(c.n) {}
  ImpactResponse respond(double delta, double rate, const ImpactPhase& phase) const override {
    if (!(delta >= 0.0)) return {};
    const PowerTerm p = power_term(delta, n_);
    const double factor = k_h_ + phase.damping * rate;
    return {p.value * factor, p.slope * factor, phase.damping * p.value};
  }

 protected:
  double k_h_;
  double n_;
};

// 9. Hertz-damp, Muthukumar & DesRoches 2006 (eq. 3.18-3.20):
//    F = k_h delta^n + xi_h delta^n rate,  xi_h = 0.75 k_h (1 - e^2) / v_imp.
// Tension would need |rate| > v_imp / (0.75 (1 - e^2)) > v_imp: never in a collision.
class HertzDampMuthukumarLaw final : public HertzDampLaw {
 public:
  using HertzDampLaw::HertzDampLaw;
  std::string_view name() const override { return "hertz_damp_muthukumar"; }
  std::unique_ptr<ImpactLaw> clone() const override {
    return std::make_unique<HertzDampMuthukumarLaw>(*this);
  }

 protected:
  double contact_damping(double e, double v_imp) const override {
    return 0.75 * k_h_ * (1.0 - e * e) / v_imp;
  }
};

// 10. Hertz-damp per Ye, Li & Zhu 2009b (eq. 3.21):
//    F = k_h delta^n + xi_h delta^n rate,  xi_h = 1.6 k_h (1 - e) / (e v_imp).
// Tension would need |rate| > e v_imp / (1.6 (1 - e)), which exceeds v_imp for e >= 8/13.
class HertzDampYeLaw final : public HertzDampLaw {
 public:
  using HertzDampLaw::HertzDampLaw;
  std::string_view name() const override { return "hertz_damp_ye"; }
  std::unique_ptr<ImpactLaw> clone() const override {
    return std::make_unique<HertzDampYeLaw>(*this);
  }

 protected:
  double contact_damping(double e, double v_imp) const override {
    return 1.6 * k_h_ * (1.0 - e) / (e * v_imp);
  }
};

// ---------------------------------------------------------------------------------------------
// Factory: which configuration fields each law uses (only those are validated).
// ---------------------------------------------------------------------------------------------

struct LawEntry {
  std::string_view name;
  bool uses_k;     // linear-spring family
  bool uses_k_h;   // Hertz family
  bool uses_n;     // laws 7, 9, 10 (law 8 fixes n = 1.5)
  bool uses_e;     // dissipative laws
  bool uses_mass;  // m_eff enters the damping coefficient
  std::unique_ptr<ImpactLaw> (*make)(const ImpactLawConfig&);
};

template <class Law>
std::unique_ptr<ImpactLaw> make_law(const ImpactLawConfig& c) {
  return std::make_unique<Law>(c);
}

constexpr std::array<LawEntry, 10> kLaws{{
    {"linear", true, false, false, false, false, &make_law<LinearLaw>},
    {"kelvin_voigt", true, false, false, true, true, &make_law<KelvinVoigtLaw>},
    {"modified_kelvin_voigt", true, false, false, true, true, &make_law<ModifiedKelvinVoigtLaw>},
    {"ye", true, false, false, true, false, &make_law<YeLaw>},
    {"mahmoud_jankowski", true, false, false, true, true, &make_law<MahmoudJankowskiLaw>},
    {"pant_wijeyewickrema", true, false, false, true, false, &make_law<PantWijeyewickremaLaw>},
    {"hertz", false, true, true, false, false, &make_law<HertzLaw>},
    {"jankowski", false, true, false, true, true, &make_law<JankowskiLaw>},
    {"hertz_damp_muthukumar", false, true, true, true, false, &make_law<HertzDampMuthukumarLaw>},
    {"hertz_damp_ye", false, true, true, true, false, &make_law<HertzDampYeLaw>},
}};

constexpr std::array<std::string_view, 10> kLawNames{
    kLaws[0].name, kLaws[1].name, kLaws[2].name, kLaws[3].name, kLaws[4].name,
    kLaws[5].name, kLaws[6].name, kLaws[7].name, kLaws[8].name, kLaws[9].name};

void validate(const LawEntry& law, const ImpactLawConfig& c) {
  const std::string_view name = law.name;
  if (law.uses_k && !(c.k > 0.0 && std::isfinite(c.k))) reject(name, "k", c.k, "must be > 0 (N/m)");
  if (law.uses_k_h && !(c.k_h > 0.0 && std::isfinite(c.k_h)))
    reject(name, "k_h", c.k_h, "must be > 0 (N/m^n)");
  if (law.uses_n && !(c.n > 0.0 && std::isfinite(c.n))) reject(name, "n", c.n, "must be > 0");
  if (law.uses_e && c.material == ImpactMaterial::kNone && !(c.e > 0.0 && c.e <= 1.0))
    reject(name, "e", c.e, "must be in (0, 1]");
  if (law.uses_mass) {
    if (!(c.mass_1 > 0.0 && std::isfinite(c.mass_1)))
      reject(name, "mass_1", c.mass_1, "must be > 0 and finite (kg; the law needs m_eff)");
    if (!(c.mass_2 > 0.0))
      reject(name, "mass_2", c.mass_2, "must be > 0 (kg; +inf for an immovable wall)");
  }
  if (name == "mahmoud_jankowski" && c.xi_formula != "eq_3_12" && c.xi_formula != "eq_3_11")
    throw std::invalid_argument("impact law 'mahmoud_jankowski': xi_formula = '" + c.xi_formula +
                                "' is unknown (expected eq_3_12 or eq_3_11)");
  if (!(c.min_impact_velocity > 0.0 && std::isfinite(c.min_impact_velocity)))
    reject(name, "min_impact_velocity", c.min_impact_velocity, "must be > 0 (m/s)");
  if (c.material != ImpactMaterial::kNone) (void)impact_material_name(c.material);  // throws
}

}  // namespace

ImpactLawUses impact_law_uses(std::string_view name) {
  for (const LawEntry& law : kLaws) {
    if (law.name != name) continue;
    ImpactLawUses uses;
    uses.k = law.uses_k;
    uses.k_h = law.uses_k_h;
    uses.n = law.uses_n;
    uses.e = law.uses_e;
    uses.mass = law.uses_mass;
    uses.min_impact_velocity = name == "ye" || name == "pant_wijeyewickrema" ||
                               name == "hertz_damp_muthukumar" || name == "hertz_damp_ye";
    uses.xi_formula = name == "mahmoud_jankowski";
    return uses;
  }
  throw std::invalid_argument("unknown impact law '" + std::string(name) + "'");
}

double ImpactLaw::stored_energy(double delta, const ImpactPhase& phase) const {
  const ImpactResponse elastic = respond(std::max(delta, 0.0), 0.0, phase);
  const double denominator = elastic.force + delta * elastic.stiffness;
  if (elastic.force > 0 && denominator > 0)
    return elastic.force * elastic.force * delta / denominator;
  return 0.0;
}

double ImpactLaw::stage_penetration() const {
  return std::numeric_limits<double>::infinity();
}

std::unique_ptr<ImpactLaw> make_impact_law(const ImpactLawConfig& config) {
  for (const LawEntry& law : kLaws) {
    if (law.name != config.law) continue;
    validate(law, config);
    return law.make(config);
  }
  std::string known;
  for (std::string_view n : kLawNames) known += (known.empty() ? "" : ", ") + std::string(n);
  throw std::invalid_argument("unknown impact law '" + config.law + "' (expected one of: " + known +
                              ")");
}

std::span<const std::string_view> impact_law_names() {
  return kLawNames;
}

// ---------------------------------------------------------------------------------------------
// Helpers
// ---------------------------------------------------------------------------------------------

double effective_mass(double m1, double m2) {
  if (!(m1 > 0.0) || !(m2 > 0.0))
    throw std::invalid_argument("effective_mass: masses must be > 0 (got " + format_value(m1) +
                                ", " + format_value(m2) + ")");
  if (std::isinf(m2)) return m1;
  if (std::isinf(m1)) return m2;
  return m1 * m2 / (m1 + m2);
}

double kelvin_voigt_xi(double e) {
  require_restitution("kelvin_voigt_xi", e);
  const double l = std::log(e);
  return (0.0 - l) / std::sqrt(kPi * kPi + l * l);  // 0.0 - l: +0 (not -0) for e = 1
}

double mahmoud_jankowski_xi(double e, std::string_view formula) {
  require_restitution("mahmoud_jankowski_xi", e);
  if (formula == "eq_3_12") return (1.0 - e * e) / (e * (e * (kPi - 2.0) + 2.0));
  if (formula == "eq_3_11") return (1.0 - e * e) / (kPi * e);
  throw std::invalid_argument("mahmoud_jankowski_xi: formula '" + std::string(formula) +
                              "' is unknown (expected eq_3_12 or eq_3_11)");
}

double jankowski_xi(double e) {
  require_restitution("jankowski_xi", e);
  return 4.5 * std::sqrt(5.0) * (1.0 - e * e) / (e * (e * (9.0 * kPi - 16.0) + 16.0));
}

double restitution_of_material(ImpactMaterial m, double impact_velocity) {
  struct Cubic {
    double a, b, c, d;
  };
  Cubic q{};
  switch (m) {
    case ImpactMaterial::kCeramic:
      q = {-0.0040, 0.0474, -0.2116, 0.8141};
      break;
    case ImpactMaterial::kConcrete:
      q = {-0.0070, 0.0696, -0.2529, 0.7929};
      break;
    case ImpactMaterial::kSteel:
      q = {-0.0039, 0.0440, -0.1867, 0.7299};
      break;
    case ImpactMaterial::kTimber:
      q = {-0.0043, 0.0479, -0.1971, 0.7067};
      break;
    default:
      throw std::invalid_argument("restitution_of_material: no material given (kNone)");
  }
  if (!(impact_velocity >= 0.0))
    throw std::invalid_argument("restitution_of_material: impact velocity " +
                                format_value(impact_velocity) + " must be >= 0 (m/s)");
  const double v = impact_velocity;
  const double e = ((q.a * v + q.b) * v + q.c) * v + q.d;
  return std::clamp(e, kMinMaterialRestitution, 1.0);
}

double restitution_of_pair(double e1, double E1, double e2, double E2) {
  require_restitution("restitution_of_pair", e1);
  require_restitution("restitution_of_pair", e2);
  if (!(E1 > 0.0 && std::isfinite(E1)) || !(E2 > 0.0 && std::isfinite(E2)))
    throw std::invalid_argument("restitution_of_pair: moduli must be > 0 and finite");
  return (e1 * E1 + e2 * E2) / (E1 + E2);
}

double hertz_stiffness_spheres(double R1, double E1, double nu1, double R2, double E2, double nu2) {
  if (!(R1 > 0.0) || !(R2 > 0.0) || (std::isinf(R1) && std::isinf(R2)))
    throw std::invalid_argument("hertz_stiffness_spheres: radii must be > 0, at most one +inf");
  if (!(E1 > 0.0) || !(E2 > 0.0) || (std::isinf(E1) && std::isinf(E2)))
    throw std::invalid_argument("hertz_stiffness_spheres: moduli must be > 0, at most one +inf");
  if (!(nu1 > -1.0 && nu1 <= 0.5) || !(nu2 > -1.0 && nu2 <= 0.5))
    throw std::invalid_argument("hertz_stiffness_spheres: Poisson ratios must be in (-1, 0.5]");
  const double lambda1 = (1.0 - nu1 * nu1) / (kPi * E1);  // 0 for a rigid body (E = inf)
  const double lambda2 = (1.0 - nu2 * nu2) / (kPi * E2);
  const double radius = std::isinf(R2) ? R1 : std::isinf(R1) ? R2 : R1 * R2 / (R1 + R2);
  return 4.0 / (3.0 * kPi) / (lambda1 + lambda2) * std::sqrt(radius);
}

double equivalent_radius(double mass, double density) {
  if (!(mass > 0.0) || !(density > 0.0))
    throw std::invalid_argument("equivalent_radius: mass and density must be > 0");
  return std::cbrt(3.0 * mass / (4.0 * kPi * density));
}

double axial_stiffness(double E, double A, double L) {
  if (!(E > 0.0) || !(A > 0.0) || !(L > 0.0))
    throw std::invalid_argument("axial_stiffness: E, A and L must be > 0");
  return E * A / L;
}

ImpactMaterial impact_material_from_name(std::string_view name) {
  if (name == "none") return ImpactMaterial::kNone;
  if (name == "concrete") return ImpactMaterial::kConcrete;
  if (name == "steel") return ImpactMaterial::kSteel;
  if (name == "timber") return ImpactMaterial::kTimber;
  if (name == "ceramic") return ImpactMaterial::kCeramic;
  throw std::invalid_argument("unknown impact material '" + std::string(name) +
                              "' (expected none, concrete, steel, timber or ceramic)");
}

std::string_view impact_material_name(ImpactMaterial m) {
  switch (m) {
    case ImpactMaterial::kNone:
      return "none";
    case ImpactMaterial::kConcrete:
      return "concrete";
    case ImpactMaterial::kSteel:
      return "steel";
    case ImpactMaterial::kTimber:
      return "timber";
    case ImpactMaterial::kCeramic:
      return "ceramic";
  }
  throw std::invalid_argument("impact_material_name: invalid ImpactMaterial value");
}

}  // namespace isopound
