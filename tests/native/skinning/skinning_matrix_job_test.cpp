// Tests for skinning/skinning_matrix_job.h: the palette and every invalid job.
#include "skinning/skinning_matrix_job.h"

#include <gtest/gtest.h>
#include <glm/gtc/matrix_transform.hpp>

namespace sw::skinning {
namespace {

TEST(SkinningMatrixJob, ModelTimesInverseBind) {
  std::vector<glm::mat4> models = {glm::translate(glm::mat4(1.0f), glm::vec3(1, 2, 3))};
  std::vector<glm::mat4> ibm = {glm::translate(glm::mat4(1.0f), glm::vec3(-1, -2, -3))};
  std::vector<glm::mat4> out(1);
  SkinningMatrixJob job{models.data(), ibm.data(), 1, out.data()};
  ASSERT_TRUE(job.run());
  EXPECT_EQ(out[0], glm::mat4(1.0f));
  SkinningMatrixJob bad = job;
  bad.models = nullptr;
  EXPECT_NE(bad.validate(), "");
  EXPECT_FALSE(bad.run());
  bad = job;
  bad.inverse_binds = nullptr;
  EXPECT_NE(bad.validate(), "");
  bad = job;
  bad.skinning_matrices = nullptr;
  EXPECT_NE(bad.validate(), "");
  bad = job;
  bad.joint_count = -1;
  EXPECT_NE(bad.validate(), "");
}

}  // namespace
}  // namespace sw::skinning
