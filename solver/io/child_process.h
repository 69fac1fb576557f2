// Running another program and waiting for it: `isopound demo` runs isopound-post, isopound-post
// runs ParaView's pvpython. posix_spawn, no shell (arguments are passed as they are).
#pragma once

#include <string>
#include <vector>

namespace isopound {

// The executable `name` in a directory of PATH ("" when there is none).
std::string find_on_path(const std::string& name);

struct ChildOptions {
  std::vector<std::string> environment;  // "KEY=value" entries; empty: this process's own
  std::string output_file;        // stdout goes there ("/dev/null" to discard); "": inherited
  bool stderr_to_output = false;  // stderr into output_file too
};

struct ChildResult {
  bool started = false;
  int exit_code = -1;  // -1 when it did not exit normally (a signal)
};

// Runs `program` with `args` (argv[0] is the program itself) and waits for it.
ChildResult run_child(const std::string& program, const std::vector<std::string>& args,
                      const ChildOptions& options = {});

}  // namespace isopound
