// What the fuzz targets share: a scratch directory of their own process, a file written there
// from the fuzzer's bytes, and the check that the process-global key registry stays bounded.
#pragma once

#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "solver/io/yaml_reader.h"

namespace isopound::fuzz {

// A directory private to this process (removed by nobody: /tmp is the fuzzer's scratch).
inline const std::filesystem::path& scratch_dir() {
  static const std::filesystem::path dir = [] {
    const std::filesystem::path d =
        std::filesystem::temp_directory_path() / ("isopound-fuzz-" + std::to_string(::getpid()));
    std::filesystem::create_directories(d);
    return d;
  }();
  return dir;
}

// Writes `size` bytes to scratch_dir()/name and returns its path.
inline std::string write_scratch(const std::string& name, const char* data, std::size_t size) {
  const std::filesystem::path path = scratch_dir() / name;
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(data, static_cast<std::streamsize>(size));
  return path.string();
}

// known_model_keys() grows with every new key path a reader looks up. Paths come from the
// reader's code (list indices dropped), never from the file, so the registry is bounded by the
// schema: more than this many is a leak across inputs, reported as a crash.
inline void check_key_registry() {
  constexpr std::size_t kMaxSchemaKeys = 2000;
  const std::size_t n = known_model_keys().size();
  if (n > kMaxSchemaKeys) {
    std::fprintf(stderr, "known_model_keys() holds %zu paths: it grows with the input\n", n);
    std::abort();
  }
}

}  // namespace isopound::fuzz
