// step-accelerations.csv (see step_accelerations.h).
#include "solver/io/step_accelerations.h"

#include <cerrno>
#include <charconv>
#include <cstring>
#include <stdexcept>

namespace isopound {
namespace {

bool kept_column(const std::string& name) {
  return name == "time [s]" || name.rfind("ground_acceleration", 0) == 0 ||
         name.find(" a_abs [") != std::string::npos;
}

}  // namespace

StepAccelerationWriter::StepAccelerationWriter(std::string path) : path_(std::move(path)) {
  file_ = std::fopen(path_.c_str(), "w");
  if (!file_) throw std::runtime_error("cannot write " + path_ + ": " + std::strerror(errno));
}

StepAccelerationWriter::~StepAccelerationWriter() {
  if (file_) std::fclose(file_);
}

void StepAccelerationWriter::begin(const std::vector<std::string>& columns) {
  kept_.clear();
  for (std::size_t c = 0; c < columns.size(); ++c)
    if (kept_column(columns[c])) {
      std::fprintf(file_, "%s%s", kept_.empty() ? "" : ",", columns[c].c_str());
      kept_.push_back(c);
    }
  std::fputc('\n', file_);
  line_.resize(kept_.size() * 32 + 1);  // a double's shortest form is at most 24 characters
}

void StepAccelerationWriter::row(const double* values, std::size_t count) {
  char* p = line_.data();
  char* const end = line_.data() + line_.size();
  for (std::size_t k = 0; k < kept_.size(); ++k) {
    if (k) *p++ = ',';
    const double v = kept_[k] < count ? values[kept_[k]] : 0.0;
    p = std::to_chars(p, end, v).ptr;
  }
  *p++ = '\n';
  std::fwrite(line_.data(), 1, static_cast<std::size_t>(p - line_.data()), file_);
  ++steps_;
}

void StepAccelerationWriter::close() {
  if (!file_) return;
  const bool failed = std::ferror(file_) != 0;
  const bool close_failed = std::fclose(file_) != 0;
  file_ = nullptr;
  if (failed || close_failed) throw std::runtime_error("error writing " + path_);
}

}  // namespace isopound
