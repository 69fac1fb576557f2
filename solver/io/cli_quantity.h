// A quantity given on a command line, read as the model files read theirs: "--until '5 s'",
// "--damping 5%". Units by units.h (a bare number is SI); the value checked against the model
// files' plausibility table (plausibility.h) under the model key the option means, so a bare
// number easily meant in another unit gets the same verdict and hint ("--damping 5": a damping
// ratio of 500 %, "did you mean '5 %'?").
#pragma once

#include <string>
#include <string_view>

#include "solver/io/units.h"

namespace isopound {

struct CliQuantityRule {
  Dimension dimension;
  // The model key the option means ("damping.ratio" for --damping, "analysis.t_end" for
  // --until): its plausibility row applies. Empty: an option no model key means (no check).
  std::string_view key_path = {};
  bool positive = false;  // the value must be > 0
};

struct CliQuantity {
  double si = 0.0;
  // Possible but implausible (outside the row's plausible range): the message with its hint,
  // without the model files' "--strict" remark (not every program has --strict); else empty.
  std::string warning;
};

// Throws UnitError (not a quantity, wrong dimension, impossible for the key, not > 0) with a
// message that does not name the option: the caller (CLI11) prefixes it.
CliQuantity parse_cli_quantity(std::string_view text, const CliQuantityRule& rule);

}  // namespace isopound
