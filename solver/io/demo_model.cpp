// The built-in demo models (see demo_model.h).
#include "solver/io/demo_model.h"

namespace isopound {

const std::string& demo_model_3d_yaml() {
  static const std::string text =
      R"(# isopound demo: a base-isolated building pounding against its moat walls (written by
# `isopound demo`; run it again with `isopound run model.yaml`, configs/tutorial-3d.yaml explains
# every key).
structures:
  - name: building
    # 3 x 3 bays of 5.5 m: 16 columns of 45 x 45 cm that yield at 0.5 % drift (Bouc-Wen).
    grid: {bays_x: [5.5 m, 5.5 m, 5.5 m], bays_y: [5.5 m, 5.5 m, 5.5 m]}
    columns: {section: [45 cm, 45 cm], E: 30 GPa, nu: 0.2,
              hysteresis: {model: bouc_wen, yield_drift_ratio: 0.5 %, post_yield_ratio: 5 %,
                           n: 2, A: 1, beta: 0.5, gamma: 0.5}}
    storeys: {count: 3, height: 3.2 m, mass: 340 t, roof_mass: 250 t}
    base: {mass: 340 t}
    # One Bouc-Wen bearing under every column: isolation period 2 s, strength 5 % of the weight.
    bearing: {model: bouc_wen, Tb: 2.0 s, QW: 5 %, uy: 1 cm, n: 2, A: 1, beta: 0.5, gamma: 0.5}
    damping: {type: rayleigh, ratios: [5 %, 2 %], modes: [1, 4], bearing_stiffness: post_yield}
    # Moat walls 15 cm from the base slab on all four sides.
    walls: {sides: all, gap: 15 cm, thickness: 1 m, height: 1 m, extension: 1 m,
            mass_per_length: 5 t/m}
# Slab-to-wall contact: penalty stiffness per unit overlap area, friction, restitution.
contact: {k_normal: 2.58e10 N/m2, k_tangential: 5.74e9 N/m, mu_static: 0.8, mu_kinetic: 0.6,
          restitution: 0.65}
# The built-in near-fault pulse along L, half of it along T, L at 30 degrees from x.
ground_motion:
  L: {pulse: {amplitude: 1.0 m/s, period: 2 s}}
  T: {pulse: {amplitude: 0.5 m/s, period: 2 s}}
  angle: 30 deg
  extra_time: 0 s
# Steps and rows every 2 ms: dense enough to draw every impact. The floor response spectra come
# from every analysis step (floor_spectra: step-accelerations.csv), where a 3 ms wall impact
# falls between two rows: exact at every period (docs/floor-spectra.md).
analysis: {t_end: 8 s, dt: 2 ms}
output: {interval: 2 ms, floor_spectra: true}
)";
  return text;
}

ModelConfig demo_model_2d() {
  ModelConfig c;
  c.source = "(built-in demo)";
  c.building.name = "3-storey";
  c.building.base_mass = 340e3;
  c.building.floors = {{340e3, 600e6, 3.2}, {340e3, 600e6, 3.2}, {250e3, 600e6, 3.2}};
  c.ground_motion.use_pulse = true;
  return c;
}

}  // namespace isopound
