// server/store/store.h: the database operations without HTTP — migration, validation on write,
// optimistic concurrency, revisions, search ranking, lookup, tokens, import modes.
#include "store/store.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <string>

#include "store/api_error.h"

namespace sw::store {
namespace {

class StoreTest : public ::testing::Test {
 protected:
  void SetUp() override {
    path_ = (std::filesystem::temp_directory_path() /
             ("signweave_store_test_" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) + "_" +
              ::testing::UnitTest::GetInstance()->current_test_info()->name() + ".db"))
                .string();
    Remove();
    store_ = Store::open(path_);
    store_->upsert_languages({{"ase", "American Sign Language", "en", "latin"}});
  }
  void TearDown() override {
    store_.reset();
    Remove();
  }
  void Remove() {
    for (const char* suffix : {"", "-wal", "-shm"}) std::remove((path_ + suffix).c_str());
  }
  SignRecord Create(const std::string& gloss, std::vector<std::string> keywords = {}, std::string letter = "") {
    SignInput input;
    input.language = "ase";
    input.gloss = gloss;
    input.notation = "R(H(flat), E(u), P(o), Loc(chin, centre, touch))";
    for (auto& word : keywords) input.keywords.push_back({word, ""});
    if (!letter.empty()) input.letter = letter;
    return store_->create_sign(input, "tester");
  }
  int StatusOf(const std::function<void()>& action) {
    try {
      action();
    } catch (const ApiError& error) {
      return error.status();
    }
    return 0;
  }

  std::string path_;
  std::unique_ptr<Store> store_;
};

TEST_F(StoreTest, MigratesToTheLatestVersion) { EXPECT_GE(store_->schema_version(), 1); }

TEST_F(StoreTest, RefusesNotationTheParserRejects) {
  SignInput input;
  input.language = "ase";
  input.gloss = "BAD";
  input.notation = "R(H(flax))";
  try {
    store_->create_sign(input, "tester");
    FAIL() << "an invalid notation was stored";
  } catch (const ApiError& error) {
    EXPECT_EQ(error.status(), 422);
    EXPECT_EQ(error.detail()["diagnostics"][0]["column"], 5);
  }
  EXPECT_EQ(store_->count_live_signs(), 0);
}

TEST_F(StoreTest, StaleRevisionIsAConflictAndChangesNothing) {
  SignRecord sign = Create("HELLO");
  SignInput edit;
  edit.gloss = "HELLO";
  edit.notation = "R(H(fist), E(u), P(o), Loc(chin, centre, touch))";
  EXPECT_EQ(store_->update_sign(sign.id, 1, edit, "tester").revision, 2);
  EXPECT_EQ(StatusOf([&] { store_->update_sign(sign.id, 1, edit, "tester"); }), 409);
  EXPECT_EQ(StatusOf([&] { store_->delete_sign(sign.id, 1, "tester"); }), 409);
  EXPECT_EQ(store_->get_sign(sign.id)->revision, 2);
  EXPECT_EQ(store_->history(sign.id).size(), 2u);
  store_->delete_sign(sign.id, 2, "tester");
  EXPECT_TRUE(store_->get_sign(sign.id)->deleted);
  EXPECT_EQ(StatusOf([&] { store_->update_sign(sign.id, 3, edit, "tester"); }), 410);
}

TEST_F(StoreTest, SearchRanksExactThenPrefixThenTypos) {
  Create("HELP", {"help"});
  Create("HELLO", {"hello"});
  Create("HELMET", {"helmet"});
  SearchQuery query;
  query.text = "help";
  SearchPage page = store_->search(query);
  ASSERT_GE(page.hits.size(), 1u);
  EXPECT_EQ(page.hits[0].gloss, "HELP");
  EXPECT_EQ(page.hits[0].match_type, "exact");
  query.text = "hel";
  page = store_->search(query);
  ASSERT_EQ(page.hits.size(), 3u);
  EXPECT_EQ(page.hits[0].gloss, "HELP");  // shortest completion first, then gloss order
  query.text = "helmtt";
  page = store_->search(query);
  ASSERT_EQ(page.hits.size(), 1u);
  EXPECT_EQ(page.hits[0].match_type, "fuzzy");
}

TEST_F(StoreTest, LookupMatchesPhrasesGreedilyAndSpellsTheRest) {
  Create("THANK-YOU", {"thank you"});
  Create("YOU", {"you"});
  Create("ASE-A", {}, "A");
  LookupResult result = store_->lookup("Thank you, you aa!", "ase");
  ASSERT_EQ(result.tokens.size(), 5u);
  EXPECT_EQ(result.tokens[0].gloss, "THANK-YOU");
  EXPECT_EQ(result.tokens[1].type, LookupToken::Type::Pause);
  EXPECT_EQ(result.tokens[2].gloss, "YOU");
  EXPECT_EQ(result.tokens[3].type, LookupToken::Type::Fingerspell);
  EXPECT_EQ(result.tokens[3].letters.size(), 2u);
  EXPECT_EQ(result.tokens[4].type, LookupToken::Type::Pause);
}

TEST_F(StoreTest, TokensAreVerifiedNotStored) {
  std::string token = store_->create_token("editor");
  EXPECT_EQ(store_->verify_token(token).result, TokenCheck::Result::Valid);
  EXPECT_EQ(store_->verify_token(token).name, "editor");
  EXPECT_EQ(store_->verify_token(token + "x").result, TokenCheck::Result::Unknown);
  EXPECT_EQ(StatusOf([&] { store_->create_token("editor"); }), 409);
}

TEST_F(StoreTest, AllOrNothingImportWritesNothingOnOneBadLine) {
  std::vector<ImportItem> items = {
      {"t", 1, {{"gloss", "ONE"}, {"notation", "R(H(flat), E(u), P(o), Loc(chin, centre, touch))"}}, "ase"},
      {"t", 2, {{"gloss", "TWO"}, {"notation", "R(H(flax))"}}, "ase"},
  };
  ImportReport strict = store_->import_items(items, "tester", ImportMode::AllOrNothing);
  EXPECT_FALSE(strict.committed);
  ASSERT_EQ(strict.rejected.size(), 1u);
  EXPECT_EQ(strict.rejected[0].line, 2);
  EXPECT_EQ(store_->count_live_signs(), 0);
  ImportReport lenient = store_->import_items(items, "tester", ImportMode::SkipInvalid);
  EXPECT_EQ(lenient.created, 1);
  EXPECT_EQ(store_->count_live_signs(), 1);
}

}  // namespace
}  // namespace sw::store
