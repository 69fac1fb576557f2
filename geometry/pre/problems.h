// A problem found by isopound-pre's checks: an error (the model is wrong) or a warning
// (suspicious but legal). The message is the solver's "file:line:col: key.path: what".
#pragma once

#include <string>
#include <vector>

#include "solver/io/yaml_reader.h"

namespace isopound::pre {

struct Problem {
  enum class Severity { kError, kWarning };
  Severity severity = Severity::kError;
  std::string message;  // "file:line:col: key: what"
};

// Collects problems in the order found; an identical message is kept once.
class ProblemList {
 public:
  void add(Problem::Severity severity, std::string message);
  void error(std::string message) { add(Problem::Severity::kError, std::move(message)); }
  void warning(std::string message) { add(Problem::Severity::kWarning, std::move(message)); }
  // The message InputNode::fail / fail_at_key would throw, as an error or a warning.
  void error_at(const InputNode& node, std::string_view key, const std::string& what);
  void warning_at(const InputNode& node, std::string_view key, const std::string& what);

  const std::vector<Problem>& all() const { return problems_; }
  int errors() const;
  int warnings() const;

 private:
  std::vector<Problem> problems_;
};

// The message of InputNode::fail (empty key) or fail_at_key, without throwing it.
std::string message_at(const InputNode& node, std::string_view key, const std::string& what);

}  // namespace isopound::pre
