// The command-line contract shared by isopound, isopound-pre and isopound-post: usage errors exit
// 2, option ranges are printed as people write them ("must be >= 0", never the 309 digits of
// DBL_MAX), and options that take a quantity accept units ("--until '5 s'", "--angle '30 deg'").
#pragma once

#include <CLI/CLI.hpp>
#include <cstdio>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "solver/io/cli_quantity.h"
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

// Warnings of quantity options with a possible but implausible value ("--until: '5000' is
// implausible ..."), collected while CLI11 parses; the program prints them after parsing.
using CliWarnings = std::vector<std::string>;

namespace cli_detail {
// A transform that rewrites an option's text to read(text), an SI value ("%.17g": CLI11 converts
// it back exactly); a UnitError is the usage error, which CLI11 prefixes with the option's name.
inline CLI::Validator si_rewrite(std::function<double(const std::string&)> read, std::string type) {
  return CLI::Validator(
      [read](std::string& text) -> std::string {
        double si = 0.0;
        try {
          si = read(text);
        } catch (const UnitError& e) {
          return e.what();
        }
        char buffer[40];
        std::snprintf(buffer, sizeof buffer, "%.17g", si);
        text = buffer;
        return {};
      },
      std::move(type));
}
}  // namespace cli_detail

// Makes `option` a quantity option: "5 s", "5000 ms" or a bare number (SI), read and judged by
// parse_cli_quantity() (the model files' units and plausibility rows) and rewritten to its SI
// value before CLI11 converts it. An error names the option and exits 2 like every usage error;
// a warning goes to `warnings` (dropped when null). Returns `option`.
inline CLI::Option* quantity_option(CLI::Option* option, const CliQuantityRule& rule,
                                    CliWarnings* warnings = nullptr) {
  const std::string name = option->get_name();
  option->transform(cli_detail::si_rewrite(
      [rule, warnings, name](const std::string& text) {
        const CliQuantity q = parse_cli_quantity(text, rule);
        if (warnings && !q.warning.empty()) warnings->push_back(name + ": " + q.warning);
        return q.si;
      },
      "QUANTITY"));
  return option;
}

// Makes `option` an angle option: "30 deg", "0.5 rad", rewritten to rad; a bare number is refused
// as in the model files (parse_angle). Returns `option`.
inline CLI::Option* angle_option(CLI::Option* option) {
  option->transform(
      cli_detail::si_rewrite([](const std::string& text) { return parse_angle(text); }, "ANGLE"));
  return option;
}

}  // namespace isopound
