// Study database -> plain table (see study_table.h): the store read once, read-only, and each
// output column's quantity taken from the study file's selectors while that file can be read.
#include "solver/study/study_table.h"

#include <filesystem>
#include <optional>

#include "solver/study/study_outputs.h"
#include "solver/study/study_spec.h"
#include "solver/study/study_store.h"

namespace isopound {
namespace {

// The selector and its quantity of each column of table.outputs ("" when the study file or its
// column is missing or does not parse): only the display of a value depends on them, so nothing
// here throws.
void selectors_from_study_file(const std::string& file, StudyTable& table) {
  const std::vector<std::string>& outputs = table.outputs;
  table.output_quantities.assign(outputs.size(), "");
  table.output_selectors.assign(outputs.size(), "");
  if (file.empty() || !std::filesystem::exists(file)) return;
  std::optional<Study> study;
  try {
    study.emplace(load_study_file(file));
  } catch (const std::exception&) {
    return;
  }
  for (std::size_t i = 0; i < outputs.size(); ++i)
    for (const OutputSpec& o : study->outputs) {
      if (o.column != outputs[i]) continue;
      try {
        table.output_quantities[i] = parse_output_selector(o.selector).quantity;
        table.output_selectors[i] = o.selector;
      } catch (const std::exception&) {
      }
      break;
    }
}

}  // namespace

StudyTableSelector parse_table_selector(const std::string& text) {
  StudyTableSelector out;
  out.text = text;
  OutputSelector s;
  try {
    s = parse_output_selector(text);
  } catch (const std::exception&) {
    return out;
  }
  switch (s.kind) {
    case OutputSelector::Kind::kLevel:
      out.kind = "level";
      break;
    case OutputSelector::Kind::kStory:
      out.kind = "story";
      break;
    case OutputSelector::Kind::kElement:
      out.kind = "element";
      break;
    case OutputSelector::Kind::kEnergy:
      out.kind = "energy";
      break;
    case OutputSelector::Kind::kGround:
      out.kind = "ground";
      break;
  }
  out.where = s.where;
  out.point = s.point;
  out.quantity = s.quantity;
  out.sum = s.sum;
  return out;
}

StudyTable read_study_table(const std::string& db_path) {
  using Reason = StudyTableError::Reason;
  if (!std::filesystem::exists(db_path))
    throw StudyTableError(Reason::missing, db_path + ": study database not found");
  std::optional<StudyStore> store;
  try {
    store.emplace(StudyStore::open(db_path, true));
  } catch (const std::exception& e) {
    throw StudyTableError(Reason::not_a_study, db_path + ": not a study database: " + e.what());
  }
  StudyTable table;
  table.axes = store->layout().axes;
  table.outputs = store->layout().outputs;
  std::string study_file;
  std::vector<RunRow> runs;
  try {
    study_file = store->meta("study_file");
    runs = store->read_runs();
  } catch (const StoreError& e) {
    throw StudyTableError(Reason::unreadable, e.what());
  }
  selectors_from_study_file(study_file, table);
  table.rows.reserve(runs.size());
  for (RunRow& r : runs) {
    StudyTableRow row;
    row.status = std::move(r.status);
    row.axes.reserve(r.axes.size());
    for (Cell& c : r.axes) row.axes.push_back({c.numeric, c.number, std::move(c.text)});
    row.values = std::move(r.values);
    table.rows.push_back(std::move(row));
  }
  return table;
}

}  // namespace isopound
