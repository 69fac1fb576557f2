// The limits of a YAML input file (docs/input-limits.md), checked by read_input_file and
// parse_single_document (yaml_reader.h; implemented in yaml_document.cpp).
#pragma once

#include <cstddef>

namespace isopound {

// What a YAML input file may hold (docs/input-limits.md). Reading stops at the first limit passed
// with an InputError naming the file and, where one exists, the line. Within them, reading a file
// of n bytes takes O(n) time and memory: yaml-cpp builds a bounded number of nodes per byte, the
// depth bounds every recursion, and aliases may add at most kMaxAliasExpansion times the nodes
// written (so a reader that visits every node it reaches stays linear; an alias loop is refused).
struct InputLimits {
  static constexpr std::size_t kMaxFileBytes = 4u << 20;   // 4 MiB; the largest config is ~6 kB
  static constexpr std::size_t kMaxLineBytes = 64u << 10;  // 64 KiB in one line
  static constexpr int kMaxDepth = 64;                     // maps and lists inside each other
  static constexpr std::size_t kMaxNodes = 1'000'000;      // scalars, maps, lists, nulls
  static constexpr std::size_t kMaxAliasExpansion = 4;     // expanded nodes <= 4 x written + 256
};

}  // namespace isopound
