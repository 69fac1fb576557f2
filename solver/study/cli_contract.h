// The command-line contract shared by isopound, isopound-pre and isopound-post: usage errors exit
// 2, option ranges are printed as people write them ("must be >= 0", never the 309 digits of
// DBL_MAX), and options that take a quantity accept units ("--until '5 s'", "--angle '30 deg'").
#pragma once

#include <CLI/CLI.hpp>
#include <cstdio>
#include <string>

#include "solver/io/units.h"

namespace isopound {

// A number >= `min` (e.g. "-j 0": 0 means all cores). CLI11's own NonNegativeNumber prints its
// upper bound, DBL_MAX, in full.
inline CLI::Validator at_least(double min) {
  return CLI::Validator(
      [min](std::string& text) -> std::string {
        double value = 0.0;
        if (!CLI::detail::lexical_cast(text, value)) return "'" + text + "' is not a number";
        if (!(value >= min)) return "must be >= " + readable_number(min) + " (got " + text + ")";
        return {};
      },
      ">= " + readable_number(min));
}

// A quantity option: "5 s", "5000 ms" or a bare number (SI of `expected`), rewritten to its SI
// value before CLI11 converts it (use with ->transform); > 0 when `positive`. An error names the
// option and exits 2 like every usage error.
inline CLI::Validator quantity_of(const Dimension& expected, bool positive) {
  return CLI::Validator(
      [expected, positive](std::string& text) -> std::string {
        double value = 0.0;
        try {
          value = parse_quantity_as(text, expected);
        } catch (const UnitError& e) {
          return e.what();
        }
        if (positive && !(value > 0.0)) return "must be > 0 (got '" + text + "')";
        char si[40];
        std::snprintf(si, sizeof si, "%.17g", value);
        text = si;
        return {};
      },
      "QUANTITY");
}

}  // namespace isopound
