// The documentation lives in the repository (issue 24, item 7): every link of README.md,
// THEORY-notes.md and docs/**/*.md points at a file inside the repository that exists, and no
// page sends the reader to the theory file outside it (../shared/docs).
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "tests/test_support.h"

namespace isopound {
namespace {

namespace fs = std::filesystem;

// The problems of one page: links (markdown `[text](target)`, `![alt](target)`, `<img src=...>`)
// outside fenced code that leave `root` or name a missing file, and mentions of shared/docs.
std::vector<std::string> link_problems(const std::string& text, const fs::path& page,
                                       const fs::path& root) {
  std::vector<std::string> problems;
  const std::regex link(R"re(\]\(([^)\s]+)(?:\s+"[^"]*")?\)|<img[^>]*\ssrc="([^"]+)")re");
  const fs::path base = root / page.parent_path();
  const std::string root_text = fs::weakly_canonical(root).string() + "/";
  std::istringstream lines(text);
  std::string line;
  bool in_code = false;
  for (int number = 1; std::getline(lines, line); ++number) {
    const std::string where = page.string() + ":" + std::to_string(number) + ": ";
    if (line.find("shared/docs") != std::string::npos)
      problems.push_back(where + "refers to shared/docs, outside the repository");
    if (line.rfind("```", 0) == 0) in_code = !in_code;
    if (in_code) continue;
    for (std::sregex_iterator m(line.begin(), line.end(), link), end; m != end; ++m) {
      std::string target = (*m)[1].matched ? (*m)[1].str() : (*m)[2].str();
      if (target.rfind("http://", 0) == 0 || target.rfind("https://", 0) == 0 ||
          target.rfind("mailto:", 0) == 0 || target.rfind('#', 0) == 0)
        continue;
      target = target.substr(0, target.find('#'));
      const fs::path resolved = fs::weakly_canonical(base / target);
      if (resolved.string().rfind(root_text, 0) != 0)
        problems.push_back(where + "'" + target + "' points outside the repository");
      else if (!fs::exists(resolved))
        problems.push_back(where + "'" + target + "' does not exist");
    }
  }
  return problems;
}

std::vector<fs::path> documentation_pages(const fs::path& root) {
  std::vector<fs::path> pages = {"README.md"};
  if (fs::exists(root / "THEORY-notes.md")) pages.emplace_back("THEORY-notes.md");
  for (const auto& entry : fs::recursive_directory_iterator(root / "docs"))
    if (entry.path().extension() == ".md") pages.push_back(fs::relative(entry.path(), root));
  return pages;
}

TEST(DocsLinks, EveryLinkOfTheReadmeAndDocsStaysInTheRepositoryAndExists) {
  const fs::path root = test::source_dir();
  const std::vector<fs::path> pages = documentation_pages(root);
  ASSERT_GE(pages.size(), 4u);  // README, THEORY-notes, docs/theory.md and more
  bool theory = false;
  int links = 0;
  for (const fs::path& page : pages) {
    theory = theory || page == fs::path("docs") / "theory.md";
    std::ifstream in(root / page);
    std::stringstream buffer;
    buffer << in.rdbuf();
    const std::string text = buffer.str();
    links += static_cast<int>(std::count(text.begin(), text.end(), ']'));
    for (const std::string& problem : link_problems(text, page, root)) ADD_FAILURE() << problem;
  }
  EXPECT_TRUE(theory) << "docs/theory.md, the user manual, is missing";
  EXPECT_GT(links, 20);
}

// The checker itself finds each kind of bad link (so the test above can fail).
TEST(DocsLinks, CheckerFindsOutsideMissingAndSharedReferences) {
  const fs::path root = test::source_dir();
  const std::string page = R"md(See [theory](../shared/docs/THEORY.md) and [x](docs/missing.md).
![figure](docs/pre/plan.png) [web](https://example.org) [here](#conventions)
<img src="../../etc/passwd">
```
[not a link in code](nowhere.md)
```
[readme](README.md#outputs)
)md";
  const std::vector<std::string> problems = link_problems(page, "README.md", root);
  ASSERT_EQ(problems.size(), 4u);
  EXPECT_NE(problems[0].find("shared/docs"), std::string::npos) << problems[0];
  EXPECT_NE(problems[1].find("outside the repository"), std::string::npos) << problems[1];
  EXPECT_NE(problems[2].find("does not exist"), std::string::npos) << problems[2];
  EXPECT_NE(problems[3].find("outside the repository"), std::string::npos) << problems[3];
}

}  // namespace
}  // namespace isopound
