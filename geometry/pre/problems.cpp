// Problem list of isopound-pre: messages formatted by the solver's InputNode (one format for the
// solver and the checks).
#include "geometry/pre/problems.h"

#include <algorithm>

namespace isopound::pre {

void ProblemList::add(Problem::Severity severity, std::string message) {
  for (const Problem& p : problems_)
    if (p.message == message) return;
  problems_.push_back({severity, std::move(message)});
}

void ProblemList::error_at(const InputNode& node, std::string_view key, const std::string& what) {
  error(message_at(node, key, what));
}

void ProblemList::warning_at(const InputNode& node, std::string_view key, const std::string& what) {
  warning(message_at(node, key, what));
}

int ProblemList::errors() const {
  return static_cast<int>(std::count_if(problems_.begin(), problems_.end(), [](const Problem& p) {
    return p.severity == Problem::Severity::kError;
  }));
}

int ProblemList::warnings() const {
  return static_cast<int>(problems_.size()) - errors();
}

std::string message_at(const InputNode& node, std::string_view key, const std::string& what) {
  try {
    if (key.empty()) node.fail(what);
    node.fail_at_key(key, what);
  } catch (const InputError& e) {
    return e.what();
  }
}

}  // namespace isopound::pre
