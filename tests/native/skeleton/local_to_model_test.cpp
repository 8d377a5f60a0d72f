// Forward kinematics job (skeleton/local_to_model.h): correctness, partial updates, validation.
#include "skeleton/local_to_model.h"

#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include "../support/matrix_compare.h"
#include "skeleton/synthetic_humanoid.h"

namespace sw::skeleton {
namespace {

using test::max_abs_diff;

// Reference: each joint's model matrix as the product of the chain from the root, computed
// independently of the job's single pass.
glm::mat4 chain_product(const Skeleton& s, const std::vector<math::Transform>& local, int joint) {
  glm::mat4 m(1.0f);
  for (int j = joint; j >= 0; j = s.joints[static_cast<std::size_t>(j)].parent) {
    m = local[static_cast<std::size_t>(j)].to_matrix() * m;
  }
  return m;
}

std::vector<glm::mat4> run_full(const Skeleton& s, const std::vector<math::Transform>& local) {
  std::vector<glm::mat4> out(local.size());
  LocalToModelJob job;
  job.skeleton = &s;
  job.input = local;
  job.output = out;
  EXPECT_TRUE(job.run());
  return out;
}

TEST(LocalToModel, TwoJointArmByHand) {
  Skeleton s;
  s.joints = {{"shoulder", -1, {}}, {"elbow", 0, {}}};
  s.joints[1].rest.translation = {0.3f, 0, 0};
  std::vector<math::Transform> local = {s.joints[0].rest, s.joints[1].rest};
  local[0].rotation = glm::angleAxis(glm::radians(90.0f), glm::vec3(0, 0, 1));
  const auto model = run_full(s, local);
  // The shoulder turned 90° about Z: the elbow, 0.3 m along +X, is now 0.3 m along +Y.
  EXPECT_NEAR(model[1][3].x, 0.0f, 1e-6f);
  EXPECT_NEAR(model[1][3].y, 0.3f, 1e-6f);
}

TEST(LocalToModel, MatchesChainProductOnHumanoid) {
  const Skeleton s = make_synthetic_humanoid();
  const auto local = make_synthetic_pose(s, 7);
  const auto model = run_full(s, local);
  for (int i = 0; i < s.joint_count(); ++i) {
    EXPECT_LT(max_abs_diff(model[static_cast<std::size_t>(i)], chain_product(s, local, i)), 1e-5f)
        << s.joints[static_cast<std::size_t>(i)].name;
  }
}

TEST(LocalToModel, MatrixInputEqualsTransformInput) {
  const Skeleton s = make_synthetic_humanoid();
  const auto local = make_synthetic_pose(s, 8);
  std::vector<glm::mat4> local_matrices;
  for (const auto& t : local) local_matrices.push_back(t.to_matrix());
  std::vector<glm::mat4> out(local.size());
  LocalToModelJob job;
  job.skeleton = &s;
  job.input_matrices = local_matrices;
  job.output = out;
  ASSERT_TRUE(job.run());
  const auto expected = run_full(s, local);
  for (std::size_t i = 0; i < out.size(); ++i) EXPECT_EQ(out[i], expected[i]);
}

TEST(LocalToModel, RootMatrixPlacesTheWholeBody) {
  const Skeleton s = make_synthetic_humanoid();
  const auto local = make_synthetic_pose(s, 9);
  const glm::mat4 placement = glm::translate(glm::mat4(1), glm::vec3(2, 0, -1));
  std::vector<glm::mat4> out(local.size());
  LocalToModelJob job;
  job.skeleton = &s;
  job.input = local;
  job.output = out;
  job.root = &placement;
  ASSERT_TRUE(job.run());
  const auto unplaced = run_full(s, local);
  for (std::size_t i = 0; i < out.size(); ++i)
    EXPECT_LT(max_abs_diff(out[i], placement * unplaced[i]), 1e-5f);
}

TEST(LocalToModel, PartialUpdateOfAHandEqualsFullUpdate) {
  const Skeleton s = make_synthetic_humanoid();
  auto local = make_synthetic_pose(s, 10);
  auto model = run_full(s, local);
  const auto before = model;
  // "IK" changes the right hand and one of its fingers; only that sub-tree is recomputed.
  const int hand = s.find("rightHand");
  local[static_cast<std::size_t>(hand)].rotation = glm::angleAxis(0.9f, glm::vec3(0, 1, 0));
  local[static_cast<std::size_t>(s.find("rightIndexIntermediate"))].rotation =
      glm::angleAxis(-0.5f, glm::vec3(0, 0, 1));
  LocalToModelJob job;
  job.skeleton = &s;
  job.input = local;
  job.output = model;
  job.from = hand;
  ASSERT_TRUE(job.run());
  const auto full = run_full(s, local);
  for (int i = 0; i < s.joint_count(); ++i) {
    EXPECT_EQ(model[static_cast<std::size_t>(i)], full[static_cast<std::size_t>(i)])
        << s.joints[static_cast<std::size_t>(i)].name;
  }
  // ... and joints outside the sub-tree were not touched (the left hand's matrix is bit-identical).
  EXPECT_EQ(model[static_cast<std::size_t>(s.find("leftHand"))],
            before[static_cast<std::size_t>(s.find("leftHand"))]);
  EXPECT_NE(model[static_cast<std::size_t>(s.find("rightIndexTip"))],
            before[static_cast<std::size_t>(s.find("rightIndexTip"))]);
}

TEST(LocalToModel, PartialUpdateWorksWhenTheSubtreeIsNotContiguous) {
  // Breadth-first order: parents before children, but a sub-tree's joints are interleaved with
  // others. The job must still update exactly the sub-tree.
  Skeleton s;
  s.joints = {{"root", -1, {}}, {"a", 0, {}},  {"b", 0, {}},
              {"a1", 1, {}},    {"b1", 2, {}}, {"a2", 3, {}}};
  for (auto& j : s.joints) j.rest.translation = {0.1f, 0.2f, 0.0f};
  auto local = std::vector<math::Transform>{};
  for (const auto& j : s.joints) local.push_back(j.rest);
  auto model = run_full(s, local);
  const glm::mat4 b1_before = model[4];
  local[1].rotation = glm::angleAxis(1.0f, glm::vec3(1, 0, 0));
  local[2].rotation = glm::angleAxis(1.0f, glm::vec3(0, 1, 0));  // changed but not asked for
  LocalToModelJob job;
  job.skeleton = &s;
  job.input = local;
  job.output = model;
  job.from = 1;
  ASSERT_TRUE(job.run());
  const auto full = run_full(s, local);
  EXPECT_EQ(model[1], full[1]);
  EXPECT_EQ(model[3], full[3]);
  EXPECT_EQ(model[5], full[5]);
  EXPECT_EQ(model[4], b1_before);  // b's sub-tree kept its old matrices
}

TEST(LocalToModel, ToStopsThePass) {
  const Skeleton s = make_synthetic_humanoid();
  const auto local = make_synthetic_pose(s, 11);
  std::vector<glm::mat4> out(local.size(), glm::mat4(0.0f));
  LocalToModelJob job;
  job.skeleton = &s;
  job.input = local;
  job.output = out;
  job.to = 8;  // torso and head only
  ASSERT_TRUE(job.run());
  const auto full = run_full(s, local);
  for (int i = 0; i <= 8; ++i)
    EXPECT_EQ(out[static_cast<std::size_t>(i)], full[static_cast<std::size_t>(i)]);
  for (int i = 9; i < s.joint_count(); ++i)
    EXPECT_EQ(out[static_cast<std::size_t>(i)], glm::mat4(0.0f));
}

TEST(LocalToModel, ValidateRejectsEveryInvalidConfiguration) {
  const Skeleton s = make_synthetic_humanoid();
  const auto local = make_synthetic_pose(s, 12);
  std::vector<glm::mat4> matrices(local.size()), out(local.size()), small(3);
  const auto valid = [&] {
    LocalToModelJob job;
    job.skeleton = &s;
    job.input = local;
    job.output = out;
    return job;
  };
  EXPECT_TRUE(valid().validate());
  {
    auto job = valid();
    job.skeleton = nullptr;
    EXPECT_FALSE(job.validate()) << "no skeleton";
  }
  {
    auto job = valid();
    job.input = {};
    EXPECT_FALSE(job.validate()) << "no input";
  }
  {
    auto job = valid();
    job.input_matrices = matrices;
    EXPECT_FALSE(job.validate()) << "two inputs";
  }
  {
    auto job = valid();
    job.input = math::Span<const math::Transform>(local.data(), 3);
    EXPECT_FALSE(job.validate()) << "input too small";
  }
  {
    auto job = valid();
    job.output = small;
    EXPECT_FALSE(job.validate()) << "output too small";
  }
  {
    auto job = valid();
    job.from = 65;
    EXPECT_FALSE(job.validate()) << "from out of range";
  }
  {
    auto job = valid();
    job.from = -2;
    EXPECT_FALSE(job.validate()) << "from below -1";
  }
  {
    auto job = valid();
    job.from = 10;
    job.to = 5;
    EXPECT_FALSE(job.validate()) << "to before from";
  }
  {
    Skeleton broken = s;
    broken.joints[3].parent = 40;
    auto job = valid();
    job.skeleton = &broken;
    EXPECT_FALSE(job.validate()) << "parent after child";
  }
  {
    auto job = valid();
    job.output = small;
    const std::vector<glm::mat4> untouched = small;
    EXPECT_FALSE(job.run());
    EXPECT_EQ(small, untouched);
  }
}

}  // namespace
}  // namespace sw::skeleton
