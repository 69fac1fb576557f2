// Helpers of the study tests: run the isopound binary, scratch directories, read files, query a
// study database. Commands run through /bin/sh with stdout and stderr captured together.
#pragma once

#include <sqlite3.h>
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>

#include "tests/test_support.h"

namespace isopound::test {

inline std::filesystem::path study_scratch(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() /
                   ("isopound-study-" + name + "-" + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

inline std::string read_file(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

inline void write_file(const std::filesystem::path& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
}

// The first column of the first row of `sql`, as an integer (-1 on any error). Opens and
// closes the database each time (read-only; the sweep may be writing it).
inline long long query_int(const std::filesystem::path& db_path, const std::string& sql) {
  sqlite3* db = nullptr;
  long long value = -1;
  if (sqlite3_open_v2(db_path.c_str(), &db, SQLITE_OPEN_READONLY, nullptr) == SQLITE_OK) {
    sqlite3_busy_timeout(db, 5000);
    sqlite3_stmt* stmt = nullptr;
    if (sqlite3_prepare_v2(db, sql.c_str(), -1, &stmt, nullptr) == SQLITE_OK &&
        sqlite3_step(stmt) == SQLITE_ROW)
      value = sqlite3_column_int64(stmt, 0);
    sqlite3_finalize(stmt);
  }
  sqlite3_close(db);
  return value;
}

// The model every end-to-end study test starts from.
inline std::string thesis_model() {
  return (source_dir() / "configs" / "thesis-3storey-bw.yaml").string();
}

}  // namespace isopound::test
