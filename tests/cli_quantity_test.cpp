// Command-line quantities (solver/io/cli_quantity.h): the model files' units and plausibility rows
// on the command line. "--damping 5" is 500 %, impossible for a damping ratio, and refused with
// the table's hint; "--until 5000" is possible but implausible, a warning with its hint.
#include <gtest/gtest.h>

#include <string>

#include "solver/io/cli_quantity.h"

namespace isopound {
namespace {

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

std::string error_of(const std::string& text, const CliQuantityRule& rule) {
  try {
    parse_cli_quantity(text, rule);
  } catch (const UnitError& e) {
    return e.what();
  }
  ADD_FAILURE() << "accepted '" << text << "'";
  return "";
}

constexpr CliQuantityRule kDamping{dim::kNone, "damping.ratio"};
constexpr CliQuantityRule kUntil{dim::kTime, "analysis.t_end", true};

TEST(CliQuantity, UnitsAsInTheModelFilesABareNumberIsSi) {
  for (const char* text : {"5 %", "5%", "0.05", " 5  % "}) {
    const CliQuantity q = parse_cli_quantity(text, kDamping);
    EXPECT_DOUBLE_EQ(q.si, 0.05) << text;
    EXPECT_TRUE(q.warning.empty()) << text << ": " << q.warning;
  }
  for (const char* text : {"0.5", "0.5 s", "500 ms"})
    EXPECT_DOUBLE_EQ(parse_cli_quantity(text, kUntil).si, 0.5) << text;
  EXPECT_TRUE(contains(error_of("5 m", kDamping), "expected dimensionless"));
  EXPECT_TRUE(contains(error_of("5 m", kUntil), "expected a time"));
  EXPECT_TRUE(contains(error_of("five", kUntil), "not a quantity"));
}

TEST(CliQuantity, BareNumbersGetThePlausibilityRuleOfTheirModelKey) {
  // Impossible (a damping ratio of 500 %): refused with the hint.
  const std::string five = error_of("5", kDamping);
  EXPECT_TRUE(contains(five, "500 %")) << five;
  EXPECT_TRUE(contains(five, "did you mean '5 %'?")) << five;
  EXPECT_TRUE(contains(error_of("-1 %", kDamping), "impossible")) << error_of("-1 %", kDamping);
  // Possible but implausible: a warning with the hint, without the model files' --strict remark.
  const CliQuantity fifty = parse_cli_quantity("0.5", kDamping);
  EXPECT_DOUBLE_EQ(fifty.si, 0.5);
  EXPECT_TRUE(contains(fifty.warning, "implausible for a damping ratio")) << fifty.warning;
  EXPECT_FALSE(contains(fifty.warning, "--strict")) << fifty.warning;
  const CliQuantity long_run = parse_cli_quantity("5000", kUntil);
  EXPECT_TRUE(contains(long_run.warning, "did you mean '5000 ms'?")) << long_run.warning;
  EXPECT_TRUE(contains(error_of("200000", kUntil), "impossible"));
  // The pushover's target drift: "2" is 200 %, refused with its hint; 50 % is warned.
  constexpr CliQuantityRule kTargetDrift{dim::kNone, "pushover.target_drift_ratio", true};
  EXPECT_DOUBLE_EQ(parse_cli_quantity("2 %", kTargetDrift).si, 0.02);
  EXPECT_TRUE(parse_cli_quantity("2 %", kTargetDrift).warning.empty());
  const std::string two = error_of("2", kTargetDrift);
  EXPECT_TRUE(contains(two, "did you mean '2 %'?")) << two;
  EXPECT_TRUE(contains(parse_cli_quantity("0.5", kTargetDrift).warning, "implausible"));
  // > 0 where the option needs it; no row: no plausibility check.
  EXPECT_TRUE(contains(error_of("0 s", kUntil), "must be > 0"));
  const CliQuantity free = parse_cli_quantity("5", CliQuantityRule{dim::kNone});
  EXPECT_DOUBLE_EQ(free.si, 5.0);
  EXPECT_TRUE(free.warning.empty());
}

}  // namespace
}  // namespace isopound
