// The table of hysteresis laws of yielding members (2D storeys, 3D columns, 2D isolators, 3D
// bearings): each law's shape in one config, one validation, one factory of its uniaxial and
// biaxial forms. The member gives the yield point (K_el, F_y, u_y, alpha) in its own numbers:
//   bilinear (kinematic hardening): F = alpha K_el d + F_h, |F_h| <= (1 - alpha) F_y;
//   bouc_wen: F = alpha K_el d + (1 - alpha) F_y z, u_y dz = A dd - (beta + gamma sgn(dd z))
//             |z|^n dd (THEORY eq. 2.1-2.2; biaxial: eq. 5.27-5.29, circular interaction);
//   peak_oriented: Ibarra-Medina-Krawinkler (peak_oriented.h), uniaxial only.
#pragma once

#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>

#include "solver/materials/biaxial_material.h"
#include "solver/materials/bouc_wen.h"
#include "solver/materials/hysteresis.h"

namespace isopound {

// kElastic: no law (a storey or column stays a linear spring in the stiffness matrix).
enum class HysteresisModel { kElastic, kBilinear, kBoucWen, kPeakOriented };

// Bouc-Wen shape, one rule for every member: n >= 1 (the biaxial law's z |z|^(n-2) needs it; n = 1
// is the smoothest, a large n approaches the bilinear), A > 0, beta + gamma > 0.
struct BoucWenShape {
  double n = 2.0;
  double A = 1.0;
  double beta = 0.5;
  double gamma = 0.5;
};

// The peak-oriented backbone beyond the yield point: capping drift = capping_drift_ratio x the
// member's length (beyond d_y), post-capping slope -post_capping_ratio K_el, residual plateau
// residual_strength_ratio F_y, cyclic deterioration lambda (E_t = lambda F_y d_y; 0: none).
struct PeakOrientedShape {
  double capping_drift_ratio = 0.0;      // > 0 (beyond d_y: checked with the yield point)
  double post_capping_ratio = 0.0;       // > 0
  double residual_strength_ratio = 0.0;  // in [0, 1]
  double deterioration = 0.0;            // >= 0
};

struct HysteresisLawConfig {
  HysteresisModel model = HysteresisModel::kElastic;
  BoucWenShape bouc_wen;            // model kBoucWen
  PeakOrientedShape peak_oriented;  // model kPeakOriented
};

// The member's yield point, SI.
struct YieldPoint {
  double elastic_stiffness = 0.0;   // K_el, N/m
  double yield_force = 0.0;         // F_y, N
  double yield_displacement = 0.0;  // u_y (d_y), m
  double post_yield_ratio = 0.0;    // alpha = post-yield / elastic stiffness, in [0, 1)
  double length = 0.0;              // m: drift ratios (the capping drift) are fractions of it
};

// The model names as the `model` key spells them, in HysteresisModel order.
std::span<const std::string_view> hysteresis_model_names();
std::string_view hysteresis_model_name(HysteresisModel model);

// One shape parameter: its key in a model file, whether it must be given (no default), where
// the config holds it, and how "Defaults used" names its default (empty: the number).
struct HysteresisShapeKey {
  std::string_view key;
  bool required;
  double& (*field)(HysteresisLawConfig& config);
  std::string_view default_name = {};
};
// The shape keys of a model (none for elastic and bilinear), and those of every model.
std::span<const HysteresisShapeKey> hysteresis_shape_keys(HysteresisModel model);
std::span<const HysteresisShapeKey> all_hysteresis_shape_keys();

// The first invalid parameter, by the key that sets it, and why ("must be >= 1 (got 0.5)");
// other_key: a key the same rule reads (beta beside gamma), or empty.
struct HysteresisProblem {
  std::string_view key;
  std::string_view other_key;
  std::string what;
};
std::optional<HysteresisProblem> hysteresis_law_problem(const HysteresisLawConfig& config);
// alpha of a member that gives it as a number (storeys, columns): in [0, 1).
std::optional<HysteresisProblem> post_yield_ratio_problem(double alpha);

// The Bouc-Wen law of a yield point with a shape (the uniaxial and coupled forms share it).
BoucWenParameters bouc_wen_parameters(const BoucWenShape& shape, const YieldPoint& yield);

// kCircular: one law of the deformation vector (biaxial bilinear, coupled Bouc-Wen); kSquare: two
// independent uniaxial laws (the hysteretic force reaches the square's corner).
enum class BiaxialInteraction { kCircular, kSquare };

// The law at a yield point. Throws std::invalid_argument for an elastic model, an invalid law
// (hysteresis_law_problem) or yield point, and for a circular peak_oriented (no biaxial form).
std::unique_ptr<UniaxialMaterial> make_uniaxial_hysteresis(const HysteresisLawConfig& config,
                                                           const YieldPoint& yield);
std::unique_ptr<BiaxialMaterial> make_biaxial_hysteresis(
    const HysteresisLawConfig& config, const YieldPoint& yield,
    BiaxialInteraction interaction = BiaxialInteraction::kCircular);

}  // namespace isopound
