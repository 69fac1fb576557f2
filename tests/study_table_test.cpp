// The study read API (solver/study/study_table.h): a tiny sweep's database read as a table gives
// the store's own axes, outputs, rows and values, and each output's selector quantity; a missing
// or foreign file fails clearly; and post/ reads studies through this table only (issue 23).
#include "solver/study/study_table.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <regex>
#include <string>
#include <vector>

#include "solver/study/study_store.h"
#include "tests/study_test_support.h"

namespace isopound {
namespace {

namespace fs = std::filesystem;

// Same bits, so that NaN (a NULL peak) equals NaN.
bool same_value(double a, double b) {
  return std::memcmp(&a, &b, sizeof a) == 0;
}

TEST(StudyTable, ReadsWhatTheStoreHolds) {
  const fs::path dir = test::study_scratch("table");
  test::write_file(dir / "study.yaml", "model: " + test::thesis_model() + R"(
set: {ground_motion.pulse: {duration: 3 s, dt: 0.01 s}}
axes: [{path: building.isolator.uy, values: [1 cm, 2 cm]}]
variants:
  BL: {building.isolator.model: bilinear, building.isolator.n: ~, building.isolator.A: ~, building.isolator.beta: ~, building.isolator.gamma: ~}
  BW: {building.isolator.model: bouc_wen}
outputs: [base.displacement, stories.drift_ratio, energy.hysteretic]
)");
  const fs::path db = dir / "s.db";
  const auto r = test::run_isopound("sweep '" + (dir / "study.yaml").string() + "' -q --db '" +
                                    db.string() + "'");
  ASSERT_EQ(r.exit_code, 0) << r.output;

  const StudyTable table = read_study_table(db.string());
  const StudyStore store = StudyStore::open(db.string(), true);
  EXPECT_EQ(table.axes, store.layout().axes);
  EXPECT_EQ(table.outputs, store.layout().outputs);
  EXPECT_EQ(table.axes, (std::vector<std::string>{"uy", "variant"}));
  EXPECT_EQ(table.output_quantities,
            (std::vector<std::string>{"displacement", "drift_ratio", "hysteretic"}));
  EXPECT_EQ(
      table.output_selectors,
      (std::vector<std::string>{"base.displacement", "stories.drift_ratio", "energy.hysteretic"}));
  const std::vector<RunRow> runs = store.read_runs();
  ASSERT_EQ(table.rows.size(), runs.size());
  ASSERT_EQ(runs.size(), 4u);
  for (std::size_t i = 0; i < runs.size(); ++i) {
    const StudyTableRow& row = table.rows[i];
    EXPECT_EQ(row.status, runs[i].status) << i;
    ASSERT_EQ(row.axes.size(), runs[i].axes.size()) << i;
    for (std::size_t a = 0; a < row.axes.size(); ++a) {
      EXPECT_EQ(row.axes[a].numeric, runs[i].axes[a].numeric) << i << " " << a;
      EXPECT_TRUE(same_value(row.axes[a].number, runs[i].axes[a].number)) << i << " " << a;
      EXPECT_EQ(row.axes[a].text, runs[i].axes[a].text) << i << " " << a;
    }
    ASSERT_EQ(row.values.size(), runs[i].values.size()) << i;
    for (std::size_t k = 0; k < row.values.size(); ++k)
      EXPECT_TRUE(same_value(row.values[k], runs[i].values[k])) << i << " " << k;
  }
  // Done runs with numbers; numeric uy in SI, labelled variants.
  EXPECT_EQ(table.rows[0].status, "done");
  EXPECT_TRUE(table.rows[0].axes[0].numeric);
  EXPECT_FALSE(table.rows[0].axes[1].numeric);
  EXPECT_GT(table.rows[0].values[0], 0.0);

  // Without the study file the quantities are unknown, the rest unchanged.
  fs::remove(dir / "study.yaml");
  const StudyTable orphan = read_study_table(db.string());
  EXPECT_EQ(orphan.output_quantities, (std::vector<std::string>(3, "")));
  EXPECT_EQ(orphan.output_selectors, (std::vector<std::string>(3, "")));
  // Selectors in parts for post's words (std types only); a bad one is kind "".
  const StudyTableSelector s = parse_table_selector("sum:wall*.impacts");
  EXPECT_EQ(s.kind, "element");
  EXPECT_EQ(s.where, "wall*");
  EXPECT_EQ(s.quantity, "impacts");
  EXPECT_TRUE(s.sum);
  const StudyTableSelector c = parse_table_selector("story2.corners.drift_ratio");
  EXPECT_EQ(c.kind, "story");
  EXPECT_EQ(c.where, "story2");
  EXPECT_EQ(c.point, "corners");
  EXPECT_EQ(parse_table_selector("no dot").kind, "");
  EXPECT_EQ(orphan.outputs, table.outputs);
  EXPECT_EQ(orphan.rows.size(), table.rows.size());
  fs::remove_all(dir);  // kept when an assertion failed above
}

TEST(StudyTable, MissingOrForeignDatabaseFailsClearly) {
  const fs::path dir = test::study_scratch("table-bad");
  const std::string missing = (dir / "nothing.db").string();
  try {
    read_study_table(missing);
    ADD_FAILURE() << "no error for a missing database";
  } catch (const StudyTableError& e) {
    EXPECT_EQ(e.reason(), StudyTableError::Reason::missing);
    EXPECT_EQ(std::string(e.what()), missing + ": study database not found");
  }
  const std::string foreign = (dir / "notes.db").string();
  test::write_file(foreign, "not a database\n");
  try {
    read_study_table(foreign);
    ADD_FAILURE() << "no error for a file that is not a study database";
  } catch (const StudyTableError& e) {
    EXPECT_EQ(e.reason(), StudyTableError::Reason::not_a_study);
    EXPECT_EQ(std::string(e.what()).rfind(foreign + ": not a study database: ", 0), 0u) << e.what();
  }
  fs::remove_all(dir);
}

// Layering: post/ sees study results only as plain tables. Its sources include no header of
// solver/study but study_table.h and cli_contract.h (the command-line contract every program
// shares, not study results). post/tests is exempt: it writes fixture databases.
TEST(StudyTable, PostIncludesNoStudyHeaderButTheTable) {
  const fs::path post = test::source_dir() / "post";
  const std::regex include(R"re(^\s*#\s*include\s*[<"](solver/study/[^">]+)[">])re");
  std::vector<std::string> problems;
  int files = 0;
  for (const auto& entry : fs::recursive_directory_iterator(post)) {
    const fs::path rel = fs::relative(entry.path(), post);
    if (*rel.begin() == "tests" || !entry.is_regular_file()) continue;
    const std::string ext = entry.path().extension().string();
    if (ext != ".h" && ext != ".cpp" && ext != ".hpp" && ext != ".cc") continue;
    ++files;
    std::ifstream in(entry.path());
    std::string line;
    for (int number = 1; std::getline(in, line); ++number) {
      std::smatch m;
      if (!std::regex_search(line, m, include)) continue;
      if (m[1] == "solver/study/study_table.h" || m[1] == "solver/study/cli_contract.h") continue;
      problems.push_back("post/" + rel.string() + ":" + std::to_string(number) + ": includes " +
                         m[1].str() + " (read studies through solver/study/study_table.h)");
    }
  }
  EXPECT_GT(files, 10);  // the scan saw post's sources
  for (const std::string& p : problems) ADD_FAILURE() << p;
}

}  // namespace
}  // namespace isopound
