// Problem list of the model checks: messages formatted by the solver's InputNode (one format for
// the reader and the checks).
#include "solver/io/problems.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace isopound {

InputErrors::InputErrors(const InputError& first, std::string all)
    : InputError(first), all_(std::move(all)) {}

void ProblemList::add(Problem::Severity severity, std::string message,
                      std::optional<InputError> located) {
  for (const Problem& p : problems_)
    if (p.message == message) return;
  problems_.push_back({severity, std::move(message), std::move(located)});
}

void ProblemList::error_at(const InputNode& node, std::string_view key, const std::string& what) {
  InputError e = isopound::error_at(node, key, what);
  add(Problem::Severity::kError, e.what(), e);
}

void ProblemList::warning_at(const InputNode& node, std::string_view key, const std::string& what) {
  InputError e = isopound::error_at(node, key, what);
  add(Problem::Severity::kWarning, e.what(), e);
}

void ProblemList::throw_errors() const {
  std::string all;
  const Problem* first = nullptr;
  int n = 0;
  for (const Problem& p : problems_) {
    if (p.severity != Problem::Severity::kError) continue;
    if (!first) first = &p;
    all += (n++ ? "\n" : "") + p.message;
  }
  if (!first) return;
  const InputError head =
      first->located ? *first->located : InputError("", 0, 0, "", first->message);
  if (n == 1) throw head;
  throw InputErrors(head, all);
}

int ProblemList::errors() const {
  return static_cast<int>(std::count_if(problems_.begin(), problems_.end(), [](const Problem& p) {
    return p.severity == Problem::Severity::kError;
  }));
}

int ProblemList::warnings() const {
  return static_cast<int>(problems_.size()) - errors();
}

std::string format_number(const char* format, double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, format, v);
  return buf;
}

std::string metres_text(double v) {
  return format_number("%.3f m", std::abs(v) < 5e-4 ? 0.0 : v);
}

InputError error_at(const InputNode& node, std::string_view key, const std::string& what) {
  try {
    if (key.empty()) node.fail(what);
    node.fail_at_key(key, what);
  } catch (const InputError& e) {
    return e;
  }
}

}  // namespace isopound
