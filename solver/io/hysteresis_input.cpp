// Reading a hysteresis law's keys into the table's config (interface: hysteresis_input.h).
#include "solver/io/hysteresis_input.h"

namespace isopound {
namespace {

// The problem at the key it names; at the other key of its rule when only that one is written
// (beta: -0.5 with the default gamma); at the map's position when neither is.
[[noreturn]] void fail_at(const InputNode& node, const HysteresisProblem& p) {
  if (const auto n = node.find(p.key)) n->fail(p.what);
  if (!p.other_key.empty())
    if (const auto n = node.find(p.other_key)) n->fail(p.what);
  node.fail_at_key(p.key, p.what);
}

}  // namespace

std::vector<std::string_view> with_hysteresis_keys(std::initializer_list<std::string_view> own) {
  std::vector<std::string_view> keys(own);
  for (const HysteresisShapeKey& k : all_hysteresis_shape_keys()) keys.push_back(k.key);
  return keys;
}

HysteresisModel read_hysteresis_model(const InputNode& node,
                                      std::initializer_list<HysteresisModel> offered) {
  std::vector<std::string_view> names;
  for (const HysteresisModel m : offered) names.push_back(hysteresis_model_name(m));
  return offered.begin()[node.required("model").choice_index(names)];
}

void read_hysteresis_shape(const InputNode& node, HysteresisLawConfig& law) {
  for (const HysteresisShapeKey& k : hysteresis_shape_keys(law.model)) {
    double& value = k.field(law);
    if (k.required)
      value = node.required(k.key).number();
    else if (const auto given = node.find(k.key))
      value = given->number();
    else if (!k.default_name.empty())
      node.note_default(k.key, std::string(k.default_name));
    else
      node.read_number(k.key, Bound::kAny, value);
  }
  if (const auto problem = hysteresis_law_problem(law)) fail_at(node, *problem);
}

double read_post_yield_ratio(const InputNode& node) {
  double alpha = 0.0;
  node.read_number("post_yield_ratio", Bound::kAny, alpha);
  if (const auto problem = post_yield_ratio_problem(alpha)) fail_at(node, *problem);
  return alpha;
}

}  // namespace isopound
