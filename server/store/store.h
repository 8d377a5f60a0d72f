// Store: the gesture database behind the server and `signweave import`. It owns the SQLite file
// (WAL, foreign keys, busy timeout, synchronous=FULL), a pool of connections (one per concurrent
// caller; WAL lets readers run beside the single writer), the in-memory search index, and every
// operation the API offers: languages, signs with revisions and optimistic concurrency, search,
// phrase lookup, bulk import, API tokens, health.
//
// Every write runs in one BEGIN IMMEDIATE transaction and validates the notation first
// (sign_validation.h). Refusals are ApiError (status + message + detail); database failures are
// DatabaseError.
//
// Does not: authenticate (the HTTP layer checks tokens with verify_token before calling a write),
// or cache sign JSON (SQLite's page cache and prepared statements make a fetch a few microseconds).
#pragma once

#include <cstdint>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "store/search_index.h"
#include "store/sign_record.h"
#include "store/sqlite_db.h"

namespace sw::store {

struct StoreOptions {
  bool synchronous_full = true;  // see OpenOptions::synchronous_full
  int busy_timeout_ms = 5000;
};

// One line of a bulk import: a sign (with its language possibly from the file) and where it came
// from, for error messages.
struct ImportItem {
  std::string source;  // file name or "request body"
  int line = 0;        // 1-based
  nlohmann::json sign; // the parsed JSON object of the line
  std::string default_language;  // used when the line has no "language"
};

struct ImportRejection {
  std::string source;
  int line = 0;
  int status = 400;
  std::string message;
  nlohmann::json detail;
};

struct ImportReport {
  int created = 0;
  int updated = 0;
  int unchanged = 0;
  std::vector<ImportRejection> rejected;
  bool committed = false;
};

enum class ImportMode {
  AllOrNothing,  // any rejected line: nothing is written (the HTTP bulk import)
  SkipInvalid,   // write the valid lines, report the rest (first start from data/, the CLI default)
  CheckOnly,     // validate every line and report; write nothing (a dry run)
};

struct TokenCheck {
  enum class Result { Valid, Malformed, Unknown } result = Result::Unknown;
  std::string name;  // the token's name when Valid (recorded as the author of revisions)
};

class Store {
 public:
  // Opens (creating if needed) and migrates the database file.
  static std::unique_ptr<Store> open(const std::string& path, const StoreOptions& options = {});
  ~Store();

  const std::string& path() const { return path_; }
  int schema_version() const { return schema_version_; }

  // --- languages
  std::vector<Language> languages();
  std::optional<Language> language(const std::string& code);
  void upsert_languages(const std::vector<Language>& languages);

  // --- signs
  // The sign with `id`, deleted ones included (deleted = true). nullopt if no such id.
  std::optional<SignRecord> get_sign(std::int64_t id);
  SignRecord create_sign(const SignInput& input, const std::string& author);
  // Throws ApiError 404 (no sign), 410 (deleted), 409 (expected_revision is not current, detail
  // carries current_revision).
  SignRecord update_sign(std::int64_t id, std::int64_t expected_revision, const SignInput& input,
                         const std::string& author);
  SignRecord delete_sign(std::int64_t id, std::int64_t expected_revision, const std::string& author);
  std::vector<RevisionRecord> history(std::int64_t id);
  // meta.content_generation: moves with every committed change to signs, keywords or alphabets
  // (by this process or another), so anything derived from them can be cached against it.
  std::int64_t content_generation();
  std::int64_t count_live_signs();

  // --- search and lookup (search_index.h has the ranking)
  // Loads the word-form dictionaries of every language and builds the index, so that the first
  // search does not wait for them (uk_UA takes about a second): the server calls it at start.
  void prepare_search();
  SearchPage search(const SearchQuery& query);
  LookupResult lookup(const std::string& text, const std::string& language);

  // --- bulk import
  ImportReport import_items(const std::vector<ImportItem>& items, const std::string& author,
                            ImportMode mode);

  // --- API tokens: the plain token is returned once and never stored (salted SHA-256 only).
  // `chosen` (optional, at least 16 bytes) registers a token the admin picked (the
  // SIGNWEAVE_ADMIN_TOKEN variable) instead of generating one.
  std::string create_token(const std::string& name, const std::string& chosen = "");
  TokenCheck verify_token(const std::string& token);
  std::int64_t count_tokens();
  bool has_token_value(const std::string& token);

  // --- operations
  bool integrity_check(std::string* detail);
  std::int64_t database_size_bytes();
  void checkpoint();  // PRAGMA wal_checkpoint(TRUNCATE): on graceful shutdown
  // A hash of every table's content, for tests that must prove a refused request changed nothing.
  std::string content_fingerprint();

 private:
  Store(std::string path, const StoreOptions& options);

  // A connection leased from the pool for the lifetime of the lease.
  class Lease {
   public:
    Lease(Store& store, std::unique_ptr<Database> db) : store_(store), db_(std::move(db)) {}
    Lease(const Lease&) = delete;
    Lease& operator=(const Lease&) = delete;
    ~Lease();
    Database& operator*() { return *db_; }
    Database* operator->() { return db_.get(); }

   private:
    Store& store_;
    std::unique_ptr<Database> db_;
  };
  Lease lease();

  std::shared_ptr<const SearchIndex> current_index(Database& db);
  std::optional<SignRecord> read_sign(Database& db, std::int64_t id);
  // Writes `input` as sign `existing_id` (0: a new sign) inside the caller's transaction.
  SignRecord write_sign(Database& db, std::int64_t existing_id, const SignInput& input,
                        const std::string& language, const std::string& format,
                        const std::optional<std::string>& compiled, const std::string& author);
  void record_revision(Database& db, const SignRecord& sign, const char* op,
                       const std::string& author);
  void bump_generation(Database& db);
  std::string language_spoken_or_throw(Database& db, const std::string& code);

  std::string path_;
  StoreOptions options_;
  int schema_version_ = 0;

  std::mutex pool_mutex_;
  std::vector<std::unique_ptr<Database>> idle_;

  // One writer at a time inside this process: SQLite would serialise them anyway, but waiting on
  // a mutex is cheaper and fairer than spinning in the busy handler.
  std::mutex write_mutex_;

  std::mutex index_mutex_;
  std::shared_ptr<const SearchIndex> index_;
};

}  // namespace sw::store
