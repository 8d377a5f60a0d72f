// Tests for synthesis/reference_humanoid.h: its body anchors on its capsule body. Every
// `*_beside` place lies beside the body — lateral to the trunk capsules' silhouette at its height
// and off their skin — as on a meshed avatar (tests/native/avatar/body_anchors_test.cpp).
#include "synthesis/reference_humanoid.h"

#include <gtest/gtest.h>

#include <glm/glm.hpp>

#include "synthesis/collision.h"
#include "synthesis/rig.h"

namespace sw::synthesis {
namespace {

TEST(ReferenceHumanoid, BesidePlacesLieOutsideTheTrunksSilhouette) {
  const avatar::Avatar av = make_reference_humanoid();
  Rig rig;
  std::string error;
  ASSERT_TRUE(build_rig(av, &rig, &error)) << error;
  const BodyModel body = build_body_model(av, rig);
  int checked = 0;
  for (const avatar::Anchor& anchor : av.anchors) {
    const std::string& n = anchor.name;
    if (n.rfind("body/", 0) != 0 || n.find("_beside") == std::string::npos) continue;
    const float sign = n.find("left_beside") != std::string::npos ? 1.0f : -1.0f;
    const glm::vec3 p = glm::vec3(glm::inverse(av.inverse_bind[static_cast<size_t>(anchor.joint)]) *
                                  glm::vec4(anchor.offset, 1.0f));
    // The trunk's silhouette seen from the front at the anchor's height: the farthest point of a
    // 2 mm grid over the horizontal slice (60 x 40 cm) inside any trunk capsule, to this side.
    float skin = -1.0f;
    for (float x = 0.0f; x <= 0.3f; x += 0.002f)
      for (float z = -0.2f; z <= 0.2f; z += 0.002f)
        for (const Capsule& c : body.trunk)
          if (segment_distance(glm::vec3(sign * x, p.y, z), c.a, c.b) < c.radius_m) skin = std::max(skin, x);
    EXPECT_GT(sign * p.x, skin + 0.01f) << n << " at x = " << p.x << ", the trunk reaches " << skin
                                        << " at its height " << p.y;
    ++checked;
  }
  EXPECT_EQ(checked, 2 * 23);
}

}  // namespace
}  // namespace sw::synthesis
