// Search ranking, cursors and phrase lookup over the in-memory index (see search_index.h).
#include "store/search_index.h"

#include <algorithm>
#include <cstring>
#include <tuple>
#include <unordered_set>

#include <nlohmann/json.hpp>

#include "store/api_error.h"
#include "store/edit_distance.h"
#include "store/sha256.h"
#include "store/sign_record.h"
#include "store/sqlite_db.h"
#include "store/utf8_text.h"
#include "store/word_forms.h"

namespace sw::store {
namespace {

using nlohmann::json;

// --- text scanning shared by the index (keyword phrases) and lookup (typed text)

struct TextItem {
  enum class Kind { Word, Pause } kind;
  std::size_t begin;  // code point range [begin, end)
  std::size_t end;
  double pause_s;
};

// Words are runs of word characters, with apostrophes allowed between two of them (don't,
// п'ять); clause and sentence punctuation becomes a pause (runs like "?!" one pause, the longest);
// everything else (spaces, hyphens, quotes, symbols) only separates.
std::vector<TextItem> scan_text(const std::vector<char32_t>& cps) {
  std::vector<TextItem> items;
  std::size_t i = 0;
  const std::size_t n = cps.size();
  while (i < n) {
    if (is_word_char(cps[i])) {
      std::size_t begin = i;
      while (i < n && (is_word_char(cps[i]) || (is_word_joiner(cps[i]) && i + 1 < n &&
                                                is_word_char(cps[i + 1]) && i > begin))) {
        ++i;
      }
      items.push_back({TextItem::Kind::Word, begin, i, 0.0});
      continue;
    }
    double pause = pause_after_punctuation_s(cps[i]);
    if (pause > 0.0) {
      if (!items.empty() && items.back().kind == TextItem::Kind::Pause && items.back().end == i) {
        items.back().end = i + 1;
        items.back().pause_s = std::max(items.back().pause_s, pause);
      } else {
        items.push_back({TextItem::Kind::Pause, i, i + 1, pause});
      }
    }
    ++i;
  }
  return items;
}

std::string lower_range(const std::vector<char32_t>& cps, std::size_t begin, std::size_t end) {
  std::string out;
  for (std::size_t i = begin; i < end; ++i) {
    if (is_word_joiner(cps[i])) {
      out.push_back('\'');  // ’ and ʼ match a keyword typed with '
    } else {
      append_utf8(out, to_lower(cps[i]));
    }
  }
  return out;
}

// The key a keyword phrase is stored under and a typed phrase looked up by: its words,
// lower-cased, joined by one space ("Thank-you!" and "thank you" both give "thank you").
std::string phrase_key(const std::string& text, int* word_count) {
  std::vector<char32_t> cps = decode_utf8(text);
  std::string key;
  int words = 0;
  for (const TextItem& item : scan_text(cps)) {
    if (item.kind != TextItem::Kind::Word) continue;
    if (!key.empty()) key.push_back(' ');
    key += lower_range(cps, item.begin, item.end);
    ++words;
  }
  if (word_count) *word_count = words;
  return key;
}

// The words of a phrase key ("thank you" -> {"thank", "you"}).
std::vector<std::string> split_words(const std::string& key) {
  std::vector<std::string> words;
  std::size_t start = 0;
  while (start <= key.size()) {
    std::size_t end = key.find(' ', start);
    if (end == std::string::npos) end = key.size();
    if (end > start) words.push_back(key.substr(start, end - start));
    start = end + 1;
  }
  return words;
}

// Each word followed by its base forms: {{"signed", "sign"}, {"books", "book"}}.
std::vector<std::vector<std::string>> forms_of(const std::vector<std::string>& words,
                                               const std::string& spoken) {
  std::vector<std::vector<std::string>> forms;
  for (const std::string& word : words) {
    std::vector<std::string> alternatives{word};
    for (std::string& stem : WordForms::shared().stems(spoken, word))
      alternatives.push_back(std::move(stem));
    forms.push_back(std::move(alternatives));
  }
  return forms;
}

// Every spelling of a phrase from one form of each word: the words as typed first, then in the
// order of the forms (the first word varying slowest); at most kMaxFormKeys.
std::vector<std::string> form_keys(const std::vector<std::vector<std::string>>& forms) {
  std::vector<std::string> keys{""};
  for (const std::vector<std::string>& word : forms) {
    std::vector<std::string> longer;
    for (const std::string& key : keys) {
      for (const std::string& form : word) {
        if (longer.size() < kMaxFormKeys) longer.push_back(key.empty() ? form : key + ' ' + form);
      }
    }
    keys = std::move(longer);
  }
  return keys;
}

std::string scoped(const std::string& language, const std::string& key) {
  return language + '\x1f' + key;
}

// Trigrams over code points with boundary markers, packed 21 bits per code point.
constexpr char32_t kBoundary = 0x110000 - 1;  // U+10FFFF never appears in a gloss
std::vector<std::uint64_t> trigrams_of(const std::vector<char32_t>& cps) {
  std::vector<char32_t> padded;
  padded.reserve(cps.size() + 2);
  padded.push_back(kBoundary);
  padded.insert(padded.end(), cps.begin(), cps.end());
  padded.push_back(kBoundary);
  std::vector<std::uint64_t> grams;
  for (std::size_t i = 0; i + 2 < padded.size(); ++i) {
    grams.push_back((std::uint64_t(padded[i]) << 42) | (std::uint64_t(padded[i + 1]) << 21) |
                    std::uint64_t(padded[i + 2]));
  }
  std::sort(grams.begin(), grams.end());
  grams.erase(std::unique(grams.begin(), grams.end()), grams.end());
  return grams;
}

int typo_bound(std::size_t query_code_points) {
  if (query_code_points < 3) return 0;
  if (query_code_points < 6) return 1;
  return 2;
}

// --- cursors: base64url of a JSON array [query hash, tier, distance, extra, gloss_norm, id]

const char kBase64Url[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789-_";

std::string base64url_encode(const std::string& in) {
  std::string out;
  std::size_t i = 0;
  while (i + 2 < in.size()) {
    std::uint32_t v =
        (std::uint8_t(in[i]) << 16) | (std::uint8_t(in[i + 1]) << 8) | std::uint8_t(in[i + 2]);
    out += kBase64Url[v >> 18];
    out += kBase64Url[(v >> 12) & 63];
    out += kBase64Url[(v >> 6) & 63];
    out += kBase64Url[v & 63];
    i += 3;
  }
  std::size_t rest = in.size() - i;
  if (rest == 1) {
    std::uint32_t v = std::uint8_t(in[i]) << 16;
    out += kBase64Url[v >> 18];
    out += kBase64Url[(v >> 12) & 63];
  } else if (rest == 2) {
    std::uint32_t v = (std::uint8_t(in[i]) << 16) | (std::uint8_t(in[i + 1]) << 8);
    out += kBase64Url[v >> 18];
    out += kBase64Url[(v >> 12) & 63];
    out += kBase64Url[(v >> 6) & 63];
  }
  return out;
}

bool base64url_decode(const std::string& in, std::string* out) {
  std::uint32_t buffer = 0;
  int bits = 0;
  for (char c : in) {
    const char* found = std::strchr(kBase64Url, c);
    if (c == '\0' || found == nullptr) return false;
    buffer = (buffer << 6) | static_cast<std::uint32_t>(found - kBase64Url);
    bits += 6;
    if (bits >= 8) {
      bits -= 8;
      out->push_back(static_cast<char>((buffer >> bits) & 0xFF));
    }
  }
  return true;
}

struct RankKey {
  int tier = 0;
  int distance = 0;
  int extra = 0;  // code points the matched term has beyond the query (shorter completions first)
  std::string gloss_norm;
  std::int64_t id = 0;
  auto tie() const { return std::tie(tier, distance, extra, gloss_norm, id); }
  bool operator<(const RankKey& other) const { return tie() < other.tie(); }
};

std::string query_hash(const SearchQuery& query, const std::string& normalized) {
  return sha256_hex(normalized + '\x1f' + query.language).substr(0, 16);
}

[[noreturn]] void bad_cursor(const std::string& why) {
  throw ApiError(400, "invalid cursor: " + why, json{{"field", "cursor"}});
}

RankKey decode_cursor(const std::string& cursor, const std::string& expected_hash) {
  std::string raw;
  if (cursor.size() > 1000 || !base64url_decode(cursor, &raw))
    bad_cursor("not a cursor this server issued");
  json parsed = json::parse(raw, nullptr, false);
  if (parsed.is_discarded() || !parsed.is_array() || parsed.size() != 6 || !parsed[0].is_string() ||
      !parsed[1].is_number_integer() || !parsed[2].is_number_integer() ||
      !parsed[3].is_number_integer() || !parsed[4].is_string() || !parsed[5].is_number_integer()) {
    bad_cursor("not a cursor this server issued");
  }
  if (parsed[0].get<std::string>() != expected_hash) {
    bad_cursor("it belongs to a different query (q and lang must stay the same between pages)");
  }
  RankKey key;
  key.tier = parsed[1].get<int>();
  key.distance = parsed[2].get<int>();
  key.extra = parsed[3].get<int>();
  key.gloss_norm = parsed[4].get<std::string>();
  key.id = parsed[5].get<std::int64_t>();
  return key;
}

std::string encode_cursor(const RankKey& key, const std::string& hash) {
  return base64url_encode(
      json::array({hash, key.tier, key.distance, key.extra, key.gloss_norm, key.id}).dump());
}

}  // namespace

SearchIndex SearchIndex::build(Database& db, std::int64_t generation) {
  SearchIndex index;
  index.generation_ = generation;
  std::unordered_map<std::int64_t, std::uint32_t> by_id;

  Statement& signs = db.prepare(
      "SELECT id, language, gloss, gloss_norm, notation, format, revision FROM signs "
      "WHERE deleted = 0 ORDER BY id");
  while (signs.step()) {
    Sign sign{
        signs.column_int(0),  signs.column_text(1), signs.column_text(2), signs.column_text(3),
        signs.column_text(4), signs.column_text(5), signs.column_int(6),  {}};
    by_id[sign.id] = static_cast<std::uint32_t>(index.signs_.size());
    index.signs_.push_back(std::move(sign));
  }
  signs.reset();

  Statement& languages = db.prepare("SELECT code, spoken FROM languages");
  while (languages.step()) index.spoken_[languages.column_text(0)] = languages.column_text(1);
  languages.reset();

  std::unordered_set<std::uint32_t> letter_signs;
  Statement& alphabet = db.prepare("SELECT language, letter, sign_id FROM alphabet");
  while (alphabet.step()) {
    auto found = by_id.find(alphabet.column_int(2));
    if (found == by_id.end()) continue;
    std::string letter = alphabet.column_text(1);
    std::string lowered;
    for (char32_t cp : decode_utf8(letter)) append_utf8(lowered, to_lower(cp));
    index.letters_[scoped(alphabet.column_text(0), lowered)] = {letter, found->second};
    letter_signs.insert(found->second);
  }
  alphabet.reset();

  auto add_term = [&](const std::string& text, std::uint32_t sign, bool is_keyword) {
    std::string norm = normalize_for_match(text);
    if (norm.empty()) return;
    std::vector<char32_t> cps = decode_utf8(norm);
    index.terms_.push_back(Term{norm, cps, sign, is_keyword, false, text});
    // Later words of a multi-word term ("you" in "thank you", "you" in "THANK-YOU").
    std::vector<TextItem> items = scan_text(cps);
    for (std::size_t w = 1; w < items.size(); ++w) {
      if (items[w].kind != TextItem::Kind::Word) continue;
      std::vector<char32_t> word(cps.begin() + items[w].begin, cps.begin() + items[w].end);
      index.terms_.push_back(Term{encode_utf8(word), word, sign, is_keyword, true, text});
    }
  };

  // A keyword or gloss is looked up under its written spelling (phrases_) and under every
  // spelling of its base forms (phrase_stems_), each sign once per spelling.
  auto add_phrase = [&](std::uint32_t sign, const std::string& text, bool is_keyword) {
    int words = 0;
    std::string key = phrase_key(text, &words);
    if (key.empty() || words > kMaxPhraseWords) return;
    const std::string& language = index.signs_[sign].language;
    auto spoken = index.spoken_.find(language);
    std::vector<std::string> keys =
        form_keys(forms_of(split_words(key), spoken == index.spoken_.end() ? "" : spoken->second));
    for (std::size_t k = 0; k < keys.size(); ++k) {
      auto& list = (k == 0 ? index.phrases_ : index.phrase_stems_)[scoped(language, keys[k])];
      bool present =
          std::any_of(list.begin(), list.end(), [&](const Phrase& p) { return p.sign == sign; });
      if (!present) list.push_back(Phrase{sign, text, is_keyword});
    }
  };

  Statement& keywords = db.prepare(
      "SELECT sk.sign_id, k.word FROM sign_keywords sk "
      "JOIN keywords k ON k.id = sk.keyword_id JOIN signs s ON s.id = sk.sign_id "
      "WHERE s.deleted = 0 ORDER BY sk.position, sk.sign_id");
  while (keywords.step()) {
    auto found = by_id.find(keywords.column_int(0));
    if (found == by_id.end()) continue;
    std::string word = keywords.column_text(1);
    index.signs_[found->second].keywords.push_back(word);
    add_term(word, found->second, true);
    add_phrase(found->second, word, true);
  }
  keywords.reset();

  // Glosses: searchable always; a phrase for lookup only after every keyword (keywords first)
  // and never for letter signs (the gloss "A" must not turn the English article into a letter).
  for (std::uint32_t s = 0; s < index.signs_.size(); ++s) {
    add_term(index.signs_[s].gloss, s, false);
    if (letter_signs.count(s)) continue;
    add_phrase(s, index.signs_[s].gloss, false);
  }

  std::sort(index.terms_.begin(), index.terms_.end(),
            [](const Term& a, const Term& b) { return a.norm < b.norm; });
  for (std::uint32_t t = 0; t < index.terms_.size(); ++t) {
    for (std::uint64_t gram : trigrams_of(index.terms_[t].code_points))
      index.trigrams_[gram].push_back(t);
  }
  return index;
}

SearchPage SearchIndex::search(const SearchQuery& query) const {
  std::string normalized = normalize_for_match(query.text);
  std::string hash = query_hash(query, normalized);
  std::optional<RankKey> after;
  if (!query.cursor.empty()) after = decode_cursor(query.cursor, hash);

  struct Candidate {
    RankKey key;
    const std::string* text;  // the gloss or keyword that matched; nullptr for a listing
    bool is_keyword;
    const char* type;
  };
  std::unordered_map<std::uint32_t, Candidate> best;  // per sign
  auto consider_match = [&](std::uint32_t sign, int tier, int distance, int extra,
                            const std::string* text, bool is_keyword, const char* type) {
    const Sign& s = signs_[sign];
    if (!query.language.empty() && s.language != query.language) return;
    RankKey key{tier, distance, extra, s.gloss_norm, s.id};
    auto found = best.find(sign);
    if (found == best.end() || key < found->second.key)
      best[sign] = Candidate{key, text, is_keyword, type};
  };
  auto consider = [&](std::uint32_t sign, int tier, int distance, int extra, const Term* term,
                      const char* type) {
    consider_match(sign, tier, distance, extra, term ? &term->text : nullptr,
                   term && term->is_keyword, type);
  };

  if (normalized.empty()) {
    for (std::uint32_t s = 0; s < signs_.size(); ++s) consider(s, 0, 0, 0, nullptr, "all");
  } else {
    std::vector<char32_t> query_cps = decode_utf8(normalized);
    // Exact and prefix: the sorted terms whose norm starts with the query form one range.
    auto first = std::lower_bound(terms_.begin(), terms_.end(), normalized,
                                  [](const Term& t, const std::string& q) { return t.norm < q; });
    for (auto it = first;
         it != terms_.end() && it->norm.compare(0, normalized.size(), normalized) == 0; ++it) {
      std::uint32_t sign = it->sign;
      int extra = static_cast<int>(it->code_points.size() - query_cps.size());
      if (it->is_inner_word) {
        consider(sign, 3, 0, extra, &*it, "word_prefix");
      } else {
        consider(sign, extra == 0 ? 0 : 2, 0, extra, &*it, extra == 0 ? "exact" : "prefix");
      }
    }
    // Other forms of the words, in each language the query may be in (word_forms.h).
    int words = 0;
    std::vector<std::string> query_words = split_words(phrase_key(normalized, &words));
    if (!query_words.empty() && words <= kMaxPhraseWords) {
      for (const auto& [language, spoken] : spoken_) {
        if (!query.language.empty() && language != query.language) continue;
        std::vector<std::string> keys = form_keys(forms_of(query_words, spoken));
        for (std::size_t k = 0; k < keys.size(); ++k) {
          for (const auto* table : {&phrases_, &phrase_stems_}) {
            if (k == 0 && table == &phrases_) continue;  // the words as written: the exact tier
            auto found = table->find(scoped(language, keys[k]));
            if (found == table->end()) continue;
            for (const Phrase& phrase : found->second) {
              consider_match(phrase.sign, 1, 0, 0, &phrase.text, phrase.is_keyword, "stem");
            }
          }
        }
      }
    }
    // Typos: candidates share enough trigrams (an insertion, deletion or substitution changes at
    // most 3 of them, a transposition 4 — "hlelo" keeps only "lo$" of "hello"); for short
    // queries the filter cannot prune, so every term of a near length is a candidate.
    int bound = typo_bound(query_cps.size());
    if (bound > 0) {
      std::vector<std::uint64_t> grams = trigrams_of(query_cps);
      int needed = static_cast<int>(grams.size()) - 4 * bound;
      std::vector<std::uint32_t> candidates;
      if (needed >= 1) {
        std::unordered_map<std::uint32_t, int> shared;
        for (std::uint64_t gram : grams) {
          auto found = trigrams_.find(gram);
          if (found == trigrams_.end()) continue;
          for (std::uint32_t t : found->second) ++shared[t];
        }
        for (const auto& [t, count] : shared) {
          if (count >= needed) candidates.push_back(t);
        }
      } else {
        for (std::uint32_t t = 0; t < terms_.size(); ++t) candidates.push_back(t);
      }
      for (std::uint32_t t : candidates) {
        const Term& term = terms_[t];
        if (term.is_inner_word) continue;
        int distance = bounded_osa_distance(query_cps, term.code_points, bound);
        if (distance == 0 || distance > bound) continue;
        consider(term.sign, 4, distance, 0, &term, "fuzzy");
      }
    }
  }

  std::vector<Candidate> ranked;
  ranked.reserve(best.size());
  for (auto& [sign, candidate] : best) ranked.push_back(candidate);
  std::sort(ranked.begin(), ranked.end(),
            [](const Candidate& a, const Candidate& b) { return a.key < b.key; });

  SearchPage page;
  page.total = ranked.size();
  auto start = ranked.begin();
  if (after) {
    start = std::upper_bound(ranked.begin(), ranked.end(), *after,
                             [](const RankKey& key, const Candidate& c) { return key < c.key; });
  }
  int limit = std::clamp(query.limit, 1, kMaxSearchLimit);
  for (auto it = start; it != ranked.end() && static_cast<int>(page.hits.size()) < limit; ++it) {
    // The key holds the id; signs_ is sorted by id.
    auto sign_it = std::lower_bound(signs_.begin(), signs_.end(), it->key.id,
                                    [](const Sign& sign, std::int64_t id) { return sign.id < id; });
    const Sign& s = *sign_it;
    SearchHit hit;
    hit.sign_id = s.id;
    hit.language = s.language;
    hit.gloss = s.gloss;
    hit.notation = s.notation;
    hit.format = s.format;
    hit.revision = s.revision;
    hit.keywords = s.keywords;
    hit.match_type = it->type;
    hit.distance = it->key.distance;
    if (it->text) {
      hit.match_field = it->is_keyword ? "keyword" : "gloss";
      hit.match_text = *it->text;
    }
    page.hits.push_back(std::move(hit));
    if (static_cast<int>(page.hits.size()) == limit && std::next(it) != ranked.end()) {
      page.next_cursor = encode_cursor(it->key, hash);
    }
  }
  return page;
}

const std::vector<SearchIndex::Phrase>* SearchIndex::find_phrase(
    const std::string& language, const std::vector<std::vector<std::string>>& word_forms,
    std::string* type, std::string* form) const {
  std::vector<std::string> keys = form_keys(word_forms);
  auto in = [&](const std::unordered_map<std::string, std::vector<Phrase>>& table,
                const std::string& key) -> const std::vector<Phrase>* {
    auto found = table.find(scoped(language, key));
    return found == table.end() || found->second.empty() ? nullptr : &found->second;
  };
  auto answer = [&](const std::vector<Phrase>* phrases, const char* how, const std::string& key) {
    *type = how;
    *form = key;
    return phrases;
  };
  if (const auto* exact = in(phrases_, keys.front())) return answer(exact, "exact", keys.front());
  for (std::size_t k = 1; k < keys.size(); ++k) {
    if (const auto* written = in(phrases_, keys[k])) return answer(written, "stem", keys[k]);
  }
  for (const std::string& key : keys) {
    if (const auto* reduced = in(phrase_stems_, key)) return answer(reduced, "stem", key);
  }
  return nullptr;
}

LookupResult SearchIndex::lookup(const std::string& text, const std::string& language) const {
  LookupResult result;
  result.language = language;
  std::vector<char32_t> cps = decode_utf8(text);
  // Byte offset of each code point, for the spans the page highlights while signing.
  std::vector<std::size_t> byte_at(cps.size() + 1, 0);
  {
    std::size_t offset = 0;
    for (std::size_t i = 0; i < cps.size(); ++i) {
      byte_at[i] = offset;
      std::string encoded;
      append_utf8(encoded, cps[i]);
      offset += encoded.size();
    }
    byte_at[cps.size()] = offset;
  }
  auto span_text = [&](std::size_t begin, std::size_t end) {
    return text.substr(byte_at[begin], byte_at[end] - byte_at[begin]);
  };

  std::vector<TextItem> items = scan_text(cps);
  // Each word's forms (as typed, then its base forms), reduced once for every run it is part of.
  auto spoken = spoken_.find(language);
  std::vector<std::vector<std::string>> word_forms(items.size());
  for (std::size_t w = 0; w < items.size(); ++w) {
    if (items[w].kind != TextItem::Kind::Word) continue;
    word_forms[w] = forms_of({lower_range(cps, items[w].begin, items[w].end)},
                             spoken == spoken_.end() ? "" : spoken->second)
                        .front();
  }
  std::size_t i = 0;
  while (i < items.size()) {
    const TextItem& item = items[i];
    if (item.kind == TextItem::Kind::Pause) {
      LookupToken pause;
      pause.type = LookupToken::Type::Pause;
      pause.text = span_text(item.begin, item.end);
      pause.offset = byte_at[item.begin];
      pause.pause_s = item.pause_s;
      result.tokens.push_back(std::move(pause));
      ++i;
      continue;
    }
    // Greedy: the longest run of words (not crossing a pause) that is a keyword phrase.
    std::size_t run_end = i;
    while (run_end < items.size() && items[run_end].kind == TextItem::Kind::Word &&
           static_cast<int>(run_end - i) < kMaxPhraseWords) {
      ++run_end;
    }
    bool matched = false;
    for (std::size_t end = run_end; end > i && !matched; --end) {
      std::vector<std::vector<std::string>> run_forms(word_forms.begin() + i,
                                                      word_forms.begin() + end);
      LookupToken token;
      const std::vector<Phrase>* found =
          find_phrase(language, run_forms, &token.match_type, &token.match_form);
      if (found == nullptr) continue;
      const Sign& s = signs_[found->front().sign];
      token.type = LookupToken::Type::Sign;
      token.text = span_text(items[i].begin, items[end - 1].end);
      token.offset = byte_at[items[i].begin];
      token.sign_id = s.id;
      token.gloss = s.gloss;
      token.match_text = found->front().text;
      for (std::size_t k = 1; k < found->size(); ++k)
        token.alternatives.push_back(signs_[(*found)[k].sign].id);
      result.tokens.push_back(std::move(token));
      i = end;
      matched = true;
    }
    if (matched) continue;

    // Fingerspell the word: longest alphabet entry first (digraphs such as "ch" before "c").
    LookupToken spell;
    spell.type = LookupToken::Type::Fingerspell;
    spell.text = span_text(item.begin, item.end);
    spell.offset = byte_at[item.begin];
    std::size_t c = item.begin;
    while (c < item.end) {
      if (is_word_joiner(cps[c])) {
        ++c;  // apostrophes have no manual sign of their own
        continue;
      }
      bool found_letter = false;
      for (std::size_t length = std::min<std::size_t>(kMaxLetterCodePoints, item.end - c);
           length >= 1; --length) {
        std::string lowered;
        for (std::size_t k = c; k < c + length; ++k) append_utf8(lowered, to_lower(cps[k]));
        auto found = letters_.find(scoped(language, lowered));
        if (found == letters_.end()) continue;
        spell.letters.push_back(LookupLetter{found->second.first, signs_[found->second.second].id,
                                             signs_[found->second.second].gloss});
        c += length;
        found_letter = true;
        break;
      }
      if (!found_letter) {
        spell.letters.push_back(LookupLetter{span_text(c, c + 1), std::nullopt, ""});
        ++c;
      }
    }
    result.tokens.push_back(std::move(spell));
    ++i;
  }
  return result;
}

}  // namespace sw::store
