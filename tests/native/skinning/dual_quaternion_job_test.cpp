// Tests for skinning/dual_quaternion_job.h: rest = bind, equal to LBS for rigid vertices, and the
// reason it exists — a twisted cylinder keeps its radius where LBS pinches (candy wrapper).
#include "skinning/dual_quaternion_job.h"

#include <cmath>

#include <gtest/gtest.h>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>

#include "skinning/skinning_job.h"

namespace sw::skinning {
namespace {

// A cylinder of radius 0.05 along +X from 0 to 1: rings at x = 0, 0.1 ... 1, weights blending
// linearly from joint 0 (x = 0) to joint 1 (x = 1) — a forearm between elbow and wrist.
struct Cylinder {
  std::vector<glm::vec3> positions, normals;
  std::vector<std::array<std::uint16_t, 4>> joints;
  std::vector<glm::vec4> weights;
  Cylinder() {
    for (int r = 0; r <= 10; ++r) {
      for (int s = 0; s < 16; ++s) {
        const float a = 6.2831853f * float(s) / 16.0f;
        positions.push_back({0.1f * float(r), 0.05f * std::cos(a), 0.05f * std::sin(a)});
        normals.push_back({0.0f, std::cos(a), std::sin(a)});
        joints.push_back({0, 1, 0, 0});
        weights.push_back({1.0f - 0.1f * float(r), 0.1f * float(r), 0.0f, 0.0f});
      }
    }
  }
};

template <typename Job>
Job make_job(const Cylinder& c, const std::vector<glm::mat4>& m, std::vector<float>& out_p,
             std::vector<float>& out_n) {
  Job job;
  job.vertex_count = static_cast<int>(c.positions.size());
  job.skinning_matrices = m.data();
  job.joint_count = static_cast<int>(m.size());
  job.in_positions = c.positions.data();
  job.in_normals = c.normals.data();
  job.joints = c.joints.data();
  job.weights = c.weights.data();
  out_p.assign(3 * c.positions.size(), 0.0f);
  out_n.assign(3 * c.positions.size(), 0.0f);
  job.out_positions = out_p.data();
  job.out_normals = out_n.data();
  return job;
}

float min_radius(const std::vector<float>& p) {
  float r = 1e9f;
  for (std::size_t v = 0; 3 * v < p.size(); ++v)
    r = std::min(r, std::hypot(p[3 * v + 1], p[3 * v + 2]));
  return r;
}

TEST(DualQuaternionSkinningJob, RestPoseIsTheBindPose) {
  const Cylinder c;
  const std::vector<glm::mat4> identity(2, glm::mat4(1.0f));
  std::vector<float> p, n;
  const auto job = make_job<DualQuaternionSkinningJob>(c, identity, p, n);
  ASSERT_EQ(job.validate(), "");
  ASSERT_TRUE(job.run());
  for (std::size_t v = 0; v < c.positions.size(); ++v)
    for (int k = 0; k < 3; ++k) {
      ASSERT_NEAR(p[3 * v + static_cast<std::size_t>(k)], c.positions[v][k], 1e-5f);
      ASSERT_NEAR(n[3 * v + static_cast<std::size_t>(k)], c.normals[v][k], 1e-5f);
    }
}

TEST(DualQuaternionSkinningJob, TwistKeepsTheRadiusWhereLinearBlendPinches) {
  const Cylinder c;
  for (float degrees : {90.0f, 170.0f}) {
    // Joint 1 (the wrist end) twists about the cylinder's own axis.
    const std::vector<glm::mat4> m = {
        glm::mat4(1.0f), glm::mat4_cast(glm::angleAxis(glm::radians(degrees), glm::vec3(1, 0, 0)))};
    std::vector<float> dq_p, dq_n, lbs_p, lbs_n;
    ASSERT_TRUE(make_job<DualQuaternionSkinningJob>(c, m, dq_p, dq_n).run());
    auto lbs = make_job<SkinningJob>(c, m, lbs_p, lbs_n);
    lbs.path = SkinningPath::Scalar;
    ASSERT_TRUE(lbs.run());
    EXPECT_NEAR(min_radius(dq_p), 0.05f, 1e-4f) << degrees;
    EXPECT_LT(min_radius(lbs_p), 0.05f * std::cos(glm::radians(degrees / 2.0f)) + 1e-4f) << degrees;
  }
}

TEST(DualQuaternionSkinningJob, RigidVerticesMatchLinearBlend) {
  Cylinder c;
  for (auto& w : c.weights) w = {1.0f, 0.0f, 0.0f, 0.0f};
  const std::vector<glm::mat4> m = {
      glm::translate(glm::mat4(1.0f), glm::vec3(0.3f, -0.2f, 1.0f)) *
          glm::mat4_cast(glm::angleAxis(1.1f, glm::normalize(glm::vec3(1, 2, 3)))),
      glm::mat4(1.0f)};
  std::vector<float> dq_p, dq_n, lbs_p, lbs_n;
  ASSERT_TRUE(make_job<DualQuaternionSkinningJob>(c, m, dq_p, dq_n).run());
  ASSERT_TRUE(make_job<SkinningJob>(c, m, lbs_p, lbs_n).run());
  for (std::size_t i = 0; i < dq_p.size(); ++i) {
    ASSERT_NEAR(dq_p[i], lbs_p[i], 1e-5f);
    ASSERT_NEAR(dq_n[i], lbs_n[i], 1e-5f);
  }
}

TEST(DualQuaternionSkinningJob, ValidateRejectsEveryBadConfiguration) {
  Cylinder c;
  const std::vector<glm::mat4> m(2, glm::mat4(1.0f));
  std::vector<float> p, n;
  const auto good = make_job<DualQuaternionSkinningJob>(c, m, p, n);
  ASSERT_EQ(good.validate(), "");
  auto b = good;
  b.vertex_count = -1;
  EXPECT_NE(b.validate(), "");
  b = good;
  b.skinning_matrices = nullptr;
  EXPECT_NE(b.validate(), "");
  b = good;
  b.out_positions = nullptr;
  EXPECT_NE(b.validate(), "");
  b = good;
  b.out_normals = nullptr;
  EXPECT_NE(b.validate(), "");
  const std::vector<glm::mat4> scaled = {glm::scale(glm::mat4(1.0f), glm::vec3(2.0f)),
                                         glm::mat4(1.0f)};
  b = good;
  b.skinning_matrices = scaled.data();
  EXPECT_NE(b.validate().find("not rigid"), std::string::npos);
  c.joints[5][1] = 7;
  b = good;
  b.joints = c.joints.data();
  EXPECT_NE(b.validate().find("out of range"), std::string::npos);
  EXPECT_FALSE(b.run());
}

}  // namespace
}  // namespace sw::skinning
