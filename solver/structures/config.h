// Plain configuration structs of an analysis, filled from YAML in one place (model_input.cpp).
// All values SI (m, kg, s, N); ratios as fractions (5 % -> 0.05).
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "solver/core/analysis_config.h"
#include "solver/elements/polygon_contact.h"
#include "solver/excitation/ground_motion.h"
#include "solver/materials/bumper_law.h"
#include "solver/materials/hysteresis_law.h"
#include "solver/materials/impact_law.h"

namespace isopound {

// Isolation system of a 2D building (the whole isolation layer as one element).
struct IsolatorConfig {
  // kFrictionPendulum: single concave surface, F = W u/R + mu(v) W z (THEORY-notes.md); it
  // ignores Tb, QW and the Bouc-Wen shape unless friction_hysteresis is smooth.
  enum class Model { kLinear, kBilinear, kBoucWen, kFrictionPendulum };
  Model model = Model::kBoucWen;
  double period = 2.0;               // T_b, s: K_post = m (2 pi / T_b)^2
  double strength_ratio = 0.05;      // Q/W: Q = (Q/W) m g
  double yield_displacement = 0.01;  // u_y, m
  // Bouc-Wen shape (THEORY eq. 2.1-2.2; hysteresis_law.h), also of the pendulum's smooth z.
  BoucWenShape bouc_wen;
  // false: Q is the characteristic strength, F_y = Q + K_post u_y (default, THEORY section 2);
  // true: the given strength (Q/W) m g is the yield force F_y itself.
  bool strength_is_yield_force = false;
  // Mass carried by the isolators, kg; 0 means the total mass of the building incl. base slab.
  double carried_mass = 0.0;
  // Friction pendulum: radius R (m) of the concave surface, mu(v) = mu_fast - (mu_fast -
  // mu_slow) exp(-rate_parameter |v|); yield_displacement is then the pre-sliding travel u_y.
  double radius = 0.0;
  double mu_slow = 0.0;
  double mu_fast = 0.0;
  double rate_parameter = 0.0;   // a, s/m
  bool smooth_friction = false;  // z: false = radial return (sharp), true = Bouc-Wen (bouc_wen)
};

// The restoring-force law of a storey (`hysteresis:` of a floor): elastic (the linear spring
// in K, as the thesis) or a law of the hysteresis table (solver/materials/hysteresis_law.h) of the
// drift, at the storey's own yield point (solver/structures/story_hysteresis.h). k is always the
// storey's elastic stiffness; Rayleigh damping stays from the elastic K.
struct StoryHysteresisConfig {
  HysteresisLawConfig law;  // model kElastic: the linear spring
  // The yield point, one of: d_y = ratio x storey height; V_y (N), d_y = V_y / k; or V_y as a
  // fraction of the weight above the storey (g x the masses above), d_y = V_y / k.
  enum class YieldBy { kDriftRatio, kShear, kShearCoefficient };
  YieldBy yield_by = YieldBy::kDriftRatio;
  double yield_value = 0.0;
  double post_yield_ratio = 0.0;  // alpha: hardening stiffness / k, in [0, 1)
  bool yields() const { return law.model != HysteresisModel::kElastic; }
};

struct FloorConfig {
  double mass = 0.0;                   // kg, lumped at the floor
  double stiffness = 0.0;              // N/m, of the story below this floor
  double height = 0.0;                 // m, of the story below this floor
  StoryHysteresisConfig hysteresis{};  // of the story below this floor ({} for {m, k, h})
};

struct SuperstructureDamping {
  enum class Type { kRayleigh, kModal, kNone };
  Type type = Type::kRayleigh;
  double ratio = 0.02;  // xi_s, at both Rayleigh modes or at every mode (modal)
  int mode_a = 1;       // Rayleigh: the two fixed-base modes (1-based) that get `ratio`
  int mode_b = 2;
};

// Moat walls beside one level (usually the base slab). Sign convention: "right" is +x, so a
// right wall is hit when the level moves by +gap, a left wall by -gap.
struct WallConfig {
  bool left = true, right = true;  // sides: both (default) | left | right
  double gap_left = 0.2;           // m, clear distance at rest (>= 0)
  double gap_right = 0.2;          // m
  // Level index that pounds, in elevation order (floors 1..k, the isolated slab, floors
  // k+1..n; 0 = base slab of a building isolated on the ground).
  int level = 0;
  ImpactLawConfig impact;  // law, k, e, ...; mass_2 is the wall mass below, mass_1 the level's
  double mass = 500e3;     // kg, wall mass (thesis 500 t)
  // Flexible wall: a single-DOF structure (mass, stiffness, damping ratio) excited by the same
  // ground motion. stiffness = 0: rigid, immovable; its mass enters only the impact damping.
  double stiffness = 0.0;      // N/m
  double damping_ratio = 0.0;  // of the wall's own oscillator
  // Rubber bumper on the wall's face (thickness 0: none). The level then meets the bumper at
  // gap - thickness; the wall's impact law acts once the rubber bottoms out (bumper_law.h).
  BumperConfig bumper;
};

// The facing column line of a 2D building (`columns:`), struck between its floors by another
// structure's slab (solver/elements/struck_column.h, docs/floor-to-column.md): `count` equal
// columns, each an Euler-Bernoulli beam fixed in rotation by the slabs, with plastic hinges of
// moment M_y at both ends and at the struck point. Their share count x 12 E I / L^3 of a struck
// storey's stiffness moves from the storey spring into the column element.
struct StruckColumnsConfig {
  bool given = false;  // false: a slab between this building's floors is refused
  int count = 1;
  double E = 0.0, I = 0.0;        // Pa, m^4
  double yield_moment = 0.0;      // M_y, N m (> 0)
  double hardening_ratio = 0.01;  // hinge hardening H = ratio x 6 E I / L
  bool shear_check = false;       // report |V| against V_n
  double shear_capacity = 0.0;    // V_n, N (shear_check only)
};

// A 2D shear building: optional base slab on isolators, floors bottom to top. The isolators
// stand on the ground (isolation_level 0) or on floor k = isolation_level of a fixed-base
// substructure (floors 1..k); floors k+1..n are the isolated superstructure, floor k+1's
// height measured from the isolated slab (docs/isolation-level.md).
struct BuildingConfig {
  std::string name = "building";
  bool isolated = true;    // false: fixed base (no base slab DOF)
  double base_mass = 0.0;  // kg, base slab (isolated only)
  std::vector<FloorConfig> floors;
  int isolation_level = 0;        // k: the isolators stand on floor k (0: the ground)
  double isolation_height = 0.0;  // m, the isolated slab above floor k (k > 0 only)
  IsolatorConfig isolator;
  SuperstructureDamping damping;
  // Of the fixed-base substructure (floors 1..k, relative to the ground); by default modal with
  // the superstructure's ratio. Unused for k = 0.
  SuperstructureDamping substructure_damping{SuperstructureDamping::Type::kModal, 0.02, 1, 2};
  double isolation_damping_ratio = 0.05;  // xi_b: c_b = 2 xi_b m_isolated omega_b
  std::vector<WallConfig> walls;          // moat walls (usually one entry, both sides)
  // P-Delta: each storey gets the geometric stiffness -P/h, P = g x the masses above it.
  bool p_delta = false;
  // An elastic storey whose peak drift ratio exceeds this is reported as outside the elastic
  // model's range (a console warning and a flag in summary.json).
  double elastic_limit_drift_ratio = 0.01;
  StruckColumnsConfig columns;  // its facing column line, when another slab may strike it
};

// A neighbouring building at a gap; floors at equal elevation pound slab to slab.
struct NeighbourConfig {
  BuildingConfig building;
  bool right = true;       // side of the main building it stands on (+x = right)
  double gap = 0.1;        // m, clear distance at rest
  ImpactLawConfig impact;  // masses are taken from the two colliding levels
  // Rubber on the neighbour's facing side at every pounding level pair (thickness 0: none): the
  // levels meet the rubber at gap - thickness, the concrete law acts once it bottoms out.
  BumperConfig bumper;
  bool pounding = true;  // false: no contact elements (the unobstructed comparison)
  // m, the neighbour's ground above the main building's (its levels are raised by this): a
  // level facing a storey of the other between its floors strikes its columns.
  double ground_level = 0.0;
};

struct GroundMotionConfig {
  bool use_pulse = true;    // no record given -> built-in pulse
  std::string record_path;  // resolved relative to the model file
  RecordReadOptions read;   // format, column, dt, unit, scale
  PulseParameters pulse;
  double extra_time = 0.0;  // s of free vibration computed after the record ends
  // A record pair (3D): components[0] = L, components[1] = T (their record or pulse fields; the
  // fields above then are unused) at incidence angle `angle` (rad, counter-clockwise from X to
  // L; THEORY eq. 5.12-5.13). Empty: one component along x (or, for a 3D model without any
  // record, the built-in pulse as L and pulse_transverse_ratio times it as T).
  std::vector<GroundMotionConfig> components;
  double angle = 0.0;
  double pulse_transverse_ratio = 0.5;
};

// config3d.h (its bearing law, bearing.h, may include this file: no include cycle here).
struct Building3DConfig;

// Special members are defined in config.cpp, where Building3DConfig is complete.
struct ModelConfig {
  ModelConfig();
  ~ModelConfig();
  ModelConfig(const ModelConfig&);
  ModelConfig(ModelConfig&&) noexcept;
  ModelConfig& operator=(const ModelConfig&);
  ModelConfig& operator=(ModelConfig&&) noexcept;

  std::string source;  // the YAML file it came from (for messages)
  BuildingConfig building;
  // 3D structures (`structures:` in the model file); when not empty, `building` and
  // `neighbours` are unused. Include solver/structures/config3d.h to use them.
  std::vector<Building3DConfig> structures3d;
  // 3D pounding (`contact:` in the model file): the law of every polygon contact pair, found
  // automatically between floors of different structures at equal elevation and between moat
  // walls and the base slab they surround (solver/structures/pounding3d.h).
  struct Contact3D {
    PolygonContactConfig law;
    // Option: a 2D impact law along the normal with δ_N as the penetration (its masses are set
    // per pair from the two bodies); false: the area law k_N A_c + c_N δ̇_N.
    bool use_impact_law = false;
    ImpactLawConfig impact_law;
    double elevation_tolerance = 0.01;  // m: two floors closer in elevation than this meet
    // m: pairs farther apart at rest than this cannot meet and get no contact element.
    double search_distance = 2.0;
    bool pounding = true;  // false: no contact elements (the unobstructed comparison)
  } contact3d;
  std::vector<NeighbourConfig> neighbours;
  GroundMotionConfig ground_motion;
  AnalysisConfig analysis;
  OutputConfig output;
  // Keys the file did not give and the values used for them ("building.walls[0].mass",
  // "500000 kg"): printed in the settings block and summary.json, so no default is silent.
  std::vector<std::pair<std::string, std::string>> defaults;
  // Legal but implausible values ("file:line:col: key: what", solver/io/plausibility.h):
  // printed in the run and in summary.json; --strict refuses them.
  std::vector<std::string> warnings;
};

}  // namespace isopound
