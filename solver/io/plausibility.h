// The one table of plausible ranges of model quantities (docs/plausibility.md): a bare number
// easily meant in another unit (gap: 15 is 15 m, mass: 340 is 340 kg) is refused or warned.
// Rule: outside the hard range -> an error with a hint; inside it but outside the plausible
// range -> a warning (an error under --strict). Ranges are in SI, keyed by the last key of the
// path ("building.walls.gap" -> "gap") and the dimension read, so every file section that uses
// the key gets the same rule.
#pragma once

#include <span>
#include <string>
#include <string_view>

#include "solver/io/units.h"

namespace isopound {

struct PlausibleRange {
  std::string_view key;       // last key of the path ("gap", "mass", "mu_fast"); see key_of()
  Dimension dimension;        // the dimension the key is read with
  double hard_min, hard_max;  // SI; outside: an error
  double low, high;           // SI; outside (but inside the hard range): a warning
  std::string_view unit;      // the unit the messages use ("cm", "t")
  double unit_si;             // SI value of one `unit`
  std::string_view what;      // what the quantity is, for messages ("a moat-wall gap")
};

// The whole table, in documentation order.
std::span<const PlausibleRange> plausible_ranges();

// The last key of a key path, list indices dropped: "structures[0].storeys[2].mass" -> "mass",
// "damping.ratios[1]" -> "ratios".
std::string key_of(std::string_view key_path);

// The row for a key path read with dimension `d`, or null when the table has none.
const PlausibleRange* plausible_range_for(std::string_view key_path, const Dimension& d);

// Numeric keys deliberately without a row, with the reason (docs/plausibility.md): solver
// settings, shape parameters of a law, coordinates and sizes whose range depends on the site.
struct UncheckedKey {
  std::string_view key;
  std::string_view why;
};
std::span<const UncheckedKey> unchecked_keys();
bool is_unchecked_key(std::string_view key);

enum class Plausibility { kOk, kWarning, kError };
struct PlausibilityVerdict {
  Plausibility level = Plausibility::kOk;
  std::string message;  // the "what" of the error or warning, with a hint for bare numbers
};

// Checks `si` read from `text` (has_unit: the text gave a unit) for the key path.
PlausibilityVerdict check_plausible(std::string_view key_path, const Dimension& d, double si,
                                    std::string_view text, bool has_unit);

}  // namespace isopound
