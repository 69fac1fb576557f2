// What isopound-post's commands share: the exit codes, the bad-input error (exit 2), writing a
// text file, a progress bar on a terminal, and reading a run with its notes on stderr.
#pragma once

#include <cstddef>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "post/run_data.h"

namespace isopound::post {

enum ExitCode { kOk = 0, kFailure = 1, kBadInput = 2 };

// Input errors: a message already naming file/key; exit code 2.
struct BadInput : std::runtime_error {
  using std::runtime_error::runtime_error;
};

void write_text(const std::filesystem::path& path, const std::string& text);

// Progress on stderr for long loops, only on a terminal (CI logs stay clean).
class Progress {
 public:
  Progress(std::string what, std::size_t total);
  void tick(std::size_t done);

 private:
  std::string what_;
  std::size_t total_;
  bool tty_ = false;
  int last_ = -1;
};

// read_run with its notes printed on stderr; a RunDataError becomes BadInput.
RunData load_run(const std::string& dir, const std::string& model);

// --where AXIS=VALUE options of the study commands as (axis, value) pairs; BadInput otherwise.
std::vector<std::pair<std::string, std::string>> parse_where(const std::vector<std::string>& where);

// The path without extension of a study figure (its .png and .csv): `-o` is the output directory
// (default: the database's) to write `name` into, or a .png file. Creates the directory.
std::string study_figure_stem(const std::string& db, const std::string& out,
                              const std::string& name);

}  // namespace isopound::post
