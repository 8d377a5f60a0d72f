// The records the gesture database reads and writes: a sign language, a sign as written by an
// author (SignInput) and as stored (SignRecord), a revision, and the limits on each field with
// the reason for each.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace sw::store {

// Field limits. Why: a sign's notation in any of the four formats is a few hundred bytes (the
// longest SiGML sign in the shared corpus is under 8 KiB); 64 KiB leaves room for hand-written
// G-SiGML while keeping one row small enough that a page of search results stays a few hundred
// KiB. Glosses, tags and keywords are labels, not text.
constexpr std::size_t kMaxNotationBytes = 64 * 1024;
constexpr std::size_t kMaxGlossBytes = 200;
constexpr std::size_t kMaxLabelBytes = 100;     // a tag, a keyword, a language code or name
constexpr std::size_t kMaxSenseBytes = 1000;
constexpr std::size_t kMaxDescriptionBytes = 4000;  // a paragraph for reviewers who do not read notation
constexpr std::size_t kMaxTags = 32;
constexpr std::size_t kMaxKeywords = 64;
constexpr std::size_t kMaxLetterCodePoints = 4;  // a letter may be a digraph (CH, LL, Ї)

struct Language {
  std::string code;             // ISO 639-3 sign language code: "ase", "ukl", "bfi"
  std::string name;
  std::string spoken;           // ISO 639-1 code of the spoken language of its keywords: "en"
  std::string alphabet_script;  // "latin", "cyrillic", ...
};

struct KeywordEntry {
  std::string word;   // as written ("thank you")
  std::string sense;  // which meaning of the word this sign carries; "" = the sign's sense
};

struct SignInput {
  std::optional<std::string> language;  // required on create; an update keeps the sign's own
  std::string gloss;
  std::string notation;
  std::optional<std::string> format;    // "formula" | "hamnosys" | "hsigml" | "gsigml"; guessed
  std::vector<std::string> tags;
  std::vector<KeywordEntry> keywords;
  std::string sense;
  std::string description;              // plain-language description of the sign's form
  bool starter = false;                 // part of the project's starter set (data/)
  std::optional<std::string> letter;    // set: this sign is the fingerspelling of that letter/digit
};

struct SignRecord {
  std::int64_t id = 0;
  std::string language;
  std::string gloss;
  std::string notation;
  std::string format;
  std::vector<std::string> tags;
  std::vector<KeywordEntry> keywords;
  std::string sense;
  std::string description;
  bool starter = false;
  std::optional<std::string> letter;
  std::optional<std::string> compiled;  // JSON the core compiled from the notation, when present
  std::int64_t revision = 0;
  bool deleted = false;
  std::string created_at;
  std::string updated_at;
};

struct RevisionRecord {
  std::int64_t sign_id = 0;
  std::int64_t revision = 0;
  std::string op;        // "create" | "update" | "delete"
  std::string author;    // the API token's name, or "import:<file>"
  std::string at;        // ISO 8601 UTC
  std::string notation;
  std::string format;
  std::string snapshot;  // the sign as JSON after this revision
};

}  // namespace sw::store
