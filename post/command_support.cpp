// isopound-post's shared command helpers (see command_support.h).
#include "post/command_support.h"

#include <unistd.h>

#include <cstdio>
#include <fstream>

namespace isopound::post {

void write_text(const std::filesystem::path& path, const std::string& text) {
  std::ofstream out(path);
  out << text;
  if (!out) throw std::runtime_error("cannot write " + path.string());
}

Progress::Progress(std::string what, std::size_t total) : what_(std::move(what)), total_(total) {
  tty_ = isatty(STDERR_FILENO) != 0;
}

void Progress::tick(std::size_t done) {
  if (!tty_ || total_ == 0) return;
  const int pct = static_cast<int>(100 * done / total_);
  if (pct == last_) return;
  last_ = pct;
  std::fprintf(stderr, "\r%s [%-40s] %3d%%", what_.c_str(),
               std::string(pct * 40 / 100, '#').c_str(), pct);
  if (done == total_) std::fprintf(stderr, "\n");
}

RunData load_run(const std::string& dir, const std::string& model) {
  try {
    RunData run = read_run(dir, model);
    for (const std::string& n : run.notes)
      std::fprintf(stderr, "isopound-post: note: %s\n", n.c_str());
    return run;
  } catch (const RunDataError& e) {
    throw BadInput(e.what());
  }
}

}  // namespace isopound::post
