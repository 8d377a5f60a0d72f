// Reference humanoid: skeleton (adult proportions, metres) + body anchors (see the header).
#include "synthesis/reference_humanoid.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "synthesis/collision.h"
#include "synthesis/rig.h"

namespace sw::synthesis {
namespace {

struct Builder {
  avatar::Avatar av;
  std::vector<glm::vec3> model;  // model-space positions as we go
  int add(const std::string& name, int parent, glm::vec3 model_pos) {
    skeleton::Joint j;
    j.name = name;
    j.parent = parent;
    j.rest.translation = parent < 0 ? model_pos : model_pos - model[parent];
    av.skeleton.joints.push_back(j);
    model.push_back(model_pos);
    return static_cast<int>(model.size()) - 1;
  }
};

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
  Builder b;
  int hips = b.add("hips", -1, {0, 1.00f, 0});
  int spine = b.add("spine", hips, {0, 1.10f, 0});
  int chest = b.add("chest", spine, {0, 1.22f, 0});
  int upper = b.add("upperChest", chest, {0, 1.34f, 0});
  int neck = b.add("neck", upper, {0, 1.46f, 0});
  int head = b.add("head", neck, {0, 1.56f, 0});
  b.add("jaw", head, {0, 1.54f, 0.04f});
  b.add("leftEye", head, {0.032f, 1.625f, 0.075f});
  b.add("rightEye", head, {-0.032f, 1.625f, 0.075f});
  for (int s = 0; s < 2; ++s) {
    const float x = s == 0 ? 1.0f : -1.0f;  // +X is the signer's left
    const std::string p = s == 0 ? "left" : "right";
    int sh = b.add(p + "Shoulder", upper, {x * 0.03f, 1.43f, 0});
    int ua = b.add(p + "UpperArm", sh, {x * 0.17f, 1.43f, 0});
    int la = b.add(p + "LowerArm", ua, {x * 0.46f, 1.43f, 0});
    int hand = b.add(p + "Hand", la, {x * 0.72f, 1.43f, 0});
    // Thumb: forward (+Z) and slightly down from the wrist, as in a relaxed T-pose hand.
    int t0 = b.add(p + "ThumbMetacarpal", hand, {x * 0.74f, 1.42f, 0.022f});
    int t1 = b.add(p + "ThumbProximal", t0, {x * 0.775f, 1.412f, 0.045f});
    int t2 = b.add(p + "ThumbDistal", t1, {x * 0.805f, 1.406f, 0.062f});
    b.add(p + "ThumbTip", t2, {x * 0.833f, 1.402f, 0.076f});
    const char* fn[4] = {"Index", "Middle", "Ring", "Little"};
    const float z[4] = {0.028f, 0.009f, -0.010f, -0.026f};
    const float knuckle[4] = {0.092f, 0.095f, 0.090f, 0.087f};
    const float len[4][3] = {{0.045f, 0.026f, 0.022f}, {0.050f, 0.030f, 0.024f},
                             {0.046f, 0.029f, 0.023f}, {0.040f, 0.024f, 0.021f}};
    for (int f = 0; f < 4; ++f) {
      std::string n = p + fn[f];
      int m = b.add(n + "Metacarpal", hand, {x * 0.74f, 1.43f, z[f] * 0.6f});
      float xx = 0.72f + knuckle[f];
      int j1 = b.add(n + "Proximal", m, {x * xx, 1.43f, z[f]});
      xx += len[f][0];
      int j2 = b.add(n + "Intermediate", j1, {x * xx, 1.43f, z[f]});
      xx += len[f][1];
      int j3 = b.add(n + "Distal", j2, {x * xx, 1.43f, z[f]});
      xx += len[f][2];
      b.add(n + "Tip", j3, {x * xx, 1.43f, z[f]});
    }
    int ul = b.add(p + "UpperLeg", hips, {x * 0.09f, 0.95f, 0});
    int ll = b.add(p + "LowerLeg", ul, {x * 0.09f, 0.52f, 0});
    int ft = b.add(p + "Foot", ll, {x * 0.09f, 0.09f, 0});
    b.add(p + "Toes", ft, {x * 0.09f, 0.02f, 0.12f});
  }
  avatar::Avatar av = std::move(b.av);
  av.inverse_bind.resize(av.skeleton.joints.size(), glm::mat4(1.0f));
  for (size_t i = 0; i < av.inverse_bind.size(); ++i) {
    glm::mat4 m(1.0f);
    m[3] = glm::vec4(-b.model[i], 1.0f);
    av.inverse_bind[i] = m;
  }

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
      a.offset = p - b.model[joint];
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
    a.offset = p - b.model[spine];
    a.normal = glm::vec3(0, 0, 1);
    av.anchors.push_back(a);
  }
  return av;
}

}  // namespace sw::synthesis
