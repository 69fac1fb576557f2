// The keys of a hysteresis law (solver/materials/hysteresis_law.h), read one way wherever a
// member yields: 2D storeys, 3D columns, 2D isolators and 3D bearings (and the friction
// pendulum's smooth z). The member reads its own yield point; this reads the law's shape keys
// (defaults noted, an invalid value refused at its key) and alpha where the member takes it as a
// key. Every member accepts every shape key, so a key the chosen law does not use is refused the
// same way everywhere, by the one rule for keys (InputNode::refuse_unused).
#pragma once

#include <initializer_list>
#include <string_view>
#include <vector>

#include "solver/io/yaml_reader.h"
#include "solver/materials/hysteresis_law.h"

namespace isopound {

// The member's own keys and every law's shape keys: the member's expect_keys list.
std::vector<std::string_view> with_hysteresis_keys(std::initializer_list<std::string_view> own);

// The required `model` of a storey or a column: one of `offered`, by the table's names.
HysteresisModel read_hysteresis_model(const InputNode& node,
                                      std::initializer_list<HysteresisModel> offered);

// The shape keys of law.model into `law` (required ones required, the others' defaults noted),
// then the one validation (hysteresis_law_problem) at the key it names.
void read_hysteresis_shape(const InputNode& node, HysteresisLawConfig& law);

// alpha of a member that gives it as a key (storeys and columns): [0, 1), default 0 (noted).
double read_post_yield_ratio(const InputNode& node);

}  // namespace isopound
