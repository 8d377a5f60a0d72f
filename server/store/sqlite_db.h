// SQLite access for the gesture database: one connection (Database), prepared statements
// (Statement) and write transactions (WriteTransaction). Every SQL text the store runs goes through
// Database::prepare, which caches the compiled statement per connection — there is no way to run
// a string built from user input, so values always travel as bound parameters.
//
// Does not: share a connection between threads (the pool in store.h hands one to each caller),
// retry on SQLITE_BUSY by itself (the busy timeout set at open does that inside SQLite).
#pragma once

#include <sqlite3.h>

#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>

namespace sw::store {

// Thrown for failures of the database itself (disk full, corrupt file, locked past the busy
// timeout): the HTTP layer answers 500/503; bad input never reaches this path.
class DatabaseError : public std::runtime_error {
 public:
  DatabaseError(const std::string& what, int code) : std::runtime_error(what), code_(code) {}
  int code() const { return code_; }

 private:
  int code_;
};

class Statement {
 public:
  explicit Statement(sqlite3_stmt* stmt, sqlite3* db) : stmt_(stmt), db_(db) {}
  Statement(const Statement&) = delete;
  Statement& operator=(const Statement&) = delete;
  ~Statement();

  // Binding is 1-based as in SQLite. Text is bound with SQLITE_TRANSIENT (copied).
  Statement& bind(int index, std::int64_t value);
  Statement& bind(int index, int value) { return bind(index, static_cast<std::int64_t>(value)); }
  Statement& bind(int index, double value);
  Statement& bind(int index, std::string_view text);
  Statement& bind(int index, const char* text) { return bind(index, std::string_view(text)); }
  Statement& bind(int index, const std::string& text) { return bind(index, std::string_view(text)); }
  Statement& bind_null(int index);
  Statement& bind_optional(int index, const std::optional<std::string>& text);

  // Advances: true while a row is available, false when done. Throws DatabaseError otherwise.
  bool step();
  // Runs a statement that returns no rows.
  void run() {
    while (step()) {
    }
  }
  void reset();  // resets and clears bindings (done automatically when the statement is reused)

  std::int64_t column_int(int index) const;
  double column_double(int index) const;
  std::string column_text(int index) const;
  bool column_is_null(int index) const;
  int column_count() const { return sqlite3_column_count(stmt_); }

 private:
  sqlite3_stmt* stmt_;
  sqlite3* db_;
};

struct OpenOptions {
  // synchronous=FULL: a commit returns only after the WAL frame is fsync'ed, so an acknowledged
  // write survives kill -9 AND a power cut. Writes are rare (authoring), so the fsync per commit
  // costs nothing that matters; reads never fsync. (NORMAL+WAL would also survive kill -9 — the
  // WAL is in the OS page cache — but not a power cut; see docs/API.md "Durability".)
  bool synchronous_full = true;
  int busy_timeout_ms = 5000;  // how long a writer waits for another process's write lock
  bool read_only = false;
};

class Database {
 public:
  Database(const std::string& path, const OpenOptions& options);
  Database(const Database&) = delete;
  Database& operator=(const Database&) = delete;
  ~Database();

  // A prepared statement for `sql`, compiled once per connection and reset for reuse. The
  // returned reference is valid until the next prepare() of the same text on this connection —
  // callers finish with one use before starting another of the same SQL.
  Statement& prepare(const char* sql);
  // Runs SQL with no parameters and no result rows (schema, pragmas, BEGIN/COMMIT).
  void exec(const char* sql);
  std::int64_t last_insert_rowid() const;
  int changes() const;
  sqlite3* handle() { return db_; }
  const std::string& path() const { return path_; }

 private:
  sqlite3* db_ = nullptr;
  std::string path_;
  std::map<std::string, std::unique_ptr<Statement>, std::less<>> statements_;
};

// BEGIN IMMEDIATE ... COMMIT, rolled back by the destructor unless commit() ran. IMMEDIATE takes
// the write lock at the start, so a read-then-write (revision check, then update) cannot be
// interleaved with another writer: that is what makes the If-Match check free of lost updates.
class WriteTransaction {
 public:
  explicit WriteTransaction(Database& db);
  WriteTransaction(const WriteTransaction&) = delete;
  WriteTransaction& operator=(const WriteTransaction&) = delete;
  ~WriteTransaction();
  void commit();

 private:
  Database& db_;
  bool done_ = false;
};

// BEGIN (deferred) ... COMMIT for a consistent multi-statement read (a sign and its keywords).
class ReadTransaction {
 public:
  explicit ReadTransaction(Database& db);
  ReadTransaction(const ReadTransaction&) = delete;
  ReadTransaction& operator=(const ReadTransaction&) = delete;
  ~ReadTransaction();

 private:
  Database& db_;
};

}  // namespace sw::store
