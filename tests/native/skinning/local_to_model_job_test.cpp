// Tests for skinning/local_to_model_job.h: FK and the skinning palette, and every invalid job.
#include "skinning/local_to_model_job.h"

#include <glm/gtc/quaternion.hpp>
#include <gtest/gtest.h>

namespace sw::skinning {
namespace {

skeleton::Skeleton chain() {
  skeleton::Skeleton s;
  for (int i = 0; i < 3; ++i) {
    skeleton::Joint j;
    j.name = "j" + std::to_string(i);
    j.parent = i - 1;
    j.rest.translation = i == 0 ? glm::vec3(0.0f) : glm::vec3(1.0f, 0.0f, 0.0f);
    s.joints.push_back(j);
  }
  return s;
}

std::vector<math::Transform> rest_of(const skeleton::Skeleton& s) {
  std::vector<math::Transform> t;
  for (const auto& j : s.joints) t.push_back(j.rest);
  return t;
}

TEST(LocalToModelJob, ChainsLocalTransforms) {
  const skeleton::Skeleton s = chain();
  std::vector<math::Transform> locals = rest_of(s);
  locals[1].rotation = glm::angleAxis(glm::radians(90.0f), glm::vec3(0, 0, 1));
  std::vector<glm::mat4> models(3);
  LocalToModelJob job{&s, locals.data(), 3, models.data(), 3, 0};
  ASSERT_EQ(job.validate(), "");
  ASSERT_TRUE(job.run());
  // Joint 1 at x=1 rotated 90° about Z: joint 2 (1 along its x) lands at (1, 1, 0).
  EXPECT_NEAR(models[2][3].x, 1.0f, 1e-6f);
  EXPECT_NEAR(models[2][3].y, 1.0f, 1e-6f);
}

TEST(LocalToModelJob, PartialUpdateRecomputesOnlyFromJoint) {
  const skeleton::Skeleton s = chain();
  std::vector<math::Transform> locals = rest_of(s);
  std::vector<glm::mat4> models(3);
  LocalToModelJob job{&s, locals.data(), 3, models.data(), 3, 0};
  ASSERT_TRUE(job.run());
  locals[0].translation = glm::vec3(0, 5, 0);   // ignored: before from_joint
  locals[2].translation = glm::vec3(2, 0, 0);
  job.from_joint = 2;
  ASSERT_TRUE(job.run());
  EXPECT_NEAR(models[0][3].y, 0.0f, 1e-6f);
  EXPECT_NEAR(models[2][3].x, 3.0f, 1e-6f);
}

TEST(LocalToModelJob, ComposeTrsMatchesTranslateRotateScale) {
  math::Transform t;
  t.translation = {1, 2, 3};
  t.rotation = glm::angleAxis(0.7f, glm::normalize(glm::vec3(1, 2, 3)));
  t.scale = {2, 3, 4};
  const glm::mat4 expected = glm::translate(glm::mat4(1.0f), t.translation) * glm::mat4_cast(t.rotation) *
                             glm::scale(glm::mat4(1.0f), t.scale);
  const glm::mat4 got = compose_trs(t);
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r) EXPECT_NEAR(got[c][r], expected[c][r], 1e-6f);
}

TEST(LocalToModelJob, ValidateRejectsEveryBadConfiguration) {
  skeleton::Skeleton s = chain();
  std::vector<math::Transform> locals = rest_of(s);
  std::vector<glm::mat4> models(3);
  const LocalToModelJob good{&s, locals.data(), 3, models.data(), 3, 0};
  ASSERT_EQ(good.validate(), "");
  LocalToModelJob j = good; j.skeleton = nullptr; EXPECT_NE(j.validate(), "");
  j = good; j.locals = nullptr; EXPECT_NE(j.validate(), "");
  j = good; j.models = nullptr; EXPECT_NE(j.validate(), "");
  j = good; j.local_count = 2; EXPECT_NE(j.validate(), "");
  j = good; j.model_count = 2; EXPECT_NE(j.validate(), "");
  j = good; j.from_joint = 4; EXPECT_NE(j.validate(), "");
  j = good; j.from_joint = -1; EXPECT_NE(j.validate(), "");
  EXPECT_FALSE(j.run());
  skeleton::Skeleton bad = s;
  bad.joints[1].parent = 2;  // child before parent
  j = good; j.skeleton = &bad; EXPECT_NE(j.validate(), "");
}

TEST(SkinningMatrixJob, ModelTimesInverseBind) {
  std::vector<glm::mat4> models = {glm::translate(glm::mat4(1.0f), glm::vec3(1, 2, 3))};
  std::vector<glm::mat4> ibm = {glm::translate(glm::mat4(1.0f), glm::vec3(-1, -2, -3))};
  std::vector<glm::mat4> out(1);
  SkinningMatrixJob job{models.data(), ibm.data(), 1, out.data()};
  ASSERT_TRUE(job.run());
  EXPECT_EQ(out[0], glm::mat4(1.0f));
  SkinningMatrixJob bad = job; bad.models = nullptr; EXPECT_NE(bad.validate(), ""); EXPECT_FALSE(bad.run());
  bad = job; bad.inverse_binds = nullptr; EXPECT_NE(bad.validate(), "");
  bad = job; bad.skinning_matrices = nullptr; EXPECT_NE(bad.validate(), "");
  bad = job; bad.joint_count = -1; EXPECT_NE(bad.validate(), "");
}

}  // namespace
}  // namespace sw::skinning
