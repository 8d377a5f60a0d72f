// The gesture database operations (see store.h).
#include "store/store.h"

#include <sys/stat.h>

#include <algorithm>
#include <random>
#include <unordered_map>

#include "store/api_error.h"
#include "store/migrations.h"
#include "store/sha256.h"
#include "store/sign_json.h"
#include "store/sign_validation.h"
#include "store/utf8_text.h"
#include "store/word_forms.h"

namespace sw::store {
namespace {

using nlohmann::json;

// Idle connections kept for reuse. Why 128: the HTTP server's default worker count, so that under
// full load no request pays for opening a connection and compiling its statements again; more
// idle handles would only hold file descriptors and page caches nobody uses.
constexpr std::size_t kMaxIdleConnections = 128;

std::string letter_kind(const std::string& letter) {
  std::vector<char32_t> cps = decode_utf8(letter);
  bool digits = !cps.empty() && std::all_of(cps.begin(), cps.end(), [](char32_t c) {
    return c >= '0' && c <= '9';
  });
  return digits ? "digit" : "letter";
}

std::vector<std::string> parse_tags(const std::string& text) {
  json tags = json::parse(text, nullptr, false);
  std::vector<std::string> out;
  if (tags.is_array()) {
    for (const json& tag : tags) {
      if (tag.is_string()) out.push_back(tag.get<std::string>());
    }
  }
  return out;
}

// The content an import compares to decide "unchanged": keywords by their normalised word.
json comparable_content(const std::string& gloss, const std::string& notation,
                        const std::string& format, const std::vector<std::string>& tags,
                        const std::vector<KeywordEntry>& keywords, const std::string& sense,
                        const std::string& description, bool starter,
                        const std::optional<std::string>& letter) {
  json words = json::array();
  for (const KeywordEntry& keyword : keywords) {
    words.push_back(json::array({normalize_for_match(keyword.word),
                                 keyword.sense.empty() ? sense : keyword.sense}));
  }
  return json{{"gloss", gloss}, {"notation", notation}, {"format", format}, {"tags", tags},
              {"keywords", words}, {"sense", sense}, {"description", description},
              {"starter", starter},
              {"letter", letter ? json(*letter) : json(nullptr)}};
}

std::string random_bytes_hex(std::size_t count) {
  std::random_device device;  // getrandom(2) on Linux: suitable for secrets
  std::vector<std::uint8_t> bytes(count);
  for (std::size_t i = 0; i < count; i += 4) {
    std::uint32_t value = device();
    for (std::size_t k = 0; k < 4 && i + k < count; ++k) bytes[i + k] = static_cast<std::uint8_t>(value >> (8 * k));
  }
  return to_hex(bytes.data(), bytes.size());
}

struct PreparedSign {
  SignInput input;
  std::string language;
  ValidatedNotation validated;
  const ImportItem* item;
};

}  // namespace

// ------------------------------------------------------------------------------------------------
// Opening and connections

Store::Store(std::string path, const StoreOptions& options)
    : path_(std::move(path)), options_(options) {}

Store::~Store() = default;

std::unique_ptr<Store> Store::open(const std::string& path, const StoreOptions& options) {
  std::unique_ptr<Store> store(new Store(path, options));
  OpenOptions open_options;
  open_options.synchronous_full = options.synchronous_full;
  open_options.busy_timeout_ms = options.busy_timeout_ms;
  auto db = std::make_unique<Database>(path, open_options);
  store->schema_version_ = migrate(*db);
  store->idle_.push_back(std::move(db));
  return store;
}

Store::Lease::~Lease() {
  if (!db_) return;
  if (!sqlite3_get_autocommit(db_->handle())) {
    // A transaction left open by an exception path: roll back before reuse.
    sqlite3_exec(db_->handle(), "ROLLBACK", nullptr, nullptr, nullptr);
  }
  std::lock_guard<std::mutex> lock(store_.pool_mutex_);
  if (store_.idle_.size() < kMaxIdleConnections) store_.idle_.push_back(std::move(db_));
}

Store::Lease Store::lease() {
  {
    std::lock_guard<std::mutex> lock(pool_mutex_);
    if (!idle_.empty()) {
      std::unique_ptr<Database> db = std::move(idle_.back());
      idle_.pop_back();
      return Lease(*this, std::move(db));
    }
  }
  OpenOptions open_options;
  open_options.synchronous_full = options_.synchronous_full;
  open_options.busy_timeout_ms = options_.busy_timeout_ms;
  return Lease(*this, std::make_unique<Database>(path_, open_options));
}

void Store::bump_generation(Database& db) {
  db.prepare("UPDATE meta SET value = value + 1 WHERE key = 'content_generation'").run();
}

std::shared_ptr<const SearchIndex> Store::current_index(Database& db) {
  auto read_generation = [&db]() {
    Statement& query = db.prepare("SELECT value FROM meta WHERE key = 'content_generation'");
    std::int64_t generation = query.step() ? query.column_int(0) : 0;
    query.reset();
    return generation;
  };
  std::int64_t generation = read_generation();
  std::lock_guard<std::mutex> lock(index_mutex_);
  if (index_ && index_->generation() == generation) return index_;
  ReadTransaction snapshot(db);
  generation = read_generation();  // the generation of the snapshot actually read
  index_ = std::make_shared<const SearchIndex>(SearchIndex::build(db, generation));
  return index_;
}

// ------------------------------------------------------------------------------------------------
// Languages

std::vector<Language> Store::languages() {
  Lease db = lease();
  Statement& query = db->prepare(
      "SELECT code, name, spoken, alphabet_script FROM languages ORDER BY code");
  std::vector<Language> out;
  while (query.step()) {
    out.push_back(Language{query.column_text(0), query.column_text(1), query.column_text(2),
                           query.column_text(3)});
  }
  query.reset();
  return out;
}

std::optional<Language> Store::language(const std::string& code) {
  Lease db = lease();
  Statement& query = db->prepare(
      "SELECT code, name, spoken, alphabet_script FROM languages WHERE code = ?");
  query.bind(1, code);
  std::optional<Language> out;
  if (query.step()) {
    out = Language{query.column_text(0), query.column_text(1), query.column_text(2),
                   query.column_text(3)};
  }
  query.reset();
  return out;
}

void Store::upsert_languages(const std::vector<Language>& languages) {
  std::lock_guard<std::mutex> writer(write_mutex_);
  Lease db = lease();
  WriteTransaction transaction(*db);
  for (const Language& language : languages) {
    db->prepare(
          "INSERT INTO languages (code, name, spoken, alphabet_script) VALUES (?, ?, ?, ?) "
          "ON CONFLICT(code) DO UPDATE SET name = excluded.name, spoken = excluded.spoken, "
          "alphabet_script = excluded.alphabet_script")
        .bind(1, language.code)
        .bind(2, language.name)
        .bind(3, language.spoken)
        .bind(4, language.alphabet_script)
        .run();
  }
  bump_generation(*db);
  transaction.commit();
}

std::string Store::language_spoken_or_throw(Database& db, const std::string& code) {
  Statement& query = db.prepare("SELECT spoken FROM languages WHERE code = ?");
  query.bind(1, code);
  if (!query.step()) {
    query.reset();
    throw ApiError(422, "unknown sign language '" + code + "' (GET /api/languages lists them)",
                   json{{"field", "language"}, {"value", code}});
  }
  std::string spoken = query.column_text(0);
  query.reset();
  return spoken;
}

// ------------------------------------------------------------------------------------------------
// Signs

std::optional<SignRecord> Store::read_sign(Database& db, std::int64_t id) {
  Statement& query = db.prepare(
      "SELECT s.id, s.language, s.gloss, s.notation, s.format, s.tags, s.sense, s.compiled, "
      "s.revision, s.deleted, s.created_at, s.updated_at, "
      "(SELECT a.letter FROM alphabet a WHERE a.sign_id = s.id LIMIT 1), s.description, s.starter "
      "FROM signs s WHERE s.id = ?");
  query.bind(1, id);
  if (!query.step()) {
    query.reset();
    return std::nullopt;
  }
  SignRecord sign;
  sign.id = query.column_int(0);
  sign.language = query.column_text(1);
  sign.gloss = query.column_text(2);
  sign.notation = query.column_text(3);
  sign.format = query.column_text(4);
  sign.tags = parse_tags(query.column_text(5));
  sign.sense = query.column_text(6);
  if (!query.column_is_null(7)) sign.compiled = query.column_text(7);
  sign.revision = query.column_int(8);
  sign.deleted = query.column_int(9) != 0;
  sign.created_at = query.column_text(10);
  sign.updated_at = query.column_text(11);
  if (!query.column_is_null(12)) sign.letter = query.column_text(12);
  sign.description = query.column_text(13);
  sign.starter = query.column_int(14) != 0;
  query.reset();

  Statement& keywords = db.prepare(
      "SELECT k.word, sk.sense FROM sign_keywords sk JOIN keywords k ON k.id = sk.keyword_id "
      "WHERE sk.sign_id = ? ORDER BY sk.position");
  keywords.bind(1, id);
  while (keywords.step()) sign.keywords.push_back(KeywordEntry{keywords.column_text(0), keywords.column_text(1)});
  keywords.reset();
  return sign;
}

std::optional<SignRecord> Store::get_sign(std::int64_t id) {
  Lease db = lease();
  ReadTransaction snapshot(*db);  // the row and its keywords from one snapshot
  return read_sign(*db, id);
}

std::int64_t Store::count_live_signs() {
  Lease db = lease();
  Statement& query = db->prepare("SELECT COUNT(*) FROM signs WHERE deleted = 0");
  std::int64_t count = query.step() ? query.column_int(0) : 0;
  query.reset();
  return count;
}

SignRecord Store::write_sign(Database& db, std::int64_t existing_id, const SignInput& input,
                             const std::string& language, const std::string& format,
                             const std::optional<std::string>& compiled, const std::string& author) {
  std::string spoken = language_spoken_or_throw(db, language);

  // A live gloss is unique per language; name the holder so the author can edit it instead.
  {
    Statement& holder = db.prepare(
        "SELECT id FROM signs WHERE language = ? AND gloss = ? AND deleted = 0 AND id != ?");
    holder.bind(1, language).bind(2, input.gloss).bind(3, existing_id);
    if (holder.step()) {
      std::int64_t other = holder.column_int(0);
      holder.reset();
      throw ApiError(409, "sign language '" + language + "' already has a sign glossed '" +
                              input.gloss + "' (id " + std::to_string(other) + ")",
                     json{{"field", "gloss"}, {"existing_id", other}});
    }
    holder.reset();
  }
  if (input.letter) {
    Statement& holder = db.prepare(
        "SELECT sign_id FROM alphabet WHERE language = ? AND letter = ? AND sign_id != ?");
    holder.bind(1, language).bind(2, *input.letter).bind(3, existing_id);
    if (holder.step()) {
      std::int64_t other = holder.column_int(0);
      holder.reset();
      throw ApiError(409, "the " + language + " alphabet already has a sign for '" + *input.letter +
                              "' (id " + std::to_string(other) + ")",
                     json{{"field", "letter"}, {"existing_id", other}});
    }
    holder.reset();
  }

  std::string tags = json(input.tags).dump();
  std::string gloss_norm = normalize_for_match(input.gloss);
  std::int64_t id = existing_id;
  // Parameters 1..10 are the same columns, in the same order, in the INSERT and the UPDATE.
  auto bind_sign_columns = [&](Statement& st) -> Statement& {
    return st.bind(1, language)
        .bind(2, input.gloss)
        .bind(3, gloss_norm)
        .bind(4, input.notation)
        .bind(5, format)
        .bind(6, tags)
        .bind(7, input.sense)
        .bind_optional(8, compiled)
        .bind(9, input.description)
        .bind(10, input.starter ? 1 : 0);
  };
  if (existing_id == 0) {
    Statement& insert = db.prepare(
          "INSERT INTO signs (language, gloss, gloss_norm, notation, format, tags, sense, compiled, "
          "description, starter, revision, created_at, updated_at) VALUES (?, ?, ?, ?, ?, ?, ?, ?, ?, ?, 1, "
          "strftime('%Y-%m-%dT%H:%M:%fZ', 'now'), strftime('%Y-%m-%dT%H:%M:%fZ', 'now'))");
    bind_sign_columns(insert).run();
    id = db.last_insert_rowid();
  } else {
    Statement& update = db.prepare(
          "UPDATE signs SET language = ?, gloss = ?, gloss_norm = ?, notation = ?, format = ?, "
          "tags = ?, sense = ?, compiled = ?, description = ?, starter = ?, revision = revision + 1, "
          "updated_at = strftime('%Y-%m-%dT%H:%M:%fZ', 'now') WHERE id = ?");
    bind_sign_columns(update).bind(11, id).run();
    db.prepare("DELETE FROM sign_keywords WHERE sign_id = ?").bind(1, id).run();
    db.prepare("DELETE FROM alphabet WHERE sign_id = ?").bind(1, id).run();
  }

  int position = 0;
  std::vector<std::string> seen;
  for (const KeywordEntry& keyword : input.keywords) {
    std::string norm = normalize_for_match(keyword.word);
    if (std::find(seen.begin(), seen.end(), norm) != seen.end()) continue;  // listed twice
    seen.push_back(norm);
    db.prepare(
          "INSERT INTO keywords (spoken, word, word_norm) VALUES (?, ?, ?) "
          "ON CONFLICT(spoken, word_norm) DO NOTHING")
        .bind(1, spoken)
        .bind(2, keyword.word)
        .bind(3, norm)
        .run();
    Statement& find = db.prepare("SELECT id FROM keywords WHERE spoken = ? AND word_norm = ?");
    find.bind(1, spoken).bind(2, norm);
    find.step();
    std::int64_t keyword_id = find.column_int(0);
    find.reset();
    db.prepare("INSERT INTO sign_keywords (sign_id, keyword_id, sense, position) VALUES (?, ?, ?, ?)")
        .bind(1, id)
        .bind(2, keyword_id)
        .bind(3, keyword.sense.empty() ? input.sense : keyword.sense)
        .bind(4, position++)
        .run();
  }
  if (input.letter) {
    db.prepare("INSERT INTO alphabet (language, letter, kind, sign_id) VALUES (?, ?, ?, ?)")
        .bind(1, language)
        .bind(2, *input.letter)
        .bind(3, letter_kind(*input.letter))
        .bind(4, id)
        .run();
  }

  std::optional<SignRecord> written = read_sign(db, id);
  record_revision(db, *written, existing_id == 0 ? "create" : "update", author);
  bump_generation(db);
  return *written;
}

void Store::record_revision(Database& db, const SignRecord& sign, const char* op,
                            const std::string& author) {
  db.prepare(
        "INSERT INTO revisions (sign_id, revision, op, author, at, notation, format, snapshot) "
        "VALUES (?, ?, ?, ?, ?, ?, ?, ?)")
      .bind(1, sign.id)
      .bind(2, sign.revision)
      .bind(3, op)
      .bind(4, author)
      .bind(5, sign.updated_at)
      .bind(6, sign.notation)
      .bind(7, sign.format)
      .bind(8, sign_content_json(sign).dump())
      .run();
}

SignRecord Store::create_sign(const SignInput& input, const std::string& author) {
  if (!input.language) {
    throw ApiError(400, "missing required field 'language'", json{{"field", "language"}});
  }
  // Parse (and synthesise) before taking the write lock: it is the slow part.
  ValidatedNotation validated = validate_notation(input.notation, input.format);
  std::lock_guard<std::mutex> writer(write_mutex_);
  Lease db = lease();
  WriteTransaction transaction(*db);
  SignRecord sign = write_sign(*db, 0, input, *input.language, validated.format, validated.compiled, author);
  transaction.commit();
  return sign;
}

namespace {
// The revision check every edit makes under the write lock.
void check_current(const std::optional<SignRecord>& sign, std::int64_t id, std::int64_t expected) {
  if (!sign) {
    throw ApiError(404, "no sign with id " + std::to_string(id), json{{"id", id}});
  }
  if (sign->deleted) {
    throw ApiError(410, "sign " + std::to_string(id) + " was deleted (revision " +
                            std::to_string(sign->revision) + "); its history remains",
                   json{{"id", id}, {"current_revision", sign->revision}});
  }
  if (sign->revision != expected) {
    throw ApiError(409,
                   "sign " + std::to_string(id) + " is at revision " + std::to_string(sign->revision) +
                       ", not " + std::to_string(expected) +
                       ": someone else changed it; fetch it again and reapply your edit",
                   json{{"id", id}, {"current_revision", sign->revision},
                        {"your_revision", expected}});
  }
}
}  // namespace

SignRecord Store::update_sign(std::int64_t id, std::int64_t expected_revision, const SignInput& input,
                              const std::string& author) {
  ValidatedNotation validated = validate_notation(input.notation, input.format);
  std::lock_guard<std::mutex> writer(write_mutex_);
  Lease db = lease();
  WriteTransaction transaction(*db);
  std::optional<SignRecord> current = read_sign(*db, id);
  check_current(current, id, expected_revision);
  std::string language = input.language ? *input.language : current->language;
  SignRecord sign = write_sign(*db, id, input, language, validated.format, validated.compiled, author);
  transaction.commit();
  return sign;
}

SignRecord Store::delete_sign(std::int64_t id, std::int64_t expected_revision, const std::string& author) {
  std::lock_guard<std::mutex> writer(write_mutex_);
  Lease db = lease();
  WriteTransaction transaction(*db);
  std::optional<SignRecord> current = read_sign(*db, id);
  check_current(current, id, expected_revision);
  db->prepare(
        "UPDATE signs SET deleted = 1, revision = revision + 1, "
        "updated_at = strftime('%Y-%m-%dT%H:%M:%fZ', 'now') WHERE id = ?")
      .bind(1, id)
      .run();
  // The snapshot keeps what was deleted (keywords and letter included) before the links go.
  std::optional<SignRecord> deleted = read_sign(*db, id);
  record_revision(*db, *deleted, "delete", author);
  db->prepare("DELETE FROM sign_keywords WHERE sign_id = ?").bind(1, id).run();
  db->prepare("DELETE FROM alphabet WHERE sign_id = ?").bind(1, id).run();
  bump_generation(*db);
  transaction.commit();
  return *deleted;
}

std::int64_t Store::content_generation() {
  Lease db = lease();
  Statement& query = db->prepare("SELECT value FROM meta WHERE key = 'content_generation'");
  std::int64_t generation = query.step() ? query.column_int(0) : 0;
  query.reset();
  return generation;
}

std::vector<RevisionRecord> Store::history(std::int64_t id) {
  Lease db = lease();
  ReadTransaction snapshot(*db);
  Statement& exists = db->prepare("SELECT 1 FROM signs WHERE id = ?");
  exists.bind(1, id);
  bool found = exists.step();
  exists.reset();
  if (!found) throw ApiError(404, "no sign with id " + std::to_string(id), json{{"id", id}});
  Statement& query = db->prepare(
      "SELECT sign_id, revision, op, author, at, notation, format, snapshot FROM revisions "
      "WHERE sign_id = ? ORDER BY revision DESC");
  query.bind(1, id);
  std::vector<RevisionRecord> out;
  while (query.step()) {
    out.push_back(RevisionRecord{query.column_int(0), query.column_int(1), query.column_text(2),
                                 query.column_text(3), query.column_text(4), query.column_text(5),
                                 query.column_text(6), query.column_text(7)});
  }
  query.reset();
  return out;
}

// ------------------------------------------------------------------------------------------------
// Search and lookup

void Store::prepare_search() {
  for (const Language& language : languages()) WordForms::shared().covers(language.spoken);
  Lease db = lease();
  current_index(*db);
}

SearchPage Store::search(const SearchQuery& query) {
  Lease db = lease();
  if (!query.language.empty()) language_spoken_or_throw(*db, query.language);
  std::shared_ptr<const SearchIndex> index = current_index(*db);
  return index->search(query);
}

LookupResult Store::lookup(const std::string& text, const std::string& language) {
  Lease db = lease();
  language_spoken_or_throw(*db, language);
  std::shared_ptr<const SearchIndex> index = current_index(*db);
  return index->lookup(text, language);
}

// ------------------------------------------------------------------------------------------------
// Bulk import

ImportReport Store::import_items(const std::vector<ImportItem>& items, const std::string& author,
                                 ImportMode mode) {
  ImportReport report;
  auto reject = [&](const ImportItem& item, const ApiError& error) {
    report.rejected.push_back(
        ImportRejection{item.source, item.line, error.status(), error.what(), error.detail()});
  };

  // Phase 1, without the write lock: read and validate every line.
  std::vector<PreparedSign> prepared;
  std::unordered_map<std::string, int> first_line_of_gloss;
  for (const ImportItem& item : items) {
    try {
      SignInput input = parse_sign_input(item.sign, false);
      std::string language = input.language ? *input.language : item.default_language;
      if (language.empty()) {
        throw ApiError(400, "missing required field 'language' (and the file names none)",
                       json{{"field", "language"}});
      }
      std::string key = language + '\x1f' + input.gloss;
      auto [it, inserted] = first_line_of_gloss.emplace(key, item.line);
      if (!inserted) {
        throw ApiError(409, "gloss '" + input.gloss + "' appears twice in this import (first on line " +
                                std::to_string(it->second) + ")",
                       json{{"field", "gloss"}, {"first_line", it->second}});
      }
      ValidatedNotation validated = validate_notation(input.notation, input.format);
      prepared.push_back(PreparedSign{std::move(input), language, std::move(validated), &item});
    } catch (const ApiError& error) {
      reject(item, error);
    }
  }
  if (mode == ImportMode::CheckOnly) return report;
  if (mode == ImportMode::AllOrNothing && !report.rejected.empty()) return report;

  // Phase 2: one transaction; each sign in a savepoint so SkipInvalid can drop just that one.
  std::lock_guard<std::mutex> writer(write_mutex_);
  Lease db = lease();
  WriteTransaction transaction(*db);
  for (const PreparedSign& sign : prepared) {
    db->exec("SAVEPOINT import_sign");
    try {
      Statement& find = db->prepare(
          "SELECT id FROM signs WHERE language = ? AND gloss = ? AND deleted = 0");
      find.bind(1, sign.language).bind(2, sign.input.gloss);
      std::int64_t existing = find.step() ? find.column_int(0) : 0;
      find.reset();
      if (existing != 0) {
        std::optional<SignRecord> current = read_sign(*db, existing);
        json before = comparable_content(current->gloss, current->notation, current->format,
                                         current->tags, current->keywords, current->sense,
                                         current->description, current->starter, current->letter);
        json after = comparable_content(sign.input.gloss, sign.input.notation, sign.validated.format,
                                        sign.input.tags, sign.input.keywords, sign.input.sense,
                                        sign.input.description, sign.input.starter,
                                        sign.input.letter);
        if (before == after) {
          ++report.unchanged;
          db->exec("RELEASE import_sign");
          continue;
        }
        write_sign(*db, existing, sign.input, sign.language, sign.validated.format,
                   sign.validated.compiled, author);
        ++report.updated;
      } else {
        write_sign(*db, 0, sign.input, sign.language, sign.validated.format, sign.validated.compiled,
                   author);
        ++report.created;
      }
      db->exec("RELEASE import_sign");
    } catch (const ApiError& error) {
      db->exec("ROLLBACK TO import_sign");
      db->exec("RELEASE import_sign");
      reject(*sign.item, error);
    }
  }
  if (mode == ImportMode::AllOrNothing && !report.rejected.empty()) {
    report.created = report.updated = report.unchanged = 0;
    return report;  // the transaction rolls back
  }
  transaction.commit();
  report.committed = true;
  std::sort(report.rejected.begin(), report.rejected.end(),
            [](const ImportRejection& a, const ImportRejection& b) {
              return std::tie(a.source, a.line) < std::tie(b.source, b.line);
            });
  return report;
}

// ------------------------------------------------------------------------------------------------
// API tokens. Generated tokens read "sw_<64 hex>" (256 random bits). The row is found by the
// first 16 hex digits of SHA-256(token) and the secret checked against salt + SHA-256(salt ||
// token) in constant time.

std::string Store::create_token(const std::string& name, const std::string& chosen) {
  if (name.empty() || name.size() > kMaxLabelBytes || !is_valid_utf8(name) ||
      std::any_of(name.begin(), name.end(), [](char c) { return static_cast<unsigned char>(c) < 0x20; })) {
    throw ApiError(400, "a token name is 1 to 100 bytes of UTF-8 without control characters",
                   json{{"field", "name"}});
  }
  if (!chosen.empty() && (chosen.size() < 16 || chosen.size() > 512 ||
                          std::any_of(chosen.begin(), chosen.end(), [](char c) {
                            return static_cast<unsigned char>(c) <= 0x20 || static_cast<unsigned char>(c) >= 0x7F;
                          }))) {
    throw ApiError(400, "a chosen token is 16 to 512 printable ASCII characters without spaces",
                   json{{"field", "token"}});
  }
  std::string token = chosen.empty() ? "sw_" + random_bytes_hex(32) : chosen;
  std::string salt = random_bytes_hex(16);
  std::lock_guard<std::mutex> writer(write_mutex_);
  Lease db = lease();
  WriteTransaction transaction(*db);
  Statement& exists = db->prepare("SELECT id FROM api_tokens WHERE name = ?");
  exists.bind(1, name);
  bool taken = exists.step();
  exists.reset();
  if (taken) throw ApiError(409, "a token named '" + name + "' exists already", json{{"field", "name"}});
  db->prepare(
        "INSERT INTO api_tokens (name, lookup, salt, hash, created_at) "
        "VALUES (?, ?, ?, ?, strftime('%Y-%m-%dT%H:%M:%fZ', 'now'))")
      .bind(1, name)
      .bind(2, sha256_hex(token).substr(0, 16))
      .bind(3, salt)
      .bind(4, sha256_hex(salt + token))
      .run();
  transaction.commit();
  return token;
}

TokenCheck Store::verify_token(const std::string& token) {
  TokenCheck check;
  check.result = TokenCheck::Result::Malformed;
  if (token.empty() || token.size() > 512) return check;
  check.result = TokenCheck::Result::Unknown;
  Lease db = lease();
  Statement& query = db->prepare("SELECT name, salt, hash FROM api_tokens WHERE lookup = ? AND revoked = 0");
  query.bind(1, sha256_hex(token).substr(0, 16));
  if (query.step()) {
    std::string name = query.column_text(0);
    std::string expected = query.column_text(2);
    std::string actual = sha256_hex(query.column_text(1) + token);
    if (constant_time_equal(expected, actual)) {
      check.result = TokenCheck::Result::Valid;
      check.name = name;
    }
  }
  query.reset();
  return check;
}

bool Store::has_token_value(const std::string& token) {
  return verify_token(token).result == TokenCheck::Result::Valid;
}

std::int64_t Store::count_tokens() {
  Lease db = lease();
  Statement& query = db->prepare("SELECT COUNT(*) FROM api_tokens WHERE revoked = 0");
  std::int64_t count = query.step() ? query.column_int(0) : 0;
  query.reset();
  return count;
}

// ------------------------------------------------------------------------------------------------
// Operations

bool Store::integrity_check(std::string* detail) {
  Lease db = lease();
  Statement& query = db->prepare("PRAGMA integrity_check");
  std::string result;
  while (query.step()) {
    if (!result.empty()) result += "; ";
    result += query.column_text(0);
  }
  query.reset();
  Statement& keys = db->prepare("PRAGMA foreign_key_check");
  bool foreign_keys_ok = !keys.step();
  keys.reset();
  if (!foreign_keys_ok) result += (result.empty() ? "" : "; ") + std::string("foreign key violations");
  if (detail) *detail = result;
  return result == "ok" && foreign_keys_ok;
}

std::int64_t Store::database_size_bytes() {
  auto file_size = [](const std::string& path) -> std::int64_t {
    struct stat info {};
    return ::stat(path.c_str(), &info) == 0 ? static_cast<std::int64_t>(info.st_size) : 0;
  };
  return file_size(path_) + file_size(path_ + "-wal");
}

void Store::checkpoint() {
  std::lock_guard<std::mutex> writer(write_mutex_);
  Lease db = lease();
  Statement& query = db->prepare("PRAGMA wal_checkpoint(TRUNCATE)");
  query.run();
}

std::string Store::content_fingerprint() {
  Lease db = lease();
  ReadTransaction snapshot(*db);
  std::string all;
  const char* const kTables[] = {
      "SELECT code, name, spoken, alphabet_script FROM languages ORDER BY code",
      "SELECT id, language, gloss, notation, format, tags, sense, description, starter, revision, "
      "deleted, updated_at "
      "FROM signs ORDER BY id",
      "SELECT id, spoken, word FROM keywords ORDER BY id",
      "SELECT sign_id, keyword_id, sense, position FROM sign_keywords ORDER BY sign_id, keyword_id",
      "SELECT language, letter, kind, sign_id FROM alphabet ORDER BY language, letter",
      "SELECT sign_id, revision, op, author, at, snapshot FROM revisions ORDER BY sign_id, revision",
      "SELECT id, name, hash, revoked FROM api_tokens ORDER BY id",
  };
  for (const char* sql : kTables) {
    Statement& query = db->prepare(sql);
    while (query.step()) {
      for (int c = 0; c < query.column_count(); ++c) {
        all += query.column_text(c);
        all.push_back('\x1f');
      }
      all.push_back('\x1e');
    }
    query.reset();
    all.push_back('\x1d');
  }
  return sha256_hex(all);
}

}  // namespace sw::store
