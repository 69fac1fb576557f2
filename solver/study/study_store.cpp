// SQLite store of a study (schema in study_store.h). journal_mode=WAL with synchronous=NORMAL: a
// committed transaction survives the process being killed (SIGKILL); only power loss may lose the
// last ones.
#include "solver/study/study_store.h"

#include "solver/study/study_ensemble.h"

#include <algorithm>

#include "solver/study/study_outputs.h"

#include <cmath>
#include <ctime>
#include <filesystem>
#include <functional>
#include <limits>
#include <nlohmann/json.hpp>
#include <system_error>

namespace isopound {
namespace {

constexpr const char* kFormat = "isopound-study-1";

std::string quoted(const std::string& identifier) {
  std::string out = "\"";
  for (const char c : identifier) {
    if (c == '"') out += '"';
    out += c;
  }
  return out + "\"";
}

std::string utc_now() {
  const std::time_t now = std::time(nullptr);
  std::tm tm{};
  gmtime_r(&now, &tm);
  char buffer[32];
  std::strftime(buffer, sizeof buffer, "%Y-%m-%dT%H:%M:%SZ", &tm);
  return buffer;
}

// A prepared statement, finalized on scope exit.
class Statement {
 public:
  Statement(sqlite3* db, const std::string& sql,
            const std::function<void(const std::string&)>& fail)
      : fail_(fail) {
    if (sqlite3_prepare_v2(db, sql.c_str(), -1, &stmt_, nullptr) != SQLITE_OK)
      fail_(sqlite3_errmsg(db));
  }
  ~Statement() { sqlite3_finalize(stmt_); }
  Statement(const Statement&) = delete;
  Statement& operator=(const Statement&) = delete;

  void bind(int i, std::int64_t v) { check(sqlite3_bind_int64(stmt_, i, v)); }
  void bind(int i, double v) {
    check(std::isnan(v) ? sqlite3_bind_null(stmt_, i) : sqlite3_bind_double(stmt_, i, v));
  }
  void bind(int i, const std::string& v) {
    check(sqlite3_bind_text(stmt_, i, v.c_str(), static_cast<int>(v.size()), SQLITE_TRANSIENT));
  }
  void bind_null(int i) { check(sqlite3_bind_null(stmt_, i)); }
  // true while a row is available.
  bool step() {
    const int rc = sqlite3_step(stmt_);
    if (rc == SQLITE_ROW) return true;
    if (rc != SQLITE_DONE) fail_(sqlite3_errmsg(sqlite3_db_handle(stmt_)));
    return false;
  }
  void reset() {
    sqlite3_reset(stmt_);
    sqlite3_clear_bindings(stmt_);
  }
  sqlite3_stmt* get() const { return stmt_; }

 private:
  void check(int rc) {
    if (rc != SQLITE_OK) fail_(sqlite3_errmsg(sqlite3_db_handle(stmt_)));
  }
  sqlite3_stmt* stmt_ = nullptr;
  std::function<void(const std::string&)> fail_;
};

std::string column_text(sqlite3_stmt* s, int i) {
  const unsigned char* text = sqlite3_column_text(s, i);
  return text ? reinterpret_cast<const char*>(text) : "";
}

}  // namespace

std::string StoreLayout::to_json() const {
  nlohmann::json j;
  j["axes"] = axes;
  j["outputs"] = outputs;
  j["axis_units"] = axis_units;
  j["output_units"] = output_units;
  j["ratios"] = nlohmann::json::array();
  for (const RatioSpec& r : ratios)
    j["ratios"].push_back({{"name", r.name},
                           {"axis", r.axis},
                           {"numerator", r.numerator},
                           {"denominator", r.denominator}});
  j["statistics"] = nlohmann::json::array();
  for (const StatisticsSpec& s : statistics)
    j["statistics"].push_back({{"over", s.over}, {"std", s.sample_std ? "sample" : "population"}});
  return j.dump();
}

StoreLayout StoreLayout::from_json(const std::string& text) {
  const nlohmann::json j = nlohmann::json::parse(text);
  StoreLayout l;
  l.axes = j.at("axes").get<std::vector<std::string>>();
  l.outputs = j.at("outputs").get<std::vector<std::string>>();
  if (j.contains("axis_units")) l.axis_units = j.at("axis_units").get<std::vector<std::string>>();
  if (j.contains("output_units"))
    l.output_units = j.at("output_units").get<std::vector<std::string>>();
  for (const auto& r : j.at("ratios"))
    l.ratios.push_back({r.at("name"), r.at("axis"), r.at("numerator"), r.at("denominator")});
  for (const auto& s : j.at("statistics"))
    l.statistics.push_back({s.at("over").get<std::vector<std::string>>(), s.at("std") == "sample"});
  return l;
}

StoreLayout StoreLayout::of(const Study& study) {
  StoreLayout l;
  for (const Axis& a : study.axes) {
    l.axes.push_back(a.name);
    const bool numeric = !a.levels.empty() && std::all_of(a.levels.begin(), a.levels.end(),
                                                          [](const Level& v) { return v.numeric; });
    l.axis_units.push_back(numeric ? "SI" : "label");
  }
  for (const OutputSpec& o : study.outputs) {
    l.outputs.push_back(o.column);
    l.output_units.push_back(output_unit(parse_output_selector(o.selector)));
  }
  if (study.ensemble >= 2) {  // study_ensemble.h
    const std::vector<std::string> names = ensemble_column_names(l.outputs);
    const std::vector<std::string> units = ensemble_column_units(l.output_units);
    l.outputs.insert(l.outputs.end(), names.begin(), names.end());
    l.output_units.insert(l.output_units.end(), units.begin(), units.end());
  }
  l.ratios = study.ratios;
  l.statistics = study.statistics;
  return l;
}

StudyStore::StudyStore(std::unique_ptr<sqlite3, Closer> db, std::string path)
    : db_(std::move(db)), path_(std::move(path)) {}

StudyStore::~StudyStore() = default;

void StudyStore::fail(const std::string& what) const {
  throw StoreError(path_ + ": " + what);
}

void StudyStore::execute(const std::string& sql) const {
  char* message = nullptr;
  if (sqlite3_exec(db_.get(), sql.c_str(), nullptr, nullptr, &message) != SQLITE_OK) {
    const std::string text = message ? message : "unknown SQLite error";
    sqlite3_free(message);
    fail(text);
  }
}

StudyStore StudyStore::create(const std::string& path, const StoreLayout& layout,
                              const std::map<std::string, std::string>& meta,
                              std::int64_t case_count,
                              const std::function<std::vector<Cell>(std::int64_t)>& labels) {
  std::error_code ec;
  if (std::filesystem::exists(path, ec)) throw StoreError(path + ": already exists");
  sqlite3* raw = nullptr;
  const int rc =
      sqlite3_open_v2(path.c_str(), &raw,
                      SQLITE_OPEN_READWRITE | SQLITE_OPEN_CREATE | SQLITE_OPEN_NOMUTEX, nullptr);
  std::unique_ptr<sqlite3, Closer> db(raw);
  if (rc != SQLITE_OK)
    throw StoreError(
        path + ": cannot create the database: " + (raw ? sqlite3_errmsg(raw) : "out of memory"));
  StudyStore store(std::move(db), path);
  store.layout_ = layout;
  // The busy timeout first: a reader that opens the new file (a user watching the study start)
  // holds a lock for a moment, and switching to WAL without waiting failed the sweep.
  store.execute("PRAGMA busy_timeout=10000; PRAGMA journal_mode=WAL; PRAGMA synchronous=NORMAL;");
  std::string runs = "CREATE TABLE runs(case_id INTEGER PRIMARY KEY";
  for (const std::string& a : layout.axes) runs += ", " + quoted(a);
  runs +=
      ", status TEXT NOT NULL DEFAULT 'pending', steps INTEGER, wall_seconds REAL, session INTEGER";
  for (const std::string& o : layout.outputs) runs += ", " + quoted(o) + " REAL";
  runs += ", error TEXT)";
  store.execute("BEGIN");
  store.execute("CREATE TABLE meta(key TEXT PRIMARY KEY, value TEXT NOT NULL)");
  store.execute(runs);
  store.execute("CREATE INDEX runs_status ON runs(status)");
  // Every column of runs with its unit (outputs SI; numeric axes SI; counts and ratios "-").
  store.execute("CREATE TABLE units(column_name TEXT PRIMARY KEY, unit TEXT NOT NULL)");
  {
    const auto fail_units = [&](const std::string& what) { store.fail(what); };
    Statement put(store.db_.get(), "INSERT INTO units(column_name, unit) VALUES(?, ?)", fail_units);
    const auto add = [&](const std::string& column, const std::string& unit) {
      put.bind(1, column);
      put.bind(2, unit);
      put.step();
      put.reset();
    };
    for (std::size_t i = 0; i < layout.axes.size(); ++i)
      add(layout.axes[i], i < layout.axis_units.size() ? layout.axis_units[i] : "");
    for (std::size_t i = 0; i < layout.outputs.size(); ++i)
      add(layout.outputs[i], i < layout.output_units.size() ? layout.output_units[i] : "");
    add("steps", "-");
    add("wall_seconds", "s");
  }
  store.execute(
      "CREATE TABLE sessions(session INTEGER PRIMARY KEY, started_utc TEXT, jobs INTEGER, ranks "
      "INTEGER, "
      "resumed INTEGER, runs_to_do INTEGER)");
  store.execute(
      "CREATE TABLE computations(id INTEGER PRIMARY KEY, case_id INTEGER NOT NULL, session INTEGER "
      "NOT NULL, "
      "rank INTEGER NOT NULL)");
  const auto fail = [&](const std::string& what) { store.fail(what); };
  {
    Statement put(store.db_.get(), "INSERT INTO meta(key, value) VALUES(?, ?)", fail);
    std::map<std::string, std::string> all = meta;
    all["format"] = kFormat;
    all["layout"] = layout.to_json();
    all["case_count"] = std::to_string(case_count);
    all["created_utc"] = utc_now();
    for (const auto& [key, value] : all) {
      put.bind(1, key);
      put.bind(2, value);
      put.step();
      put.reset();
    }
  }
  {
    std::string sql = "INSERT INTO runs(case_id";
    for (const std::string& a : layout.axes) sql += ", " + quoted(a);
    sql += ") VALUES(?";
    for (std::size_t i = 0; i < layout.axes.size(); ++i) sql += ", ?";
    sql += ")";
    Statement insert(store.db_.get(), sql, fail);
    for (std::int64_t c = 0; c < case_count; ++c) {
      insert.bind(1, c);
      const std::vector<Cell> cells = labels(c);
      for (std::size_t i = 0; i < cells.size(); ++i) {
        if (cells[i].numeric)
          insert.bind(static_cast<int>(i) + 2, cells[i].number);
        else
          insert.bind(static_cast<int>(i) + 2, cells[i].text);
      }
      insert.step();
      insert.reset();
    }
  }
  store.execute("COMMIT");
  return store;
}

StudyStore StudyStore::open(const std::string& path, bool read_only) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) throw StoreError(path + ": no such database");
  sqlite3* raw = nullptr;
  const int flags =
      (read_only ? SQLITE_OPEN_READONLY : SQLITE_OPEN_READWRITE) | SQLITE_OPEN_NOMUTEX;
  const int rc = sqlite3_open_v2(path.c_str(), &raw, flags, nullptr);
  std::unique_ptr<sqlite3, Closer> db(raw);
  if (rc != SQLITE_OK)
    throw StoreError(
        path + ": cannot open the database: " + (raw ? sqlite3_errmsg(raw) : "out of memory"));
  StudyStore store(std::move(db), path);
  store.execute("PRAGMA busy_timeout=10000;");
  if (!read_only) store.execute("PRAGMA journal_mode=WAL; PRAGMA synchronous=NORMAL;");
  std::string format;
  try {
    format = store.meta("format");
  } catch (const StoreError&) {
    throw StoreError(path + ": not an isopound study database");
  }
  if (format != kFormat)
    throw StoreError(path + ": not an isopound study database (format '" + format + "')");
  try {
    store.layout_ = StoreLayout::from_json(store.meta("layout"));
  } catch (const std::exception& e) {
    throw StoreError(path + ": damaged layout in meta: " + e.what());
  }
  return store;
}

bool StudyStore::has_schema(const std::string& path) {
  sqlite3* raw = nullptr;
  const int rc = sqlite3_open_v2(path.c_str(), &raw, SQLITE_OPEN_READONLY, nullptr);
  std::unique_ptr<sqlite3, Closer> db(raw);
  if (rc != SQLITE_OK) return true;  // let open() report the problem
  sqlite3_stmt* stmt = nullptr;
  bool tables = true;
  if (sqlite3_prepare_v2(raw, "SELECT COUNT(*) FROM sqlite_master", -1, &stmt, nullptr) ==
          SQLITE_OK &&
      sqlite3_step(stmt) == SQLITE_ROW)
    tables = sqlite3_column_int64(stmt, 0) > 0;
  sqlite3_finalize(stmt);
  return tables;
}

std::string StudyStore::meta(const std::string& key) const {
  Statement get(db_.get(), "SELECT value FROM meta WHERE key = ?",
                [&](const std::string& w) { fail(w); });
  get.bind(1, key);
  return get.step() ? column_text(get.get(), 0) : "";
}

std::int64_t StudyStore::case_count() const {
  Statement count(db_.get(), "SELECT COUNT(*) FROM runs", [&](const std::string& w) { fail(w); });
  count.step();
  return sqlite3_column_int64(count.get(), 0);
}

std::int64_t StudyStore::count_with_status(const std::string& status) const {
  Statement count(db_.get(), "SELECT COUNT(*) FROM runs WHERE status = ?",
                  [&](const std::string& w) { fail(w); });
  count.bind(1, status);
  count.step();
  return sqlite3_column_int64(count.get(), 0);
}

std::vector<std::int64_t> StudyStore::unfinished_cases() const {
  Statement get(db_.get(), "SELECT case_id FROM runs WHERE status = 'pending' ORDER BY case_id",
                [&](const std::string& w) { fail(w); });
  std::vector<std::int64_t> out;
  while (get.step()) out.push_back(sqlite3_column_int64(get.get(), 0));
  return out;
}

std::int64_t StudyStore::begin_session(int jobs, int ranks, bool resumed, std::int64_t runs_to_do) {
  Statement add(
      db_.get(),
      "INSERT INTO sessions(started_utc, jobs, ranks, resumed, runs_to_do) VALUES(?, ?, ?, ?, ?)",
      [&](const std::string& w) { fail(w); });
  add.bind(1, utc_now());
  add.bind(2, static_cast<std::int64_t>(jobs));
  add.bind(3, static_cast<std::int64_t>(ranks));
  add.bind(4, static_cast<std::int64_t>(resumed ? 1 : 0));
  add.bind(5, runs_to_do);
  add.step();
  return sqlite3_last_insert_rowid(db_.get());
}

void StudyStore::commit(const std::vector<RunRecord>& runs, std::int64_t session) {
  if (runs.empty()) return;
  const auto fail_with = [&](const std::string& w) { fail(w); };
  std::string sql =
      "UPDATE runs SET status = ?, steps = ?, wall_seconds = ?, session = ?, error = ?";
  for (const std::string& o : layout_.outputs) sql += ", " + quoted(o) + " = ?";
  sql += " WHERE case_id = ?";
  execute("BEGIN IMMEDIATE");
  try {
    Statement update(db_.get(), sql, fail_with);
    Statement log(db_.get(), "INSERT INTO computations(case_id, session, rank) VALUES(?, ?, ?)",
                  fail_with);
    for (const RunRecord& run : runs) {
      update.bind(1, std::string(run.ok ? "done" : "failed"));
      update.bind(2, run.steps);
      update.bind(3, run.wall_seconds);
      update.bind(4, session);
      if (run.error.empty())
        update.bind_null(5);
      else
        update.bind(5, run.error);
      for (std::size_t k = 0; k < layout_.outputs.size(); ++k) {
        const double v = run.ok && k < run.values.size() ? run.values[k]
                                                         : std::numeric_limits<double>::quiet_NaN();
        update.bind(static_cast<int>(k) + 6, v);
      }
      update.bind(static_cast<int>(layout_.outputs.size()) + 6, run.case_id);
      update.step();
      update.reset();
      if (run.computed) {
        log.bind(1, run.case_id);
        log.bind(2, session);
        log.bind(3, static_cast<std::int64_t>(run.rank));
        log.step();
        log.reset();
      }
    }
  } catch (...) {
    sqlite3_exec(db_.get(), "ROLLBACK", nullptr, nullptr, nullptr);
    throw;
  }
  execute("COMMIT");
}

std::vector<RunRow> StudyStore::read_runs() const {
  std::string sql = "SELECT case_id";
  for (const std::string& a : layout_.axes) sql += ", " + quoted(a);
  sql += ", status, steps, wall_seconds";
  for (const std::string& o : layout_.outputs) sql += ", " + quoted(o);
  sql += ", error FROM runs ORDER BY case_id";
  Statement get(db_.get(), sql, [&](const std::string& w) { fail(w); });
  std::vector<RunRow> rows;
  const int axes = static_cast<int>(layout_.axes.size());
  const int outputs = static_cast<int>(layout_.outputs.size());
  sqlite3_stmt* s = get.get();
  while (get.step()) {
    RunRow row;
    row.case_id = sqlite3_column_int64(s, 0);
    for (int i = 0; i < axes; ++i) {
      Cell cell;
      const int type = sqlite3_column_type(s, 1 + i);
      cell.numeric = type == SQLITE_FLOAT || type == SQLITE_INTEGER;
      if (cell.numeric)
        cell.number = sqlite3_column_double(s, 1 + i);
      else
        cell.text = column_text(s, 1 + i);
      row.axes.push_back(std::move(cell));
    }
    row.status = column_text(s, 1 + axes);
    row.steps =
        sqlite3_column_type(s, 2 + axes) == SQLITE_NULL ? -1 : sqlite3_column_int64(s, 2 + axes);
    row.wall_seconds = sqlite3_column_double(s, 3 + axes);
    for (int k = 0; k < outputs; ++k) {
      const int column = 4 + axes + k;
      row.values.push_back(sqlite3_column_type(s, column) == SQLITE_NULL
                               ? std::numeric_limits<double>::quiet_NaN()
                               : sqlite3_column_double(s, column));
    }
    row.error = column_text(s, 4 + axes + outputs);
    rows.push_back(std::move(row));
  }
  return rows;
}

}  // namespace isopound
