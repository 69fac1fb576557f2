// A problem found by the model checks (solver/io/site_checks.h, isopound-pre): an error (the
// model is wrong) or a warning (suspicious but legal). The message is the solver's
// "file:line:col: key.path: what".
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "solver/io/yaml_reader.h"

namespace isopound {

struct Problem {
  enum class Severity { kError, kWarning };
  Severity severity = Severity::kError;
  std::string message;                // "file:line:col: key: what"
  std::optional<InputError> located;  // its parts, when found at a node (error_at, warning_at)
};

// Every error of a list at once, thrown by the reader: file, line, column and key are the first
// error's; what() is one message per line, in the order found.
class InputErrors : public InputError {
 public:
  InputErrors(const InputError& first, std::string all);
  const char* what() const noexcept override { return all_.c_str(); }

 private:
  std::string all_;
};

// Collects problems in the order found; an identical message is kept once.
class ProblemList {
 public:
  void add(Problem::Severity severity, std::string message,
           std::optional<InputError> located = std::nullopt);
  void error(std::string message) { add(Problem::Severity::kError, std::move(message)); }
  void warning(std::string message) { add(Problem::Severity::kWarning, std::move(message)); }
  // The message InputNode::fail / fail_at_key would throw, as an error or a warning.
  void error_at(const InputNode& node, std::string_view key, const std::string& what);
  void warning_at(const InputNode& node, std::string_view key, const std::string& what);

  const std::vector<Problem>& all() const { return problems_; }
  int errors() const;
  int warnings() const;
  // Throws InputErrors (or the one InputError) when there are errors.
  void throw_errors() const;

 private:
  std::vector<Problem> problems_;
};

// Numbers in messages: printf's `format` applied to v; a length as "1.234 m" (never "-0.000 m").
std::string format_number(const char* format, double v);
std::string metres_text(double v);

// The error InputNode::fail (empty key) or fail_at_key would throw, without throwing it.
InputError error_at(const InputNode& node, std::string_view key, const std::string& what);

}  // namespace isopound
