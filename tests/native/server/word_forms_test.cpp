// server/store/word_forms.h and the lookup and search that use it: inflected words find the sign
// of their base form ("books" -> BOOK) before falling back to fingerspelling, in English and
// Ukrainian, over the table in tests/server/fixtures/inflected_forms.json.
#include "store/word_forms.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <string>

#include <nlohmann/json.hpp>

#include "store/store.h"

namespace sw::store {
namespace {

using nlohmann::json;

bool Contains(const std::vector<std::string>& list, const std::string& value) {
  return std::find(list.begin(), list.end(), value) != list.end();
}

TEST(WordForms, ReducesEnglishAndUkrainianInflections) {
  WordForms& forms = WordForms::shared();
  ASSERT_TRUE(forms.covers("en"));
  ASSERT_TRUE(forms.covers("uk"));
  EXPECT_TRUE(Contains(forms.stems("en", "books"), "book"));
  EXPECT_TRUE(Contains(forms.stems("en", "signed"), "sign"));
  EXPECT_TRUE(Contains(forms.stems("en", "mothers"), "mother"));
  EXPECT_TRUE(Contains(forms.stems("uk", "книги"), "книга"));
  EXPECT_TRUE(Contains(forms.stems("uk", "читала"), "читати"));
}

TEST(WordForms, NeverReturnsTheWordItselfOrAFormTooShortToBeAKeyword) {
  WordForms& forms = WordForms::shared();
  EXPECT_TRUE(forms.stems("en", "book").empty());
  // en_US reduces "is" to "i": the verb must not become the pronoun.
  EXPECT_TRUE(forms.stems("en", "is").empty());
  EXPECT_TRUE(forms.stems("en", "us").empty());
}

TEST(WordForms, LanguagesWithoutADictionaryAndMissingFilesAreMatchedAsTyped) {
  EXPECT_FALSE(WordForms::shared().covers("de"));
  EXPECT_TRUE(WordForms::shared().stems("de", "bücher").empty());
  WordForms nowhere("/nonexistent-signweave-dictionaries");
  EXPECT_FALSE(nowhere.covers("en"));
  EXPECT_TRUE(nowhere.stems("en", "books").empty());
}

class InflectionTest : public ::testing::Test {
 protected:
  void SetUp() override {
    path_ = (std::filesystem::temp_directory_path() /
             ("signweave_inflection_test_" +
              std::to_string(::testing::UnitTest::GetInstance()->random_seed()) + "_" +
              ::testing::UnitTest::GetInstance()->current_test_info()->name() + ".db"))
                .string();
    Remove();
    store_ = Store::open(path_);
    store_->upsert_languages({{"ase", "American Sign Language", "en", "latin"},
                              {"ukl", "Ukrainian Sign Language", "uk", "cyrillic"}});
  }
  void TearDown() override {
    store_.reset();
    Remove();
  }
  void Remove() {
    for (const char* suffix : {"", "-wal", "-shm"}) std::remove((path_ + suffix).c_str());
  }
  void Create(const std::string& language, const std::string& gloss,
              std::vector<std::string> keywords) {
    SignInput input;
    input.language = language;
    input.gloss = gloss;
    input.notation = "R(H(flat), E(u), P(o), Loc(chin, centre, touch))";
    for (auto& word : keywords) input.keywords.push_back({word, ""});
    store_->create_sign(input, "tester");
  }

  std::string path_;
  std::unique_ptr<Store> store_;
};

json ReadTable() {
  std::ifstream in(std::string(SIGNWEAVE_SOURCE_DIR) +
                   "/tests/server/fixtures/inflected_forms.json");
  return json::parse(in);
}

TEST_F(InflectionTest, EveryInflectedFormOfTheTableFindsItsBaseSign) {
  json table = ReadTable()["forms"];
  ASSERT_GE(table.size(), 40u);
  std::map<std::pair<std::string, std::string>, std::set<std::string>>
      signs;  // (language, gloss) -> keywords
  for (const json& row : table)
    signs[{row["language"], row["gloss"]}].insert(row["keyword"].get<std::string>());
  for (const auto& [key, keywords] : signs)
    Create(key.first, key.second, {keywords.begin(), keywords.end()});

  int found = 0;
  for (const json& row : table) {
    const std::string typed = row["typed"];
    LookupResult result = store_->lookup(typed, row["language"]);
    ASSERT_EQ(result.tokens.size(), 1u) << typed;
    const LookupToken& token = result.tokens[0];
    EXPECT_EQ(token.type, LookupToken::Type::Sign) << typed << " was not found as a sign";
    EXPECT_EQ(token.gloss, row["gloss"].get<std::string>()) << typed;
    EXPECT_EQ(token.match_type, "stem") << typed;
    EXPECT_EQ(token.match_text, row["keyword"].get<std::string>()) << typed;
    found +=
        token.type == LookupToken::Type::Sign && token.gloss == row["gloss"].get<std::string>();
  }
  std::printf("inflected forms that found their base sign: %d of %zu\n", found, table.size());
}

TEST_F(InflectionTest, TheWordAsTypedWinsAndThePlanSaysWhichFormMatched) {
  Create("ase", "SIGN", {"sign"});
  Create("ase", "SIGNED-DOCUMENT", {"signed"});
  Create("ase", "BOOK", {"book"});
  LookupResult result = store_->lookup("Signed books", "ase");
  ASSERT_EQ(result.tokens.size(), 2u);
  EXPECT_EQ(result.tokens[0].gloss, "SIGNED-DOCUMENT");
  EXPECT_EQ(result.tokens[0].match_type, "exact");
  EXPECT_EQ(result.tokens[1].gloss, "BOOK");
  EXPECT_EQ(result.tokens[1].match_type, "stem");
  EXPECT_EQ(result.tokens[1].match_form, "book");
  EXPECT_EQ(result.tokens[1].text, "books");
}

TEST_F(InflectionTest, KeywordsAreReducedTooAndPhrasesMatchWordByWord) {
  Create("ase", "SIGN", {"signing"});  // the keyword is the inflected one
  Create("ase", "SIGN-LANGUAGE", {"sign language"});
  Create("ase", "ME", {"me", "I"});
  LookupResult signs = store_->lookup("signs", "ase");
  ASSERT_EQ(signs.tokens.size(), 1u);
  EXPECT_EQ(signs.tokens[0].gloss, "SIGN");
  LookupResult languages = store_->lookup("signed languages", "ase");
  ASSERT_EQ(languages.tokens.size(), 1u);
  EXPECT_EQ(languages.tokens[0].gloss, "SIGN-LANGUAGE");
  EXPECT_EQ(languages.tokens[0].match_form, "sign language");
  // "is" must be fingerspelled, not signed ME.
  LookupResult is = store_->lookup("is", "ase");
  ASSERT_EQ(is.tokens.size(), 1u);
  EXPECT_EQ(is.tokens[0].type, LookupToken::Type::Fingerspell);
}

TEST_F(InflectionTest, SearchRanksAnotherFormAfterExactAndBeforePrefix) {
  Create("ase", "BOOK", {"book"});
  Create("ase", "BOOKS-CLUB", {"books club"});
  Create("ase", "BOOKSHOP", {"books"});
  SearchQuery query;
  query.text = "books";
  SearchPage page = store_->search(query);
  ASSERT_EQ(page.hits.size(), 3u);
  EXPECT_EQ(page.hits[0].gloss, "BOOKSHOP");
  EXPECT_EQ(page.hits[0].match_type, "exact");
  EXPECT_EQ(page.hits[1].gloss, "BOOK");
  EXPECT_EQ(page.hits[1].match_type, "stem");
  EXPECT_EQ(page.hits[1].match_field, "keyword");
  EXPECT_EQ(page.hits[1].match_text, "book");
  EXPECT_EQ(page.hits[2].gloss, "BOOKS-CLUB");
  EXPECT_EQ(page.hits[2].match_type, "prefix");
  query.language = "ukl";
  EXPECT_TRUE(store_->search(query).hits.empty());
}

}  // namespace
}  // namespace sw::store
