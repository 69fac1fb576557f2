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

std::vector<std::pair<std::string, std::string>> parse_where(
    const std::vector<std::string>& where) {
  std::vector<std::pair<std::string, std::string>> out;
  for (const std::string& w : where) {
    const auto eq = w.find('=');
    if (eq == std::string::npos || eq == 0) throw BadInput("--where '" + w + "': write AXIS=VALUE");
    out.push_back({w.substr(0, eq), w.substr(eq + 1)});
  }
  return out;
}

std::string study_figure_stem(const std::string& db, const std::string& out,
                              const std::string& name) {
  namespace fs = std::filesystem;
  fs::path png = out.empty() ? fs::path(db).parent_path() / name : fs::path(out);
  if (png.extension() == ".png" || png.extension() == ".PNG")
    png.replace_extension();
  else if (!out.empty())
    png /= name;
  if (!png.parent_path().empty()) fs::create_directories(png.parent_path());
  return png.string();
}

}  // namespace isopound::post
