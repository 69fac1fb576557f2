// The input readers are bounded by construction (issue 28, docs/input-limits.md): the file that
// made `isopound check` allocate without end, every limit of InputLimits, and peak memory that
// grows no faster than the stated multiple of the input size for each reader.
#include <gtest/gtest.h>
#include <malloc.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>

#include "solver/excitation/ground_motion.h"
#include "solver/io/model_input.h"
#include "solver/io/polygon_input.h"
#include "solver/io/yaml_document.h"
#include "solver/io/yaml_reader.h"
#include "solver/study/study_spec.h"
#include "tests/test_support.h"

namespace isopound {
namespace {

namespace fs = std::filesystem;

fs::path scratch_dir() {
  const fs::path dir =
      fs::temp_directory_path() / ("isopound-bounds-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  return dir;
}

fs::path write_file(const std::string& name, const std::string& text) {
  const fs::path path = scratch_dir() / name;
  std::ofstream(path, std::ios::binary) << text;
  return path;
}

// The InputError parse_single_document gives for `text` (fails the test when there is none).
InputError parse_error(const std::string& text) {
  try {
    parse_single_document(text, "f.yaml", "a model file");
  } catch (const InputError& e) {
    return e;
  }
  ADD_FAILURE() << "no InputError for: " << text.substr(0, 80);
  return InputError("", 0, 0, "", "");
}

// --- issue 28: the hang ---

TEST(ReaderBounds, Issue28FileIsASyntaxErrorAtItsLineWithinASecond) {
  const fs::path file =
      test::source_dir() / "tests" / "data" / "fuzz_regressions" / "issue28-hang.yaml";
  const auto start = std::chrono::steady_clock::now();
  // `timeout`: were the endless loop back, the test fails after 20 s instead of eating memory.
  const test::CommandResult c = test::run_command("timeout 20 " + std::string(ISOPOUND_BINARY) +
                                                  " check '" + file.string() + "'");
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_EQ(c.exit_code, 2) << c.output;
  EXPECT_NE(c.output.find("issue28-hang.yaml:2:1: YAML syntax error: unexpected ','"),
            std::string::npos)
      << c.output;
  EXPECT_LT(seconds, 1.0) << c.output;
}

TEST(ReaderBounds, TextTheParserCannotConsumeIsRefusedAtItsPosition) {
  // yaml-cpp 0.7 starts an empty document at such a token without consuming it: the loop the
  // reader now stops. Same shape at the start of a file, and after a flow map.
  for (const auto& [text, line, column] :
       {std::tuple{std::string("    b: 1\n,c: 2"), 2, 1}, std::tuple{std::string(",c"), 1, 1},
        std::tuple{std::string("  a: 1\n]"), 2, 1}}) {
    const InputError e = parse_error(text);
    EXPECT_EQ(e.line(), line) << text;
    EXPECT_EQ(e.column(), column) << text;
    EXPECT_NE(e.detail().find("YAML syntax error"), std::string::npos) << e.what();
  }
  // A real second document keeps its own message, at its '---'.
  const InputError e = parse_error("a: 1\n---\nb: 2\n");
  EXPECT_EQ(e.line(), 2);
  EXPECT_NE(e.detail().find("more than one YAML document"), std::string::npos) << e.what();
}

// --- the limits of InputLimits, each at its line ---

TEST(ReaderBounds, NestingDeeperThanTheLimitIsRefusedAtTheLevelThatPassesIt) {
  const int depth = InputLimits::kMaxDepth;
  EXPECT_NO_THROW(parse_single_document(std::string(depth, '[') + std::string(depth, ']'), "f",
                                        "a model file"));
  const InputError e =
      parse_error("a:\n  " + std::string(depth + 1, '[') + std::string(depth + 1, ']'));
  EXPECT_EQ(e.line(), 2);
  EXPECT_NE(e.detail().find("nested more than 64 deep"), std::string::npos) << e.what();
  // Far deeper than yaml-cpp's own recursion limit: stops at ours, no stack exhaustion.
  EXPECT_EQ(parse_error(std::string(100000, '[')).line(), 1);
}

TEST(ReaderBounds, LongLinesAndFilesAreRefusedNamingTheLine) {
  const std::string long_line(InputLimits::kMaxLineBytes + 1, 'x');
  const InputError e = parse_error("a: 1\nb: 2\nc: " + long_line + "\n");
  EXPECT_EQ(e.line(), 3);
  EXPECT_NE(e.detail().find("longer than 64 KiB"), std::string::npos) << e.what();

  const fs::path big = write_file("big.yaml", std::string(InputLimits::kMaxFileBytes + 1, '\n'));
  try {
    read_input_file(big.string(), "a YAML model file");
    ADD_FAILURE() << "no error for a file over the limit";
  } catch (const InputError& error) {
    EXPECT_NE(error.detail().find("more than 4 MiB"), std::string::npos) << error.what();
  }
  fs::remove(big);
  // A device that never ends is read no further than the limit.
  EXPECT_THROW(read_input_file("/dev/zero", "a YAML model file"), InputError);
}

TEST(ReaderBounds, TooManyNodesAndAliasBombsAndLoopsAreRefused) {
  std::string many;
  for (std::size_t i = 0; i <= InputLimits::kMaxNodes; ++i) many += "- 0\n";
  EXPECT_NE(parse_error(many).detail().find("more than 1000000"), std::string::npos);

  // Ten levels of ten aliases each: 10^10 nodes once expanded, from 150 written.
  std::string bomb = "l0: &a0 [0, 0, 0, 0, 0, 0, 0, 0, 0, 0]\n";
  for (int level = 1; level < 10; ++level) {
    const std::string previous = "*a" + std::to_string(level - 1);
    bomb += "l" + std::to_string(level) + ": &a" + std::to_string(level) + " [";
    for (int k = 0; k < 10; ++k) bomb += (k ? ", " : "") + previous;
    bomb += "]\n";
  }
  EXPECT_NE(parse_error(bomb).detail().find("aliases (*name) expand"), std::string::npos);
  EXPECT_NE(parse_error("a: &x [1, *x]\n").detail().find("once aliases"), std::string::npos);
  // Ordinary reuse of an anchor stays allowed.
  EXPECT_NO_THROW(parse_single_document("a: &w {k: 1, e: 0.7}\nb: *w\n", "f", "a model file"));
}

// --- peak memory against input size ---

// What a read in a forked child added to its peak resident memory: the child resets its peak
// (/proc/self/clear_refs "5"), runs the read, and reports VmHWM minus VmRSS before it.
struct Peak {
  long long added_bytes = -1;  // -1: could not be measured
  std::string error;           // what the read threw, if it did
};

Peak peak_of(const std::function<void()>& reader) {
  int fds[2];
  if (pipe(fds) != 0) return {};
  const pid_t pid = fork();
  if (pid == 0) {
    close(fds[0]);
    const auto status_kb = [](const std::string& field) {
      std::ifstream in("/proc/self/status");
      std::string line;
      while (std::getline(in, line))
        if (line.rfind(field, 0) == 0) return std::stoll(line.substr(field.size()));
      return -1LL;
    };
    long long added = -1;
    std::string error;
    // Free heap pages inherited from the parent would take the read's allocations unseen.
    malloc_trim(0);
    if (std::ofstream("/proc/self/clear_refs") << "5") {
      const long long before = status_kb("VmRSS:");
      try {
        reader();
      } catch (const std::exception& e) {
        error = e.what();
      }
      added = (status_kb("VmHWM:") - before) * 1024;
    }
    const std::string text = std::to_string(added) + "\n" + error;
    if (write(fds[1], text.data(), text.size()) < 0) _exit(1);
    _exit(0);
  }
  close(fds[1]);
  std::string text;
  char buffer[4096];
  for (ssize_t n; (n = read(fds[0], buffer, sizeof buffer)) > 0;)
    text.append(buffer, static_cast<std::size_t>(n));
  close(fds[0]);
  int status = 0;
  waitpid(pid, &status, 0);
  const std::size_t newline = text.find('\n');
  if (newline == std::string::npos) return {};
  return {std::stoll(text.substr(0, newline)), text.substr(newline + 1)};
}

// Inputs of about `bytes` bytes that each reader reads to the end (valid files, so every
// value is read, checked and kept).
std::string model_of_size(std::size_t bytes) {
  std::string text =
      "building:\n  base: {mass: 340 t}\n"
      "  floors: {count: 3, mass: 340 t, stiffness: 600 MN/m, height: 3.2 m}\n"
      "  isolator: {model: linear, Tb: 2.5 s}\nneighbours:\n";
  for (int k = 0; text.size() < bytes; ++k)
    text +=
        "  - {side: right, gap: 10 cm, impact: {law: linear, k: 2500 kN/mm},\n"
        "     building: {name: n" +
        std::to_string(k) +
        ", isolated: false, floors: {count: 2, mass: 300 t, stiffness: 500 MN/m, "
        "height: 3.2 m}}}\n";
  return text;
}
std::string pairs_of_size(std::size_t bytes) {
  std::string text = "pairs:\n";
  for (int k = 0; text.size() < bytes; ++k)
    text += "  - {name: p" + std::to_string(k) +
            ", a: [[0, 0], [20 m, 0], [20 m, 15 m], [0, 15 m]],\n"
            "     b: [[19.95 m, 2 m], [3195 cm, 2 m], [31.95 m, 12 m], [19.95 m, 12 m]]}\n";
  return text;
}
std::string peer_of_size(std::size_t bytes) {
  const std::size_t values = bytes / 14;
  std::string text =
      "PEER\nSYNTHETIC\nACCELERATION TIME SERIES IN UNITS OF G\nNPTS= " + std::to_string(values) +
      ", DT= .0050 SEC\n";
  for (std::size_t i = 0; i < values; ++i)
    text += (i % 5 == 4) ? " -.1234567E-02\n" : " .12345E-02";
  return text;
}
std::string columns_of_size(std::size_t bytes) {
  std::string text;
  for (int i = 0; text.size() < bytes; ++i)
    text += std::to_string(i * 0.005) + ", " + std::to_string(1e-3 * (i % 7)) + "\n";
  return text;
}
std::string study_of_size(std::size_t bytes) {
  std::string text =
      "name: big\nmodel: model.yaml\naxes:\n  - path: building.walls.k\n    values:\n";
  for (int k = 1; text.size() < bytes; ++k) text += "      - " + std::to_string(k) + " kN/mm\n";
  return text + "outputs:\n  u_base: base.displacement\n";
}

struct Reader {
  const char* name;
  std::function<std::string(std::size_t)> input;
  std::function<void(const std::string&)> read;  // reads the file at this path
  double bytes_per_input_byte;                   // the stated bound (docs/input-limits.md)
};

#if defined(__SANITIZE_ADDRESS__)  // GCC's spelling
#define ISOPOUND_UNDER_ADDRESS_SANITIZER 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)  // clang's (CI's sanitizer tree)
#define ISOPOUND_UNDER_ADDRESS_SANITIZER 1
#endif
#endif

TEST(ReaderBounds, PeakMemoryGrowsLinearlyWithinTheStatedMultipleOfTheInput) {
#ifdef ISOPOUND_UNDER_ADDRESS_SANITIZER
  GTEST_SKIP() << "AddressSanitizer keeps freed memory in quarantine: its resident peak is not "
                  "the reader's (the Release tree runs this test)";
#endif
  write_file("model.yaml", model_of_size(0) + "  walls: {gap: 10 cm, k: 1000 MN/m}\n");
  const std::vector<Reader> readers = {
      {"model", model_of_size, [](const std::string& p) { load_model_file(p); }, 200},
      {"polygon pairs", pairs_of_size, [](const std::string& p) { load_polygon_pairs_file(p); },
       200},
      {"study", study_of_size, [](const std::string& p) { load_study_file(p); }, 200},
      {"PEER record", peer_of_size, [](const std::string& p) { read_record(p); }, 8},
      {"columns record", columns_of_size,
       [](const std::string& p) {
         RecordReadOptions options;
         options.format = RecordReadOptions::Format::kColumns;
         options.column = 1;
         options.time_column = 0;
         read_record(p, options);
       },
       8},
  };
  constexpr long long kBaseBytes = 8ll << 20;  // allocator arenas, first pages of the libraries
  for (const Reader& reader : readers) {
    for (const std::size_t size : {10'000u, 100'000u, 1'000'000u, 3'000'000u}) {
      const std::string text = reader.input(size);
      const fs::path path = write_file("input.txt", text);
      const Peak peak = peak_of([&] { reader.read(path.string()); });
      ASSERT_GE(peak.added_bytes, 0) << "cannot measure peak memory (/proc/self/clear_refs)";
      EXPECT_EQ(peak.error, "") << reader.name << ": the input must be read to its end";
      const long long added = peak.added_bytes;
      const long long bound =
          kBaseBytes + static_cast<long long>(reader.bytes_per_input_byte * double(text.size()));
      std::printf("%-15s %8zu bytes: peak +%7.1f MiB (%.1f bytes per input byte; bound %.1f MiB)\n",
                  reader.name, text.size(), double(added) / (1 << 20),
                  double(added) / double(text.size()), double(bound) / (1 << 20));
      EXPECT_LE(added, bound) << reader.name << ", " << text.size() << " bytes";
    }
  }
}

}  // namespace
}  // namespace isopound
