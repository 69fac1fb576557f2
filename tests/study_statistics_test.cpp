// Statistics of a study against hand computations: the summary of a sample, and the grouped
// tables (statistics over records, variant ratios) exported from a database filled by hand.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "solver/study/study_csv.h"
#include "solver/study/study_export.h"
#include "solver/study/study_statistics.h"
#include "solver/study/study_store.h"
#include "tests/study_test_support.h"

namespace isopound {
namespace {

namespace fs = std::filesystem;

TEST(StudyStatistics, SummaryMatchesHandComputation) {
  // 2 4 4 4 5 5 7 9: mean 40/8 = 5; squared deviations 9+1+1+1+0+0+4+16 = 32;
  // population std sqrt(32/8) = 2, sample std sqrt(32/7); median (4+5)/2.
  const std::vector<double> x{9, 4, 2, 4, 5, 7, 4, 5};
  const SummaryStatistics p = summarize(x, false);
  EXPECT_EQ(p.n, 8);
  EXPECT_DOUBLE_EQ(p.mean, 5.0);
  EXPECT_DOUBLE_EQ(p.std, 2.0);
  EXPECT_DOUBLE_EQ(p.min, 2.0);
  EXPECT_DOUBLE_EQ(p.max, 9.0);
  EXPECT_DOUBLE_EQ(p.median, 4.5);
  const SummaryStatistics s = summarize(x, true);
  EXPECT_DOUBLE_EQ(s.std, std::sqrt(32.0 / 7.0));

  // Odd count and a failed run (NaN) left out: 1, 3, 8 -> median 3, mean 4,
  // sample std sqrt((9 + 1 + 16) / 2) = sqrt(13).
  const SummaryStatistics odd = summarize({8, std::nan(""), 1, 3}, true);
  EXPECT_EQ(odd.n, 3);
  EXPECT_DOUBLE_EQ(odd.mean, 4.0);
  EXPECT_DOUBLE_EQ(odd.median, 3.0);
  EXPECT_DOUBLE_EQ(odd.std, std::sqrt(13.0));

  const SummaryStatistics one = summarize({2.5}, true);
  EXPECT_EQ(one.n, 1);
  EXPECT_TRUE(std::isnan(one.std));  // a sample of one has no spread
  EXPECT_EQ(summarize({}, true).n, 0);
}

TEST(StudyStatistics, NumbersAndFieldsHaveOneTextForm) {
  EXPECT_EQ(format_number(0.0105), "0.0105");
  EXPECT_EQ(format_number(0.1 + 0.2), "0.30000000000000004");
  EXPECT_EQ(format_number(2.5e9), "2.5e+09");  // the shorter of fixed and scientific
  EXPECT_EQ(format_number(-0.0), "0");
  EXPECT_EQ(format_number(std::nan("")), "");
  EXPECT_EQ(csv_field("a,b"), "\"a,b\"");
  EXPECT_EQ(csv_field("say \"hi\""), "\"say \"\"hi\"\"\"");
}

std::vector<std::vector<std::string>> parse_csv(const std::string& text) {
  std::vector<std::vector<std::string>> rows;
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line)) {
    std::vector<std::string> cells;
    std::string cell;
    std::istringstream fields(line);
    while (std::getline(fields, cell, ',')) cells.push_back(cell);
    if (!line.empty() && line.back() == ',') cells.emplace_back();
    rows.push_back(cells);
  }
  return rows;
}

// Database of 3 records x 2 u_y x 2 variants filled with known peaks; one run failed.
TEST(StudyStatistics, GroupedTablesMatchHandComputation) {
  const fs::path dir = test::study_scratch("statistics");
  StoreLayout layout;
  layout.axes = {"record", "uy", "variant"};
  layout.outputs = {"u_base"};
  layout.ratios = {{"BL_over_BW", "variant", "BL", "BW"}};
  layout.statistics = {{{"record"}, true}};
  const std::vector<std::string> records{"A", "B", "C"};
  const std::vector<double> uy{0.01, 0.02};
  const std::vector<std::string> variants{"BL", "BW"};
  // u_base[record][uy][variant]
  const double u[3][2][2] = {
      {{0.30, 0.20}, {0.40, 0.25}}, {{0.50, 0.40}, {0.60, 0.30}}, {{0.10, 0.05}, {0.20, 0.10}}};
  StudyStore store =
      StudyStore::create((dir / "hand.db").string(), layout, {}, 12, [&](std::int64_t c) {
        return std::vector<Cell>{
            {false, 0, records[c / 4]}, {true, uy[(c / 2) % 2], ""}, {false, 0, variants[c % 2]}};
      });
  std::vector<RunRecord> runs;
  for (std::int64_t c = 0; c < 12; ++c) {
    RunRecord r;
    r.case_id = c;
    r.ok = c != 11;  // C, uy 0.02, BW failed
    r.steps = 100;
    if (r.ok)
      r.values = {u[c / 4][(c / 2) % 2][c % 2]};
    else
      r.error = "diverged";
    runs.push_back(r);
  }
  store.commit(runs, store.begin_session(1, 1, false, 12));

  const ExportTables t = export_tables(store, ExportOptions{});
  const auto run_rows = parse_csv(t.runs);
  ASSERT_EQ(run_rows.size(), 13u);
  EXPECT_EQ(run_rows[0], (std::vector<std::string>{"case_id", "record", "uy", "variant", "status",
                                                   "steps", "u_base", "error"}));
  EXPECT_EQ(run_rows[12],
            (std::vector<std::string>{"11", "C", "0.02", "BW", "failed", "100", "", "diverged"}));

  // Ratios BL/BW, other axes equal: A 0.01 -> 0.30/0.20 = 1.5.
  const auto ratio_rows = parse_csv(t.ratios);
  ASSERT_EQ(ratio_rows.size(), 7u);
  EXPECT_EQ(ratio_rows[1][0], "A");
  EXPECT_EQ(ratio_rows[1][2], "BL_over_BW");
  EXPECT_DOUBLE_EQ(std::stod(ratio_rows[1][3]), 0.30 / 0.20);
  EXPECT_EQ(ratio_rows[6][3], "");  // C 0.02: its BW run failed

  // Statistics over records, grouped by (uy, variant); the ratio rows form their own groups.
  const auto stats = parse_csv(t.statistics);
  ASSERT_EQ(stats[0], (std::vector<std::string>{"record", "uy", "variant", "over", "output", "n",
                                                "mean", "std", "mean_minus_std", "mean_plus_std",
                                                "min", "max", "median"}));
  const auto find = [&](const std::string& uy_text, const std::string& variant) {
    for (const auto& row : stats)
      if (row[1] == uy_text && row[2] == variant) return row;
    return std::vector<std::string>{};
  };
  // uy 0.01, BL: 0.30, 0.50, 0.10 -> mean 0.3, sample std sqrt((0 + 0.04 + 0.04) / 2) = 0.2, median
  // 0.3.
  const auto bl = find("0.01", "BL");
  ASSERT_EQ(bl.size(), 13u);
  EXPECT_EQ(bl[0], "");
  EXPECT_EQ(bl[3], "record");
  EXPECT_EQ(bl[4], "u_base");
  EXPECT_EQ(bl[5], "3");
  EXPECT_NEAR(std::stod(bl[6]), 0.3, 1e-15);
  EXPECT_NEAR(std::stod(bl[7]), 0.2, 1e-15);
  EXPECT_NEAR(std::stod(bl[8]), 0.1, 1e-15);
  EXPECT_NEAR(std::stod(bl[9]), 0.5, 1e-15);
  EXPECT_DOUBLE_EQ(std::stod(bl[10]), 0.10);
  EXPECT_DOUBLE_EQ(std::stod(bl[11]), 0.50);
  EXPECT_DOUBLE_EQ(std::stod(bl[12]), 0.30);
  // uy 0.02, BW: 0.25, 0.30 and a failed run -> n 2, mean 0.275, std sqrt(2 * 0.025^2) , median
  // 0.275.
  const auto bw = find("0.02", "BW");
  ASSERT_EQ(bw.size(), 13u);
  EXPECT_EQ(bw[5], "2");
  EXPECT_NEAR(std::stod(bw[6]), 0.275, 1e-15);
  EXPECT_NEAR(std::stod(bw[7]), std::sqrt(2 * 0.025 * 0.025), 1e-15);
  EXPECT_NEAR(std::stod(bw[12]), 0.275, 1e-15);
  // Ratio rows, uy 0.01: 1.5, 1.25, 2 -> mean 4.75/3, median 1.5.
  const auto ratio = find("0.01", "BL_over_BW");
  ASSERT_EQ(ratio.size(), 13u);
  EXPECT_NEAR(std::stod(ratio[6]), 4.75 / 3, 1e-15);
  EXPECT_NEAR(std::stod(ratio[12]), 1.5, 1e-15);
  EXPECT_EQ(stats.size(), 1u + 6u);  // 4 run groups + 2 ratio groups, one peak each
  fs::remove_all(dir);
}

}  // namespace
}  // namespace isopound
