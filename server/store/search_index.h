// SearchIndex: an immutable in-memory snapshot of what search and phrase lookup read — every
// live sign's gloss and keywords (normalised), a trigram index over them, the keyword phrases per
// language, and the alphabets. Built from the database in one read transaction and replaced when
// meta.content_generation moves (store.cpp), so readers never lock and never see half a write.
//
// Search ranks each sign by its best match, in tiers: exact gloss/keyword (0), another form of
// one ("books" finds "book", 1; word_forms.h), prefix of a gloss or keyword (2), prefix of a later
// word of one ("you" finds "thank you", 3), typo within a bounded edit distance (4: 1 edit for 3–5
// characters, 2 from 6). Within a tier: fewer edits, shorter completion, then gloss and id.
//
// Lookup tries, for each run of words (longest first): the keyword phrase as typed, then another
// form of it — the typed words reduced to their base forms against the keywords as written, then
// the typed words (as typed or reduced) against the keywords' own base forms. Only then a shorter
// run, and a word no run matches is fingerspelled. Pages are cut with an opaque keyset cursor (the
// last hit's sort key), so a page boundary stays put while signs are added elsewhere in the
// ranking.
//
// Limits, with their reason: a page holds at most kMaxSearchLimit hits (the page lists, it does
// not export); a lookup text is at most kMaxLookupBytes (a typed phrase, not a document) and a
// keyword phrase at most kMaxPhraseWords words (the greedy match tries each length).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

namespace sw::store {

class Database;

constexpr int kMaxSearchLimit = 100;
constexpr int kDefaultSearchLimit = 20;
constexpr std::size_t kMaxQueryBytes = 200;
constexpr std::size_t kMaxLookupBytes = 2000;
constexpr int kMaxPhraseWords = 6;
// Why 64: a phrase of up to kMaxPhraseWords words, each with its base forms, has that many
// spellings at most before the rarest combinations are dropped (a word has 1–3 forms in practice).
constexpr std::size_t kMaxFormKeys = 64;

struct SearchQuery {
  std::string text;      // "" lists every sign (of the language) by gloss
  std::string language;  // "" = every language
  int limit = kDefaultSearchLimit;
  std::string cursor;  // "" = first page
};

struct SearchHit {
  std::int64_t sign_id = 0;
  std::string language;
  std::string gloss;
  std::string notation;
  std::string format;
  std::int64_t revision = 0;
  std::vector<std::string> keywords;
  std::string match_field;  // "gloss" | "keyword" | "" (listing)
  std::string match_text;   // the gloss or keyword that matched
  std::string match_type;   // "exact" | "stem" | "prefix" | "word_prefix" | "fuzzy" | "all"
  int distance = 0;         // edits, for fuzzy matches
};

struct SearchPage {
  std::vector<SearchHit> hits;
  std::string next_cursor;  // "" when this is the last page
  std::size_t total = 0;    // hits over all pages
};

struct LookupLetter {
  std::string letter;                   // as written in the alphabet ("К")
  std::optional<std::int64_t> sign_id;  // nullopt: the alphabet has no sign for this character
  std::string gloss;
};

struct LookupToken {
  enum class Type { Sign, Fingerspell, Pause } type = Type::Sign;
  std::string text;        // the span of the input this token covers, as typed
  std::size_t offset = 0;  // its byte offset in the input
  std::int64_t sign_id = 0;
  std::string gloss;
  std::vector<std::int64_t> alternatives;  // other signs for the same keyword
  std::string match_type;  // signs: "exact" (as typed) | "stem" (another form of the words)
  std::string match_form;  // the words' form that matched, lower-cased ("book" for "Books")
  std::string match_text;  // the keyword or gloss that matched, as written
  std::vector<LookupLetter> letters;
  double pause_s = 0.0;
};

struct LookupResult {
  std::string language;
  std::vector<LookupToken> tokens;
};

class SearchIndex {
 public:
  // Reads every live sign, keyword and alphabet entry. The caller holds a read transaction.
  static SearchIndex build(Database& db, std::int64_t generation);

  std::int64_t generation() const { return generation_; }
  // Throws ApiError(400) for a cursor that is malformed or belongs to another query.
  SearchPage search(const SearchQuery& query) const;
  LookupResult lookup(const std::string& text, const std::string& language) const;

  struct Sign {
    std::int64_t id;
    std::string language;
    std::string gloss;
    std::string gloss_norm;
    std::string notation;
    std::string format;
    std::int64_t revision;
    std::vector<std::string> keywords;
  };
  // A gloss, a keyword, or one later word of either (for word-prefix matches).
  // A keyword phrase or gloss under one of its spellings (the lookup's phrase tables).
  struct Phrase {
    std::uint32_t sign;  // index into signs_
    std::string text;    // the keyword or gloss, as written
    bool is_keyword;
  };
  struct Term {
    std::string norm;
    std::vector<char32_t> code_points;
    std::uint32_t sign;  // index into signs_
    bool is_keyword;
    bool is_inner_word;  // a word after the first of a multi-word gloss/keyword
    std::string text;    // the whole gloss or keyword, as written
  };

 private:
  // The phrases a run of words spells (the lookup order in the comment at the top), with how they
  // matched ("exact" | "stem") and the spelling that did; nullptr when none.
  const std::vector<Phrase>* find_phrase(const std::string& language,
                                         const std::vector<std::vector<std::string>>& word_forms,
                                         std::string* type, std::string* form) const;

  std::int64_t generation_ = 0;
  std::vector<Sign> signs_;
  std::vector<Term> terms_;  // sorted by norm, for prefix ranges
  std::unordered_map<std::uint64_t, std::vector<std::uint32_t>> trigrams_;  // -> terms_
  // "<language>\x1f<normalised phrase>" -> the keywords and glosses written so, best first.
  std::unordered_map<std::string, std::vector<Phrase>> phrases_;
  // "<language>\x1f<phrase of base forms>" -> the keywords and glosses that reduce to it (their
  // written spelling is in phrases_ only).
  std::unordered_map<std::string, std::vector<Phrase>> phrase_stems_;
  // sign language -> its spoken language ("ase" -> "en"), for WordForms.
  std::unordered_map<std::string, std::string> spoken_;
  // "<language>\x1f<lower-cased letter>" -> (letter as written, signs_ index)
  std::unordered_map<std::string, std::pair<std::string, std::uint32_t>> letters_;
};

}  // namespace sw::store
