// Schema migrations (see migrations.h). Append new migrations to kMigrations; never edit one that
// has shipped — a database in the field has already run it.
#include "store/migrations.h"

#include <string>

namespace sw::store {
namespace {

struct Migration {
  int version;
  const char* description;
  const char* sql;
};

// Notes on the schema:
// - signs are never physically deleted: DELETE marks them deleted (and drops their keyword and
//   alphabet links) so that revisions, which reference them, keep the whole history.
// - a live gloss is unique per sign language (partial unique index): imports match on it, and
//   homonyms are written as distinct glosses (HOUSE, HOUSE#2), as dictionaries do.
// - keywords belong to the SPOKEN language (en, uk): ASL and BSL signs share the English word.
// - api_tokens keep salt + SHA-256(salt || token) to verify, and `lookup` = the first 16 hex
//   digits of the unsalted SHA-256 to find the row (tokens are 256-bit random, or chosen by the
//   admin through SIGNWEAVE_ADMIN_TOKEN, so 64 bits of an unsalted hash reveal nothing usable).
// - meta.content_generation increases in every write transaction that changes what search or
//   lookup can see; the in-memory search index rebuilds when it moves (also after another
//   process — `signweave import` — wrote).
const Migration kMigrations[] = {
    {1, "languages, signs, keywords, alphabets, revisions, api tokens",
     R"sql(
CREATE TABLE meta (
  key   TEXT PRIMARY KEY,
  value INTEGER NOT NULL
);
INSERT INTO meta (key, value) VALUES ('content_generation', 1);

CREATE TABLE languages (
  code            TEXT PRIMARY KEY,
  name            TEXT NOT NULL,
  spoken          TEXT NOT NULL,
  alphabet_script TEXT NOT NULL DEFAULT ''
);

CREATE TABLE signs (
  id         INTEGER PRIMARY KEY,
  language   TEXT NOT NULL REFERENCES languages(code),
  gloss      TEXT NOT NULL,
  gloss_norm TEXT NOT NULL,
  notation   TEXT NOT NULL,
  format     TEXT NOT NULL CHECK (format IN ('formula', 'hamnosys', 'hsigml', 'gsigml')),
  tags       TEXT NOT NULL DEFAULT '[]',
  sense      TEXT NOT NULL DEFAULT '',
  description TEXT NOT NULL DEFAULT '',
  starter    INTEGER NOT NULL DEFAULT 0 CHECK (starter IN (0, 1)),
  compiled   TEXT,
  revision   INTEGER NOT NULL CHECK (revision >= 1),
  deleted    INTEGER NOT NULL DEFAULT 0 CHECK (deleted IN (0, 1)),
  created_at TEXT NOT NULL,
  updated_at TEXT NOT NULL
);
CREATE UNIQUE INDEX signs_live_gloss ON signs (language, gloss) WHERE deleted = 0;
CREATE INDEX signs_gloss_norm ON signs (language, gloss_norm) WHERE deleted = 0;

CREATE TABLE keywords (
  id        INTEGER PRIMARY KEY,
  spoken    TEXT NOT NULL,
  word      TEXT NOT NULL,
  word_norm TEXT NOT NULL,
  UNIQUE (spoken, word_norm)
);

CREATE TABLE sign_keywords (
  sign_id    INTEGER NOT NULL REFERENCES signs(id),
  keyword_id INTEGER NOT NULL REFERENCES keywords(id),
  sense      TEXT NOT NULL DEFAULT '',
  position   INTEGER NOT NULL,
  PRIMARY KEY (sign_id, keyword_id)
);
CREATE INDEX sign_keywords_by_keyword ON sign_keywords (keyword_id);

CREATE TABLE alphabet (
  language TEXT NOT NULL REFERENCES languages(code),
  letter   TEXT NOT NULL,
  kind     TEXT NOT NULL CHECK (kind IN ('letter', 'digit')),
  sign_id  INTEGER NOT NULL REFERENCES signs(id),
  PRIMARY KEY (language, letter)
);
CREATE INDEX alphabet_by_sign ON alphabet (sign_id);

CREATE TABLE revisions (
  sign_id  INTEGER NOT NULL REFERENCES signs(id),
  revision INTEGER NOT NULL,
  op       TEXT NOT NULL CHECK (op IN ('create', 'update', 'delete')),
  author   TEXT NOT NULL,
  at       TEXT NOT NULL,
  notation TEXT NOT NULL,
  format   TEXT NOT NULL,
  snapshot TEXT NOT NULL,
  PRIMARY KEY (sign_id, revision)
);

CREATE TABLE api_tokens (
  id         INTEGER PRIMARY KEY,
  name       TEXT NOT NULL UNIQUE,
  lookup     TEXT NOT NULL UNIQUE,
  salt       TEXT NOT NULL,
  hash       TEXT NOT NULL,
  created_at TEXT NOT NULL,
  revoked    INTEGER NOT NULL DEFAULT 0 CHECK (revoked IN (0, 1))
);
)sql"},
};

}  // namespace

int latest_schema_version() {
  return kMigrations[sizeof(kMigrations) / sizeof(kMigrations[0]) - 1].version;
}

int migrate(Database& db) {
  db.exec(
      "CREATE TABLE IF NOT EXISTS schema_version ("
      " version INTEGER PRIMARY KEY, description TEXT NOT NULL, applied_at TEXT NOT NULL)");
  int current = 0;
  {
    Statement& query = db.prepare("SELECT COALESCE(MAX(version), 0) FROM schema_version");
    if (query.step()) current = static_cast<int>(query.column_int(0));
    query.reset();
  }
  if (current > latest_schema_version()) {
    throw DatabaseError("database schema version " + std::to_string(current) +
                            " is newer than this build understands (" +
                            std::to_string(latest_schema_version()) + "); upgrade signweave",
                        SQLITE_MISMATCH);
  }
  for (const Migration& migration : kMigrations) {
    if (migration.version <= current) continue;
    WriteTransaction transaction(db);
    // Re-check under the write lock: two processes opening a fresh file at once.
    Statement& again = db.prepare("SELECT COUNT(*) FROM schema_version WHERE version = ?");
    again.bind(1, migration.version);
    bool applied = again.step() && again.column_int(0) > 0;
    again.reset();
    if (applied) continue;
    db.exec(migration.sql);
    Statement& record = db.prepare(
        "INSERT INTO schema_version (version, description, applied_at) "
        "VALUES (?, ?, strftime('%Y-%m-%dT%H:%M:%fZ', 'now'))");
    record.bind(1, migration.version).bind(2, migration.description).run();
    transaction.commit();
    current = migration.version;
  }
  return current;
}

}  // namespace sw::store
