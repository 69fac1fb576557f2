// The keys of a 2D isolator and of a 3D bearing after its `model`, read one way for both: the
// friction pendulum's (friction_pendulum_input.h), or the yield point Tb, QW, uy,
// strength_is_yield_force (THEORY eq. 2.4) and the law's shape from the hysteresis table.
#pragma once

#include <vector>

#include "solver/io/friction_pendulum_input.h"
#include "solver/io/hysteresis_input.h"

namespace isopound {

// Every key of an isolator or bearing map (both take the same).
inline std::vector<std::string_view> isolator_keys() {
  return with_hysteresis_keys({"model", "Tb", "QW", "uy", "strength_is_yield_force", "carried_mass",
                               "R", "mu_slow", "mu_fast", "rate_parameter", "friction_hysteresis"});
}

// Config: IsolatorConfig or BearingConfig (the same field names). `law`: the table law of the
// chosen model, kElastic for the linear model (K_post only: no strength, no yield).
// after_period(): the member's own keys read after Tb (or the pendulum's keys), where its list of
// defaults used has always had them.
template <class Config, class AfterPeriod>
void read_isolator_keys(const InputNode& node, bool pendulum, HysteresisModel law, Config& c,
                        AfterPeriod after_period) {
  HysteresisLawConfig shape;
  shape.bouc_wen = c.bouc_wen;
  if (pendulum) {  // no Tb, QW: the pendulum's period is R's
    read_friction_pendulum(node, c);
    after_period();
    shape.model = c.smooth_friction ? HysteresisModel::kBoucWen : HysteresisModel::kElastic;
  } else {
    node.read_quantity("Tb", dim::kTime, Bound::kPositive, c.period);
    after_period();
    if (law == HysteresisModel::kElastic) return;
    if (const auto qw = node.find("QW")) {
      c.strength_ratio = qw->number(Bound::kNonNegative);
      if (c.strength_ratio == 0.0)
        qw->fail(
            "must be > 0 for the bilinear and bouc_wen models (without strength: model: linear)");
      // Q/W > 1 (a bare 5 is 500 %) is refused by the plausibility table (plausibility.h).
    } else {
      node.note_default("QW", "0.05");
    }
    node.read_quantity("uy", dim::kLength, Bound::kPositive, c.yield_displacement);
    node.read_boolean("strength_is_yield_force", c.strength_is_yield_force);
    shape.model = law;
  }
  read_hysteresis_shape(node, shape);
  c.bouc_wen = shape.bouc_wen;
}

}  // namespace isopound
