// WordForms: the base forms of an inflected word ("books" -> "book", "signed" -> "sign",
// "книги" -> "книга"), so that search and phrase lookup find a sign whose keyword is another form
// of the typed word. Both sides are reduced: the typed words and the keywords (search_index.cpp).
//
// Hunspell does the reduction, with the Debian dictionaries en_US (hunspell-en-us) and uk_UA
// (hunspell-uk): its stem() strips the affixes its dictionary declares for the word. Snowball
// (libstemmer) was the other candidate; its algorithms have no Ukrainian (2.2: Russian is the
// nearest), and a stemmer cuts words to non-words ("happi") where Hunspell returns dictionary
// words, which is what a keyword is. Spoken languages without a dictionary are not reduced.
//
// Does not: lemmatise irregular forms the dictionary lists as words of their own ("went",
// "children", "матері" stay as typed: Hunspell's en_US and uk_UA carry no morphology for them),
// or pick one meaning ("leaves" is only "leave").
//
// Limits, with their reason: a base form shorter than kMinStemCodePoints is dropped (en_US
// reduces "is" to "i" and "us" to "u", which would turn the verb into the pronoun sign ME).
//
// Thread-safe: each dictionary loads on first use (uk_UA takes about a second) and is then used
// under its own mutex (Hunspell does not promise concurrent calls on one object).
#pragma once

#include <memory>
#include <string>
#include <vector>

namespace sw::store {

constexpr std::size_t kMinStemCodePoints = 3;

class WordForms {
 public:
  // The process-wide instance, reading the dictionaries from SIGNWEAVE_HUNSPELL_DIR when that is
  // set, else from the directory CMake found them in.
  static WordForms& shared();

  explicit WordForms(std::string dictionary_dir);
  ~WordForms();
  WordForms(const WordForms&) = delete;
  WordForms& operator=(const WordForms&) = delete;

  // True when `spoken` (ISO 639-1: "en", "uk") has a dictionary this instance can load.
  bool covers(const std::string& spoken);
  // The base forms of `word` (lower-case UTF-8) other than the word itself, lower-cased, in the
  // dictionary's order, each once. Empty for a word the dictionary does not know, a base form, or
  // a language without a dictionary.
  std::vector<std::string> stems(const std::string& spoken, const std::string& word);

 private:
  struct Dictionary;
  Dictionary* dictionary_for(const std::string& spoken);

  std::string dictionary_dir_;
  std::vector<std::unique_ptr<Dictionary>> dictionaries_;
};

}  // namespace sw::store
