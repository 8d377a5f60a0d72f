// Skeleton lookup and validation (skeleton/skeleton.h).
#include "skeleton/skeleton.h"

#include <gtest/gtest.h>

#include <cmath>

namespace sw::skeleton {
namespace {

Skeleton chain() {
  Skeleton s;
  s.joints = {{"hips", -1, {}}, {"spine", 0, {}}, {"head", 1, {}}};
  return s;
}

TEST(Skeleton, FindByExactName) {
  const Skeleton s = chain();
  EXPECT_EQ(s.find("spine"), 1);
  EXPECT_EQ(s.find("Spine"), -1);
  EXPECT_EQ(s.find(""), -1);
}

TEST(Skeleton, ValidChainAndEmptySkeletonPass) {
  EXPECT_EQ(chain().validate(), "");
  EXPECT_EQ(Skeleton{}.validate(), "");
}

TEST(Skeleton, ValidateNamesEachProblem) {
  struct Case {
    const char* what;
    void (*break_it)(Skeleton&);
    const char* expected_fragment;
  };
  const Case cases[] = {
      {"parent after child", [](Skeleton& s) { s.joints[1].parent = 2; }, "comes after it"},
      {"own parent", [](Skeleton& s) { s.joints[1].parent = 1; }, "its own parent"},
      {"out of range", [](Skeleton& s) { s.joints[2].parent = 7; }, "out of range"},
      {"negative", [](Skeleton& s) { s.joints[2].parent = -3; }, "out of range"},
      {"duplicate", [](Skeleton& s) { s.joints[2].name = "hips"; }, "duplicate name"},
      {"empty name", [](Skeleton& s) { s.joints[1].name.clear(); }, "empty name"},
      {"nan", [](Skeleton& s) { s.joints[1].rest.translation.y = NAN; }, "non-finite"},
      {"inf scale", [](Skeleton& s) { s.joints[1].rest.scale.x = INFINITY; }, "non-finite"},
      {"bad quaternion", [](Skeleton& s) { s.joints[1].rest.rotation = glm::quat(2, 0, 0, 0); },
       "unit quaternion"},
  };
  for (const Case& c : cases) {
    Skeleton s = chain();
    c.break_it(s);
    const std::string message = s.validate();
    EXPECT_NE(message.find(c.expected_fragment), std::string::npos) << c.what << ": " << message;
  }
}

TEST(Skeleton, ValidateMessageNamesTheJoint) {
  Skeleton s = chain();
  s.joints[2].parent = 5;
  EXPECT_NE(s.validate().find("'head'"), std::string::npos);
}

}  // namespace
}  // namespace sw::skeleton
