// A thin RAII layer over the SQLite C API: a connection, prepared statements with typed binds
// and column reads, and a BEGIN IMMEDIATE transaction guard. Errors throw StoreError.
#pragma once

#include <sqlite3.h>

#include <cstdint>
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>

namespace kontakt::server {

class StoreError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class SqliteDb {
 public:
  /// Opens (creating) the file in WAL mode with a busy timeout, foreign keys on and
  /// synchronous=NORMAL (transactions ask for more: Durability).
  explicit SqliteDb(const std::filesystem::path& file);
  ~SqliteDb();
  SqliteDb(const SqliteDb&) = delete;
  SqliteDb& operator=(const SqliteDb&) = delete;

  /// Runs one or more statements without results.
  void exec(const std::string& sql);
  sqlite3* handle() { return db_; }
  /// Rows changed by the last statement.
  int changes() const { return sqlite3_changes(db_); }

 private:
  sqlite3* db_ = nullptr;
};

class Statement {
 public:
  Statement(SqliteDb& db, std::string_view sql);
  ~Statement();
  Statement(const Statement&) = delete;
  Statement& operator=(const Statement&) = delete;

  /// Binds are 1-based, as in SQLite; an empty optional binds NULL.
  Statement& bind(int index, std::string_view text);
  Statement& bind(int index, std::int64_t value);
  Statement& bind(int index, double value);
  Statement& bind_optional(int index, const std::optional<std::string>& text);
  Statement& bind_null(int index);

  /// Advances to the next row: true while there is one.
  bool step();
  /// Runs a statement that returns no rows.
  void run();

  std::string text(int column) const;
  std::optional<std::string> optional_text(int column) const;
  std::int64_t integer(int column) const;
  double real(int column) const;
  bool is_null(int column) const;

 private:
  sqlite3* db_;
  sqlite3_stmt* stmt_ = nullptr;
};

/// How a commit survives an OS crash or power cut. Both survive the process being killed: in
/// WAL mode a commit is in the OS's hands before COMMIT returns.
enum class Durability {
  Flushed,  ///< synchronous=NORMAL: the last commits may be lost to a power cut (progress events)
  Synced,   ///< synchronous=FULL: fsync before COMMIT returns (jobs, status changes)
};

/// BEGIN IMMEDIATE on construction (takes the write lock up front, so a transaction never has
/// to upgrade from reading and hit SQLITE_BUSY), ROLLBACK unless commit() was called.
class WriteTransaction {
 public:
  explicit WriteTransaction(SqliteDb& db, Durability durability = Durability::Synced);
  ~WriteTransaction();
  WriteTransaction(const WriteTransaction&) = delete;
  WriteTransaction& operator=(const WriteTransaction&) = delete;
  void commit();

 private:
  SqliteDb& db_;
  Durability durability_;
  bool done_ = false;
};

}  // namespace kontakt::server
