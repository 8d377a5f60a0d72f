// The project's own avatar (models/signweave-avatar.glb) through the whole synthesis: loaded,
// anchors computed from its mesh, capsules from its mesh extents; touch reach, no-contact
// distances and penetration measured on it.
#include "synthesis/signing_avatar.h"

#include <gtest/gtest.h>

#include <fstream>

#include "synthesis_fixture.h"

namespace sw::synthesis {
namespace {

using namespace testing;
using notation::BodyLevel;
using notation::Contact;
using notation::Side;

const std::string kModel = std::string(SIGNWEAVE_SOURCE_DIR) + "/models/signweave-avatar.glb";

class SynthesisOnProjectAvatar : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    if (!std::ifstream(kModel).good()) return;
    avatar_ = new SigningAvatar(load_signing_avatar_file(kModel));
  }
  static void TearDownTestSuite() {
    delete avatar_;
    avatar_ = nullptr;
  }
  void SetUp() override {
    if (!avatar_) GTEST_SKIP() << "models/signweave-avatar.glb not present";
    ASSERT_TRUE(avatar_->ok()) << avatar_->error;
  }
  static SigningAvatar* avatar_;
};
SigningAvatar* SynthesisOnProjectAvatar::avatar_ = nullptr;

TEST_F(SynthesisOnProjectAvatar, TouchReachesFacesAndTrunkWithin1cm) {
  float worst = 0.0f;
  for (BodyLevel level : {BodyLevel::Forehead, BodyLevel::Nose, BodyLevel::Chin, BodyLevel::Cheeks,
                          BodyLevel::Chest, BodyLevel::Stomach})
    for (Side side : {Side::Right, Side::Centre}) {
      notation::SignSpec s = sign_at(index_point(), level, side, Contact::Touch);
      bool trunk = static_cast<int>(level) >= static_cast<int>(BodyLevel::Chest);
      s.dominant.orientation.extended_finger = trunk ? notation::Direction{1, 0, 0} : notation::Direction{0, 1, 1};
      s.dominant.orientation.palm = {0, 0, -1};
      SynthesisResult r = synthesize_sign(s, avatar_->avatar);
      ASSERT_TRUE(r.ok()) << r.errors[0].message;
      ASSERT_EQ(r.report.contact_distances_m.size(), 1u);
      EXPECT_LT(r.report.contact_distances_m[0], 0.01f) << "level " << int(level) << " side " << int(side);
      worst = std::max(worst, r.report.contact_distances_m[0]);
    }
  RecordProperty("worst_touch_reach_error_mm", std::to_string(worst * 1000.0f));
}

TEST_F(SynthesisOnProjectAvatar, NoContactStays3To10cmAway) {
  for (BodyLevel level : {BodyLevel::Chin, BodyLevel::Chest, BodyLevel::Shoulders})
    for (Contact c : {Contact::None, Contact::Close}) {
      notation::SignSpec s = sign_at(flat(), level, Side::Right, c);
      s.dominant.orientation.extended_finger = {0, 1, 0};
      s.dominant.orientation.palm = {0, 0, 1};
      SynthesisResult r = synthesize_sign(s, avatar_->avatar);
      ASSERT_TRUE(r.ok());
      float d = r.report.contact_distances_m[0];
      EXPECT_GE(d, 0.03f) << int(level) << " " << int(c);
      EXPECT_LE(d, 0.10f) << int(level) << " " << int(c);
    }
}

TEST_F(SynthesisOnProjectAvatar, FingerspellingSequenceDoesNotPenetrate) {
  std::vector<PhraseItem> items;
  const notation::HandShape shapes[] = {fist(), flat(), index_point(), shape_all(notation::kFingerRound, notation::kThumbOpposed)};
  for (int i = 0; i < 8; ++i) {
    PhraseItem it;
    it.kind = PhraseItem::Kind::Letter;
    it.sign = sign_at(shapes[i % 4], BodyLevel::Shoulders, Side::Right, Contact::None);
    it.sign.dominant.orientation.extended_finger = {0, 1, 0};
    it.sign.dominant.orientation.palm = {0, 0, 1};
    it.label = std::string(1, static_cast<char>('A' + i));
    items.push_back(it);
  }
  SynthesisResult r = synthesize_phrase(items, avatar_->avatar);
  ASSERT_TRUE(r.ok());
  EXPECT_LE(r.report.max_penetration_m, 0.005f) << (r.report.warnings.empty() ? "" : r.report.warnings.back());
  RecordProperty("max_penetration_mm", std::to_string(r.report.max_penetration_m * 1000.0f));
}

}  // namespace
}  // namespace sw::synthesis
