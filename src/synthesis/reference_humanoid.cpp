// Reference humanoid: the synthetic skeleton + body anchors (see the header).
#include "synthesis/reference_humanoid.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "skeleton/synthetic_humanoid.h"
#include "synthesis/collision.h"
#include "synthesis/rig.h"

namespace sw::synthesis {
namespace {

const char* kLevelNames[] = {"above_head", "head_top", "head", "forehead", "eyebrows", "eyes",
                             "nose", "ears", "cheeks", "mouth", "lips", "teeth", "tongue", "chin",
                             "under_chin", "neck", "shoulders", "shoulder_top", "chest", "stomach",
                             "belly", "waist", "below_waist"};
// Heights (m) of the levels on this body.
const float kLevelHeight[] = {1.86f, 1.745f, 1.70f, 1.68f, 1.645f, 1.625f, 1.595f, 1.61f, 1.575f,
                              1.545f, 1.545f, 1.545f, 1.545f, 1.505f, 1.49f, 1.45f, 1.40f, 1.44f,
                              1.30f, 1.18f, 1.08f, 1.02f, 0.93f};
const char* kSideNames[] = {"right_beside", "right", "centre", "left", "left_beside"};

}  // namespace

avatar::Avatar make_reference_humanoid() {
  avatar::Avatar av;
  av.skeleton = skeleton::make_synthetic_humanoid({/*finger_metacarpals=*/true});
  const std::vector<glm::vec3> model = skeleton::rest_positions(av.skeleton);
  av.inverse_bind.resize(av.skeleton.joints.size(), glm::mat4(1.0f));
  for (size_t i = 0; i < av.inverse_bind.size(); ++i) av.inverse_bind[i][3] = glm::vec4(-model[i], 1.0f);
  const int hips = av.skeleton.find("hips"), spine = av.skeleton.find("spine"), chest = av.skeleton.find("chest");
  const int upper = av.skeleton.find("upperChest"), neck = av.skeleton.find("neck"), head = av.skeleton.find("head");

  // Anchors on the capsule body collision.h builds for this skeleton: a ray from the body axis at
  // the level's height, towards the side, leaves the union of trunk capsules at the skin point.
  Rig rig;
  std::string error;
  if (!build_rig(av, &rig, &error)) return av;
  BodyModel body = build_body_model(av, rig);
  auto inside = [&](const glm::vec3& p) {
    for (const Capsule& c : body.trunk)
      if (segment_distance(p, c.a, c.b) < c.radius_m) return true;
    return false;
  };
  const int levels = static_cast<int>(sizeof(kLevelHeight) / sizeof(kLevelHeight[0]));
  const float torso_bottom_y = std::min(body.trunk[0].a.y, body.trunk[0].b.y);
  for (int l = 0; l < levels; ++l) {
    float y = kLevelHeight[l];
    int joint = y > 1.56f ? head : y > 1.455f ? neck : y > 1.34f ? upper : y > 1.22f ? chest
              : y > 1.10f ? spine : hips;
    bool is_head = y > 1.46f;
    glm::vec3 origin(0, y, is_head ? 0.03f : 0.0f);
    for (int s = 0; s < 5; ++s) {
      float side = static_cast<float>(s - 2);  // -2 right_beside .. +2 left_beside (+X = left)
      std::string level = kLevelNames[l];
      glm::vec3 dir;
      if (level == "ears") dir = glm::vec3(side == 0 ? 0.0f : (side > 0 ? 1.0f : -1.0f), 0, side == 0 ? 1.0f : 0.0f);
      else if (level == "cheeks") dir = glm::vec3(0.8f * glm::clamp(side, -1.0f, 1.0f), 0, 1.0f);
      else dir = glm::vec3(0.55f * glm::clamp(side, -1.0f, 1.0f), 0, 1.0f);
      if (level == "head_top" || level == "above_head") dir = glm::vec3(0.3f * glm::clamp(side, -1.0f, 1.0f), 1.0f, 0.25f);
      dir = glm::normalize(dir);
      // Below the torso capsules' hemispherical ends (the pelvis) the surface is taken from the
      // lowest full-width section, at the level's own height.
      float march_y = std::max(y, torso_bottom_y);
      glm::vec3 p(origin.x, march_y, origin.z);
      for (int step = 0; step < 600 && inside(p); ++step) p += 0.001f * dir;
      p.y = y;
      if (level == "above_head") p += 0.12f * glm::vec3(0, 1, 0);
      if (std::fabs(side) > 1.5f) {  // *_beside: off the body, a hand's width to the side
        glm::vec3 out(side > 0 ? 1.0f : -1.0f, 0, 0);
        glm::vec3 q(0, y, 0.02f);
        for (int step = 0; step < 600 && inside(q); ++step) q += 0.001f * out;
        p = q + 0.09f * out;
        dir = out;
      }
      avatar::Anchor a;
      a.name = "body/" + level + "/" + kSideNames[s];
      a.joint = joint;
      a.offset = p - model[static_cast<std::size_t>(joint)];
      a.normal = dir;
      av.anchors.push_back(a);
    }
  }
  // Neutral signing space: in front of the lower chest, a forearm's length from the body.
  for (int s = 0; s < 5; ++s) {
    avatar::Anchor a;
    a.name = std::string("space/") + kSideNames[s];
    a.joint = spine;
    glm::vec3 p(0.14f * static_cast<float>(s - 2), 1.22f, 0.33f);
    a.offset = p - model[static_cast<std::size_t>(spine)];
    a.normal = glm::vec3(0, 0, 1);
    av.anchors.push_back(a);
  }
  return av;
}

}  // namespace sw::synthesis
