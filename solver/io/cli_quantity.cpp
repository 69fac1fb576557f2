// Command-line quantities (see cli_quantity.h): units.h parses, plausibility.h judges.
#include "solver/io/cli_quantity.h"

#include "solver/io/plausibility.h"

namespace isopound {
namespace {

// check_plausible() ends a warning with this remark, true of the model files' programs only.
constexpr std::string_view kStrictRemark = " (--strict makes this an error)";

}  // namespace

CliQuantity parse_cli_quantity(std::string_view text, const CliQuantityRule& rule) {
  const Quantity q = parse_quantity(text);
  CliQuantity out;
  out.si = parse_quantity_as(text, rule.dimension);
  if (rule.positive && !(out.si > 0.0))
    throw UnitError("must be > 0 (got '" + std::string(text) + "')");
  if (!rule.key_path.empty()) {
    PlausibilityVerdict verdict =
        check_plausible(rule.key_path, rule.dimension, out.si, text, q.has_unit);
    if (verdict.level == Plausibility::kError) throw UnitError(verdict.message);
    if (verdict.level == Plausibility::kWarning) {
      if (verdict.message.ends_with(kStrictRemark))
        verdict.message.resize(verdict.message.size() - kStrictRemark.size());
      out.warning = std::move(verdict.message);
    }
  }
  return out;
}

}  // namespace isopound
