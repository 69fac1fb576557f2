// A study's results as a plain table (std types only, no SQLite): the read API for programs that
// show results (isopound-post), so that they never see the study store's internals.
// Values are SI as stored (numeric axes too: angles in rad); a NULL peak reads as NaN.
#pragma once

#include <stdexcept>
#include <string>
#include <vector>

namespace isopound {

class StudyTableError : public std::runtime_error {
 public:
  enum class Reason {
    missing,      // no file at the path
    not_a_study,  // the file does not open as a study database
    unreadable,   // it opened but its runs could not be read
  };
  StudyTableError(Reason reason, const std::string& what)
      : std::runtime_error(what), reason_(reason) {}
  Reason reason() const { return reason_; }

 private:
  Reason reason_;
};

// A value of an axis column: a number (SI) or a label.
struct StudyTableCell {
  bool numeric = false;
  double number = 0.0;
  std::string text;
};

// One run: its status (pending | done | failed), axis cells and output values (NaN for NULL).
struct StudyTableRow {
  std::string status;
  std::vector<StudyTableCell> axes;  // per StudyTable::axes
  std::vector<double> values;        // per StudyTable::outputs
};

struct StudyTable {
  std::vector<std::string> axes;     // axis columns, in enumeration order
  std::vector<std::string> outputs;  // output (peak) columns
  // Per output column: the quantity of its selector in the study file ("displacement",
  // "drift_ratio", ...). "" when unknown: the study file is gone or unreadable, or holds no such
  // column (ensemble statistics c_ens_S are columns of the table, not of the study file).
  std::vector<std::string> output_quantities;
  // Per output column: its selector as the study file writes it ("base.displacement",
  // "sum:wall*.impacts"); "" when unknown (as output_quantities). For axis titles in words.
  std::vector<std::string> output_selectors;
  std::vector<StudyTableRow> rows;  // in case order
};

// An output selector in parts (solver/study/study_outputs.h's grammar) in std types: what a
// program that shows results needs to name a column in words (post/study_words.h).
struct StudyTableSelector {
  std::string text;   // as written ("sum:wall*.impacts")
  std::string kind;   // "level", "story", "element", "energy", "ground"; "" when it does not parse
  std::string where;  // "base", "stories" (also for "columns"), "wall*", ...
  std::string point;  // 3D plan point or column set ("corners", "A1"); "" for none
  std::string quantity;
  bool sum = false;  // "sum:" over the matched elements
};
// The parts of `text`; kind "" (and the rest empty) when it does not parse. Never throws.
StudyTableSelector parse_table_selector(const std::string& text);

// The runs table of the study database at `db_path`. Throws StudyTableError:
// "<path>: study database not found", "<path>: not a study database: <why>" or, when the runs
// cannot be read, the store's own message.
StudyTable read_study_table(const std::string& db_path);

}  // namespace isopound
