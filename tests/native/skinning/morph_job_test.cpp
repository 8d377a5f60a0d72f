// Tests for skinning/morph_job.h: deltas add with their weights, ranges, and invalid jobs.
#include "skinning/morph_job.h"

#include <limits>

#include <gtest/gtest.h>

namespace sw::skinning {
namespace {

struct Fixture {
  std::vector<glm::vec3> rest = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {3, 0, 0}};
  std::vector<glm::vec3> normals = {{0, 1, 0}, {0, 1, 0}, {0, 1, 0}, {0, 1, 0}};
  std::vector<avatar::MorphTarget> targets;
  std::vector<float> weights = {0.5f, 2.0f};
  std::vector<glm::vec3> out = std::vector<glm::vec3>(4), out_n = std::vector<glm::vec3>(4);
  Fixture() {
    avatar::MorphTarget a;
    a.name = "a";
    a.position_deltas = {{0, 0, 0}, {0, 1, 0}, {0, 0, 0}, {0, 0, 0}};
    a.normal_deltas = {{0, 0, 0}, {1, 0, 0}, {0, 0, 0}, {0, 0, 0}};
    avatar::MorphTarget b;
    b.name = "b";
    b.position_deltas = {{0, 0, 0}, {0, 0, 1}, {0, 0, 1}, {0, 0, 0}};
    targets = {a, b};
  }
  MorphJob job(const VertexRange* ranges = nullptr) {
    MorphJob j;
    j.vertex_count = 4;
    j.rest_positions = rest.data();
    j.rest_normals = normals.data();
    j.targets = targets.data();
    j.target_count = 2;
    j.ranges = ranges;
    j.weights = weights.data();
    j.out_positions = out.data();
    j.out_normals = out_n.data();
    return j;
  }
};

TEST(MorphJob, WeightedDeltasAddToTheRestMesh) {
  Fixture f;
  ASSERT_TRUE(f.job().run());
  EXPECT_EQ(f.out[0], glm::vec3(0, 0, 0));
  EXPECT_EQ(f.out[1], glm::vec3(1, 0.5f, 2.0f));
  EXPECT_EQ(f.out[2], glm::vec3(2, 0, 2.0f));
  EXPECT_EQ(f.out_n[1], glm::vec3(0.5f, 1, 0));
  EXPECT_EQ(f.out_n[2], glm::vec3(0, 1, 0));
}

TEST(MorphJob, ZeroWeightsReproduceTheRestMesh) {
  Fixture f;
  f.weights = {0.0f, 0.0f};
  ASSERT_TRUE(f.job().run());
  EXPECT_EQ(f.out, f.rest);
  EXPECT_EQ(f.out_n, f.normals);
}

TEST(MorphJob, VertexRangesSkipUnmovedVerticesWithTheSameResult) {
  Fixture f;
  const std::vector<VertexRange> ranges = morph_vertex_ranges(f.targets);
  ASSERT_EQ(ranges.size(), 2u);
  EXPECT_EQ(ranges[0].first, 1u);
  EXPECT_EQ(ranges[0].end, 2u);
  EXPECT_EQ(ranges[1].first, 1u);
  EXPECT_EQ(ranges[1].end, 3u);
  ASSERT_TRUE(f.job().run());
  const std::vector<glm::vec3> full = f.out;
  ASSERT_TRUE(f.job(ranges.data()).run());
  EXPECT_EQ(f.out, full);
}

TEST(MorphJob, ValidateRejectsEveryBadConfiguration) {
  Fixture f;
  ASSERT_EQ(f.job().validate(), "");
  MorphJob j = f.job();
  j.vertex_count = -1;
  EXPECT_NE(j.validate(), "");
  j = f.job();
  j.rest_positions = nullptr;
  EXPECT_NE(j.validate(), "");
  j = f.job();
  j.out_positions = nullptr;
  EXPECT_NE(j.validate(), "");
  j = f.job();
  j.out_normals = nullptr;
  EXPECT_NE(j.validate(), "");
  j = f.job();
  j.weights = nullptr;
  EXPECT_NE(j.validate(), "");
  j = f.job();
  j.vertex_count = 3;
  EXPECT_NE(j.validate(), "");  // delta counts differ
  f.weights[1] = std::numeric_limits<float>::quiet_NaN();
  j = f.job();
  EXPECT_NE(j.validate(), "");
  EXPECT_FALSE(j.run());
  f.weights[1] = 1.0f;
  const VertexRange bad_range[2] = {{0, 9}, {0, 1}};
  j = f.job(bad_range);
  EXPECT_NE(j.validate(), "");
  f.targets[1].normal_deltas = {{0, 0, 0}};
  j = f.job();
  EXPECT_NE(j.validate(), "");
}

}  // namespace
}  // namespace sw::skinning
