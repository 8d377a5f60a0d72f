// Tests for skinning/skinning_job.h on the synthetic humanoid: rest pose = bind pose, one joint
// moves only what it weights, SIMD == scalar, and every invalid job.
#include "skinning/skinning_job.h"

#include <random>

#include <gtest/gtest.h>
#include <glm/gtc/quaternion.hpp>

#include "avatar/gltf_loader.h"
#include "avatar/synthetic_avatar.h"
#include "skeleton/humanoid_names.h"
#include "skeleton/local_to_model.h"
#include "skinning/skinning_matrix_job.h"

namespace sw::skinning {
namespace {

const avatar::Avatar& humanoid() {
  static const avatar::Avatar a = [] {
    const std::vector<std::uint8_t> glb = avatar::make_synthetic_avatar_glb();
    avatar::LoadResult r = avatar::load_avatar(glb.data(), glb.size());
    EXPECT_TRUE(r.ok()) << r.message();
    return r.avatar;
  }();
  return a;
}

std::vector<glm::mat4> palette(const avatar::Avatar& a,
                               const std::vector<math::Transform>& locals) {
  std::vector<glm::mat4> models(locals.size()), skin(locals.size());
  skeleton::LocalToModelJob fk;
  fk.skeleton = &a.skeleton;
  fk.input = locals;
  fk.output = models;
  EXPECT_TRUE(fk.run());
  SkinningMatrixJob sm{models.data(), a.inverse_bind.data(), static_cast<int>(locals.size()),
                       skin.data()};
  EXPECT_TRUE(sm.run());
  return skin;
}

std::vector<math::Transform> rest_pose(const avatar::Avatar& a) {
  std::vector<math::Transform> t;
  for (const auto& j : a.skeleton.joints) t.push_back(j.rest);
  return t;
}

struct Output {
  std::vector<float> positions, normals;
};

Output skin(const avatar::Avatar& a, const std::vector<glm::mat4>& matrices, SkinningPath path) {
  const std::size_t n = a.mesh.positions.size();
  Output out{std::vector<float>(3 * n), std::vector<float>(3 * n)};
  SkinningJob job;
  job.vertex_count = static_cast<int>(n);
  job.skinning_matrices = matrices.data();
  job.joint_count = static_cast<int>(matrices.size());
  job.in_positions = a.mesh.positions.data();
  job.in_normals = a.mesh.normals.data();
  job.joints = a.mesh.joints.data();
  job.weights = a.mesh.weights.data();
  job.out_positions = out.positions.data();
  job.out_normals = out.normals.data();
  job.path = path;
  EXPECT_EQ(job.validate(), "");
  EXPECT_TRUE(job.run());
  return out;
}

class SkinningPaths : public ::testing::TestWithParam<SkinningPath> {};

TEST_P(SkinningPaths, RestPoseSkinsToTheBindPose) {
  const avatar::Avatar& a = humanoid();
  const Output out = skin(a, palette(a, rest_pose(a)), GetParam());
  for (std::size_t v = 0; v < a.mesh.positions.size(); ++v) {
    for (int k = 0; k < 3; ++k) {
      ASSERT_NEAR(out.positions[3 * v + static_cast<std::size_t>(k)], a.mesh.positions[v][k], 1e-5f)
          << v;
      ASSERT_NEAR(out.normals[3 * v + static_cast<std::size_t>(k)], a.mesh.normals[v][k], 1e-5f)
          << v;
    }
  }
}

TEST_P(SkinningPaths, RotatingOneJointMovesOnlyTheVerticesItWeights) {
  const avatar::Avatar& a = humanoid();
  const int elbow = a.canonical_to_joint[skeleton::kLeftLowerArm];
  ASSERT_GE(elbow, 0);
  // The forearm's subtree: the joint and every descendant (they move with it).
  std::vector<bool> moved_joint(a.skeleton.joints.size(), false);
  for (std::size_t j = 0; j < a.skeleton.joints.size(); ++j) {
    const int p = a.skeleton.joints[j].parent;
    moved_joint[j] =
        static_cast<int>(j) == elbow || (p >= 0 && moved_joint[static_cast<std::size_t>(p)]);
  }
  std::vector<math::Transform> pose = rest_pose(a);
  pose[static_cast<std::size_t>(elbow)].rotation =
      glm::angleAxis(glm::radians(90.0f), glm::vec3(0, 1, 0));
  const Output rest = skin(a, palette(a, rest_pose(a)), GetParam());
  const Output bent = skin(a, palette(a, pose), GetParam());
  int moved = 0;
  for (std::size_t v = 0; v < a.mesh.positions.size(); ++v) {
    bool weighted = false;
    for (int k = 0; k < 4; ++k) {
      if (a.mesh.weights[v][k] > 0.0f && moved_joint[a.mesh.joints[v][static_cast<std::size_t>(k)]])
        weighted = true;
    }
    const glm::vec3 before(rest.positions[3 * v], rest.positions[3 * v + 1],
                           rest.positions[3 * v + 2]);
    const glm::vec3 after(bent.positions[3 * v], bent.positions[3 * v + 1],
                          bent.positions[3 * v + 2]);
    if (weighted) {
      // Every such vertex lies beyond the elbow axis' pivot (x > 0.44), so a 90° turn moves it.
      if (glm::length(after - before) > 1e-3f) ++moved;
    } else {
      ASSERT_LT(glm::length(after - before), 1e-6f)
          << "vertex " << v << " is not weighted on the forearm";
    }
  }
  EXPECT_GT(moved, 100);
}

INSTANTIATE_TEST_SUITE_P(Both, SkinningPaths,
                         ::testing::Values(SkinningPath::Scalar, SkinningPath::Simd),
                         [](const auto& info) {
                           return info.param == SkinningPath::Scalar ? "Scalar" : "Simd";
                         });

TEST(SkinningJob, SimdEqualsScalarOnARandomPose) {
  const avatar::Avatar& a = humanoid();
  EXPECT_TRUE(simd_available()) << "native builds (x86-64 SSE2) always have the SIMD loop";
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> angle(-1.5f, 1.5f);
  std::vector<math::Transform> pose = rest_pose(a);
  for (auto& t : pose)
    t.rotation = glm::angleAxis(
        angle(rng), glm::normalize(glm::vec3(angle(rng), angle(rng), angle(rng) + 2.0f)));
  const std::vector<glm::mat4> matrices = palette(a, pose);
  const Output scalar = skin(a, matrices, SkinningPath::Scalar);
  const Output simd = skin(a, matrices, SkinningPath::Simd);
  for (std::size_t i = 0; i < scalar.positions.size(); ++i) {
    ASSERT_NEAR(scalar.positions[i], simd.positions[i], 1e-5f) << i;
    ASSERT_NEAR(scalar.normals[i], simd.normals[i], 1e-5f) << i;
  }
}

TEST(SkinningJob, SimdWritesNothingPastTheLastVertex) {
  // The SIMD loop stores 4 floats per vertex except for the last one: a sentinel after the
  // buffers must survive.
  const glm::mat4 m = glm::translate(glm::mat4(1.0f), glm::vec3(1, 2, 3));
  const std::vector<glm::vec3> p = {{0, 0, 0}, {1, 1, 1}, {2, 2, 2}};
  const std::vector<std::array<std::uint16_t, 4>> j(3, {0, 0, 0, 0});
  const std::vector<glm::vec4> w(3, {1, 0, 0, 0});
  std::vector<float> out(10, -7.0f), out_n(10, -7.0f);
  SkinningJob job;
  job.vertex_count = 3;
  job.skinning_matrices = &m;
  job.joint_count = 1;
  job.in_positions = p.data();
  job.in_normals = p.data();
  job.joints = j.data();
  job.weights = w.data();
  job.out_positions = out.data();
  job.out_normals = out_n.data();
  job.path = SkinningPath::Simd;
  ASSERT_TRUE(job.run());
  EXPECT_EQ(out[9], -7.0f);
  EXPECT_EQ(out_n[9], -7.0f);
  EXPECT_EQ(out[6], 3.0f);
  EXPECT_EQ(out[7], 4.0f);
  EXPECT_EQ(out[8], 5.0f);
  EXPECT_EQ(out_n[6], 2.0f);  // normals ignore translation
}

TEST(SkinningJob, ValidateRejectsEveryBadConfiguration) {
  const glm::mat4 m(1.0f);
  const std::vector<glm::vec3> p(2);
  const std::vector<std::array<std::uint16_t, 4>> j(2, {0, 0, 0, 0});
  const std::vector<glm::vec4> w(2, {1, 0, 0, 0});
  std::vector<float> out(6), out_n(6);
  SkinningJob good;
  good.vertex_count = 2;
  good.skinning_matrices = &m;
  good.joint_count = 1;
  good.in_positions = p.data();
  good.in_normals = p.data();
  good.joints = j.data();
  good.weights = w.data();
  good.out_positions = out.data();
  good.out_normals = out_n.data();
  ASSERT_EQ(good.validate(), "");
  SkinningJob b = good;
  b.vertex_count = -1;
  EXPECT_NE(b.validate(), "");
  b = good;
  b.skinning_matrices = nullptr;
  EXPECT_NE(b.validate(), "");
  b = good;
  b.joint_count = 0;
  EXPECT_NE(b.validate(), "");
  b = good;
  b.in_positions = nullptr;
  EXPECT_NE(b.validate(), "");
  b = good;
  b.joints = nullptr;
  EXPECT_NE(b.validate(), "");
  b = good;
  b.weights = nullptr;
  EXPECT_NE(b.validate(), "");
  b = good;
  b.out_positions = nullptr;
  EXPECT_NE(b.validate(), "");
  b = good;
  b.out_normals = nullptr;
  EXPECT_NE(b.validate(), "");
  b = good;
  b.out_normals = out.data();
  EXPECT_NE(b.validate(), "");  // outputs overlap
  b = good;
  b.out_positions = reinterpret_cast<float*>(const_cast<glm::vec3*>(p.data()));
  EXPECT_NE(b.validate(), "");
  EXPECT_FALSE(b.run());
}

}  // namespace
}  // namespace sw::skinning
