// Test helpers shared by the suite: where ../shared lives, and skip-or-fail when it is absent.
// Convention: ISOPOUND_SHARED overrides the location; ISOPOUND_REQUIRE_SHARED=1 (set by .ci/run)
// turns a missing ../shared into a test failure instead of a skip.
#pragma once

#include <gtest/gtest.h>

#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace isopound::test {

inline std::filesystem::path shared_dir() {
  if (const char* env = std::getenv("ISOPOUND_SHARED")) return env;
  return std::filesystem::path(ISOPOUND_SOURCE_DIR) / ".." / "shared";
}

inline std::filesystem::path records_dir() {
  return shared_dir() / "records";
}

inline bool shared_required() {
  const char* env = std::getenv("ISOPOUND_REQUIRE_SHARED");
  return env != nullptr && std::string(env) != "" && std::string(env) != "0";
}

inline std::filesystem::path source_dir() {
  return ISOPOUND_SOURCE_DIR;
}

// The whole text of a file ("" when absent).
inline std::string file_text(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

struct CommandResult {
  int exit_code = -1;
  std::string output;  // stdout and stderr
};

// Runs a shell command, capturing stdout and stderr together.
inline CommandResult run_command(const std::string& command) {
  CommandResult result;
  FILE* pipe = popen((command + " 2>&1").c_str(), "r");
  if (!pipe) return result;
  std::array<char, 4096> buffer{};
  std::size_t n;
  while ((n = std::fread(buffer.data(), 1, buffer.size(), pipe)) > 0)
    result.output.append(buffer.data(), n);
  const int status = pclose(pipe);
  result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return result;
}

#ifdef ISOPOUND_BINARY
inline CommandResult run_isopound(const std::string& args) {
  return run_command(std::string(ISOPOUND_BINARY) + " " + args);
}
#endif

}  // namespace isopound::test

// Use at the top of a test that needs ../shared/records.
#define ISOPOUND_REQUIRE_RECORDS()                                                       \
  do {                                                                                   \
    if (!std::filesystem::exists(::isopound::test::records_dir())) {                     \
      if (::isopound::test::shared_required())                                           \
        FAIL() << "../shared/records is required (ISOPOUND_REQUIRE_SHARED) but absent: " \
               << ::isopound::test::records_dir();                                       \
      GTEST_SKIP() << "../shared/records absent: " << ::isopound::test::records_dir();   \
    }                                                                                    \
  } while (0)
