// Reading one YAML document from a file within InputLimits (yaml_reader.h, docs/input-limits.md):
// the file's size and line lengths are checked on the text, the parser's events are counted
// before any tree is built (depth, nodes, documents), and aliases are expanded on a budget.
//
// Why not YAML::LoadAll: yaml-cpp 0.7 returns an empty document, without consuming anything,
// for a token that cannot start one (a ',' at the start of a line after a block map: issue 28's
// "    b: 1\n,c: 2"); LoadAll then appends empty documents until memory runs out. Here at most
// three documents are asked for, and one that starts where the previous one started is the
// parser stuck on text it cannot read: a syntax error at that position.
#include <yaml-cpp/eventhandler.h>

#include <algorithm>
#include <array>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>

#include "solver/io/yaml_document.h"

#include "solver/io/yaml_reader.h"

namespace isopound {
namespace {

using Limits = InputLimits;

int line_of(const YAML::Mark& m) {
  return m.is_null() ? 0 : m.line + 1;
}
int column_of(const YAML::Mark& m) {
  return m.is_null() ? 0 : m.column + 1;
}

// A limit passed while the parser's events were counted.
struct LimitPassed {
  YAML::Mark mark;
  std::string what;
};

// Counts one document's events: nesting depth and nodes (checked as they arrive, so a deep or
// huge document stops at the limit, before yaml-cpp's own recursion or any tree), and aliases.
class EventCounter : public YAML::EventHandler {
 public:
  std::size_t nodes = 0;
  std::size_t aliases = 0;
  YAML::Mark document_start = YAML::Mark::null_mark();

  void OnDocumentStart(const YAML::Mark& mark) override { document_start = mark; }
  void OnDocumentEnd() override {}
  void OnNull(const YAML::Mark& mark, YAML::anchor_t) override { node(mark); }
  void OnAlias(const YAML::Mark& mark, YAML::anchor_t) override {
    node(mark);
    ++aliases;
  }
  void OnScalar(const YAML::Mark& mark, const std::string&, YAML::anchor_t,
                const std::string&) override {
    node(mark);
  }
  void OnSequenceStart(const YAML::Mark& mark, const std::string&, YAML::anchor_t,
                       YAML::EmitterStyle::value) override {
    open(mark);
  }
  void OnSequenceEnd() override { --depth_; }
  void OnMapStart(const YAML::Mark& mark, const std::string&, YAML::anchor_t,
                  YAML::EmitterStyle::value) override {
    open(mark);
  }
  void OnMapEnd() override { --depth_; }

 private:
  void node(const YAML::Mark& mark) {
    if (++nodes > Limits::kMaxNodes)
      throw LimitPassed{mark, "more than " + std::to_string(Limits::kMaxNodes) +
                                  " values, maps and lists: not an isopound input file"};
  }
  void open(const YAML::Mark& mark) {
    node(mark);
    if (++depth_ > Limits::kMaxDepth)
      throw LimitPassed{
          mark, "maps and lists nested more than " + std::to_string(Limits::kMaxDepth) + " deep"};
  }
  int depth_ = 0;
};

// Walks the tree as a reader would, each alias expanded again, and stops once it has seen
// `budget` nodes or gone deeper than the limit (an alias inside its own anchor is a loop).
void check_expansion(const YAML::Node& node, int depth, std::size_t& budget) {
  if (budget == 0)
    throw LimitPassed{node.Mark(), "aliases (*name) expand to more than " +
                                       std::to_string(Limits::kMaxAliasExpansion) +
                                       " times the values written"};
  --budget;
  if (depth > Limits::kMaxDepth)
    throw LimitPassed{node.Mark(), "maps and lists nested more than " +
                                       std::to_string(Limits::kMaxDepth) +
                                       " deep once aliases (*name) are expanded (an alias inside "
                                       "its own anchor?)"};
  if (node.IsSequence()) {
    for (const auto& item : node) check_expansion(item, depth + 1, budget);
  } else if (node.IsMap()) {
    for (const auto& entry : node) {
      check_expansion(entry.first, depth + 1, budget);
      check_expansion(entry.second, depth + 1, budget);
    }
  }
}

InputError too_large(const std::string& path) {
  return InputError(path, 0, 0, "",
                    "more than " + std::to_string(Limits::kMaxFileBytes >> 20) +
                        " MiB: not an isopound input file");
}

// A NUL byte, or many control characters, in the first 4 kB: not a text file.
void refuse_binary(const std::string& text, const std::string& path, std::string_view what) {
  const std::size_t n = std::min<std::size_t>(text.size(), 4096);
  std::size_t control = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const auto c = static_cast<unsigned char>(text[i]);
    if (c == 0)
      throw InputError(path, 0, 0, "",
                       "is a binary file (a NUL byte at byte " + std::to_string(i + 1) + "), not " +
                           std::string(what) + " (YAML text)");
    if (c < 0x20 && c != '\t' && c != '\n' && c != '\r' && c != '\f') ++control;
  }
  if (control > 8 && control * 20 > n)
    throw InputError(path, 0, 0, "",
                     "is a binary file (" + std::to_string(control) +
                         " control characters in its first " + std::to_string(n) + " bytes), not " +
                         std::string(what) + " (YAML text)");
}

// The 1-based line and column of the first tab in a line's leading white space.
std::optional<std::pair<int, int>> first_indenting_tab(const std::string& text) {
  int line = 1;
  bool leading = true;
  int column = 0;
  for (char c : text) {
    ++column;
    if (c == '\n') {
      ++line;
      column = 0;
      leading = true;
      continue;
    }
    if (!leading) continue;
    if (c == '\t') return std::pair{line, column};
    if (c != ' ') leading = false;
  }
  return std::nullopt;
}

// Size and line lengths, on the text before any parsing; a binary file is named as such first.
void check_text(const std::string& text, const std::string& path, std::string_view what) {
  refuse_binary(text, path, what);
  if (text.size() > Limits::kMaxFileBytes) throw too_large(path);
  std::size_t line_start = 0;
  int line = 1;
  for (std::size_t i = 0; i <= text.size(); ++i) {
    if (i < text.size() && text[i] != '\n') continue;
    if (i - line_start > Limits::kMaxLineBytes)
      throw InputError(path, line, 0, "",
                       "a line longer than " + std::to_string(Limits::kMaxLineBytes >> 10) +
                           " KiB: not a text input file (binary data?)");
    line_start = i + 1;
    ++line;
  }
}

std::string shown_character(const std::string& text, const YAML::Mark& mark) {
  if (mark.pos < 0 || static_cast<std::size_t>(mark.pos) >= text.size()) return "the end";
  const unsigned char c = static_cast<unsigned char>(text[static_cast<std::size_t>(mark.pos)]);
  if (c >= 0x21 && c < 0x7f) return "'" + std::string(1, static_cast<char>(c)) + "'";
  std::ostringstream os;
  os << "byte 0x" << std::hex << static_cast<int>(c);
  return os.str();
}

}  // namespace

std::string read_input_file(const std::string& path, std::string_view expected) {
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) throw InputError(path, 0, 0, "", "file not found");
  if (std::filesystem::is_directory(path, ec))
    throw InputError(path, 0, 0, "", "is a directory, expected " + std::string(expected));
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, 0, 0, "", "cannot open the file");
  // In blocks, stopping once past the limit: a device or pipe that never ends is refused too.
  std::string text;
  std::array<char, 1 << 16> block;
  while (in.read(block.data(), block.size()) || in.gcount() > 0) {
    text.append(block.data(), static_cast<std::size_t>(in.gcount()));
    if (text.size() > Limits::kMaxFileBytes) throw too_large(path);
  }
  if (in.bad()) throw InputError(path, 0, 0, "", "cannot read the file");
  check_text(text, path, expected);
  return text;
}

YAML::Node parse_single_document(const std::string& text, const std::string& path,
                                 std::string_view what) {
  check_text(text, path, what);
  EventCounter counter;
  try {
    std::istringstream in(text);
    YAML::Parser parser(in);
    std::vector<YAML::Mark> starts;
    while (starts.size() < 3 && parser.HandleNextDocument(counter)) {
      const YAML::Mark start = counter.document_start;
      if (!starts.empty() && start.pos == starts.back().pos)
        throw InputError(path, line_of(start), column_of(start), "",
                         "YAML syntax error: unexpected " + shown_character(text, start) +
                             " (the document ends before it: check the indentation above)");
      starts.push_back(start);
    }
    if (starts.size() > 1)
      throw InputError(path, line_of(starts[1]), column_of(starts[1]), "",
                       "more than one YAML document ('---'); " + std::string(what) + " holds one");
  } catch (const YAML::Exception& e) {
    // YAML indents with spaces only; yaml-cpp's own message does not say a tab was the cause.
    if (const auto tab = first_indenting_tab(text))
      throw InputError(path, tab->first, tab->second, "",
                       "a tab character in the indentation: YAML indents with spaces only "
                       "(replace the tab by spaces)");
    throw InputError(path, line_of(e.mark), column_of(e.mark), "", "YAML syntax error: " + e.msg);
  } catch (const LimitPassed& e) {
    throw InputError(path, line_of(e.mark), column_of(e.mark), "", e.what);
  }
  YAML::Node root;
  try {
    root = YAML::Load(text);
    if (counter.aliases > 0) {
      std::size_t budget = Limits::kMaxAliasExpansion * counter.nodes + 256;
      check_expansion(root, 0, budget);
    }
  } catch (const YAML::Exception& e) {
    throw InputError(path, line_of(e.mark), column_of(e.mark), "", "YAML syntax error: " + e.msg);
  } catch (const LimitPassed& e) {
    throw InputError(path, line_of(e.mark), column_of(e.mark), "", e.what);
  }
  return root;
}

}  // namespace isopound
