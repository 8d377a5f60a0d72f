// Body anchors from skeleton + mesh. See body_anchors.h for the names and the method.
#include "avatar/body_anchors.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>

#include "skeleton/humanoid_names.h"

namespace sw::avatar {
namespace {

using skeleton::Finger;
using skeleton::FingerSegment;

constexpr std::array<const char*, 23> kLevels = {
    "above_head", "head_top", "head", "forehead", "eyebrows", "eyes", "nose", "ears",
    "cheeks", "mouth", "lips", "teeth", "tongue", "chin", "under_chin", "neck",
    "shoulders", "shoulder_top", "chest", "stomach", "belly", "waist", "below_waist"};
constexpr std::array<const char*, 5> kSides = {"right_beside", "right", "centre", "left", "left_beside"};
constexpr std::array<const char*, 7> kHandPlaces = {"palm", "back", "thumb_side", "little_side", "wrist", "wrist_back", "thumb_ball"};
constexpr std::array<const char*, 6> kFingerPlaces = {"tip", "pad", "nail", "base", "middle_joint", "side"};
constexpr std::array<const char*, 5> kFingerNames = {"thumb", "index", "middle", "ring", "little"};
// How far a `*_beside` place stays at least beyond the body's silhouette at its height: a hand
// held there (half a hand's thickness, ~1.5 cm, on either side of the place) stays off the skin
// by more than a centimetre.
constexpr float kBesideClear_m = 0.03f;
// How far a `*_beside` place stays at most beyond the silhouette where a level's width takes in
// the legs (below the waist: the hips and thighs). 1.6 half widths of that width put the place
// 10.4 cm off the project avatar's hip (27.7 cm from the midline, against 21-24 cm beside its
// chest and waist), where the other hand crossing to it reached at full stretch across the hips
// (fists touching there 42.1 / 44.2 mm in the trunk and 18.1 / 17.0 mm short of the place, a flat
// hand held off 12.9 mm). 4 cm off the silhouette (21.3 cm out): 22.8 / 20.4 mm, 0.2 / 0.1 mm
// short, 0.2 mm (collision_test.cpp). Measured too: 5 cm 39.2 / 26.1 mm, 6 cm 32.9 / 33.6, 7 cm
// 45.2 / 47.0 and 8 mm short (the depth is not monotonic in it: the arm's swivel and the thorax
// turn change with the place), 8 cm 50.3 / 52.1.
constexpr float kBesideLegsClearMax_m = 0.04f;
constexpr std::array<const char*, 5> kArmPlaces = {"forearm", "forearm_back", "elbow", "upper_arm", "elbow_inside"};

// Which body part a triangle belongs to, so a ray from inside the head cannot stop on a hand.
enum Region : unsigned { kCore = 1, kLeftArm = 2, kRightArm = 4, kLeftHand = 8, kRightHand = 16, kLegs = 32 };

struct Hit {
  glm::vec3 point{0.0f};
  glm::vec3 normal{0.0f};  // geometric, turned to face along the ray (outward from inside)
  float distance = 0.0f;
};

glm::vec3 perpendicular(glm::vec3 v, glm::vec3 axis) {
  const glm::vec3 p = v - axis * glm::dot(v, axis);
  const float len = glm::length(p);
  return len > 1e-6f ? p / len : v;
}

class Surface {
 public:
  Surface(const Avatar& avatar, const std::vector<unsigned>& joint_region) : mesh_(avatar.mesh) {
    const std::size_t triangles = mesh_.indices.size() / 3;
    region_.resize(triangles);
    for (std::size_t t = 0; t < triangles; ++t) {
      // The triangle's part: the dominant joint of its first vertex (parts meet at seams, where
      // either answer is right).
      const std::uint32_t v = mesh_.indices[3 * t];
      const glm::vec4 w = mesh_.weights[v];
      int best = 0;
      for (int k = 1; k < 4; ++k) if (w[k] > w[best]) best = k;
      const std::size_t joint = mesh_.joints[v][static_cast<std::size_t>(best)];
      region_[t] = joint < joint_region.size() ? joint_region[joint] : kCore;
    }
    // Runs of consecutive triangles (neighbours in the file, so close on the body) with their box
    // and parts: a ray that misses a run's box skips its triangles. The page loads the avatar on
    // its main thread, where testing every triangle for each of the ~200 anchor rays was the
    // largest part of the start-up.
    for (std::size_t first = 0; first < triangles; first += kChunkTriangles) {
      Chunk chunk;
      chunk.first = first;
      chunk.end = std::min(triangles, first + kChunkTriangles);
      chunk.lo = glm::vec3(std::numeric_limits<float>::max());
      chunk.hi = glm::vec3(std::numeric_limits<float>::lowest());
      for (std::size_t t = chunk.first; t < chunk.end; ++t) {
        chunk.regions |= region_[t];
        for (int k = 0; k < 3; ++k) {
          const glm::vec3& p = mesh_.positions[mesh_.indices[3 * t + static_cast<std::size_t>(k)]];
          chunk.lo = glm::min(chunk.lo, p);
          chunk.hi = glm::max(chunk.hi, p);
        }
      }
      chunks_.push_back(chunk);
    }
  }

  // Nearest surface along the ray (Möller–Trumbore, both faces) among triangles of `regions`.
  // The same triangles are tested in the same order as without the runs, so the answer is the
  // same to the bit: a run is skipped only when no triangle in it can be hit.
  std::optional<Hit> cast(glm::vec3 origin, glm::vec3 dir, unsigned regions) const {
    float best = 1e30f;
    std::size_t best_t = 0;
    bool found = false;
    for (const Chunk& chunk : chunks_) {
      if (!(chunk.regions & regions) || !chunk.may_hit(origin, dir, best)) continue;
      for (std::size_t t = chunk.first; t < chunk.end; ++t) {
        if (!(region_[t] & regions)) continue;
        const glm::vec3& a = mesh_.positions[mesh_.indices[3 * t]];
        const glm::vec3& b = mesh_.positions[mesh_.indices[3 * t + 1]];
        const glm::vec3& c = mesh_.positions[mesh_.indices[3 * t + 2]];
        const glm::vec3 e1 = b - a, e2 = c - a;
        const glm::vec3 p = glm::cross(dir, e2);
        const float det = glm::dot(e1, p);
        if (std::abs(det) < 1e-12f) continue;
        const float inv = 1.0f / det;
        const glm::vec3 s = origin - a;
        const float u = glm::dot(s, p) * inv;
        if (u < 0.0f || u > 1.0f) continue;
        const glm::vec3 q = glm::cross(s, e1);
        const float v = glm::dot(dir, q) * inv;
        if (v < 0.0f || u + v > 1.0f) continue;
        const float dist = glm::dot(e2, q) * inv;
        if (dist > 1e-5f && dist < best) { best = dist; best_t = t; found = true; }
      }
    }
    if (!found) return std::nullopt;
    const glm::vec3& a = mesh_.positions[mesh_.indices[3 * best_t]];
    const glm::vec3& b = mesh_.positions[mesh_.indices[3 * best_t + 1]];
    const glm::vec3& c = mesh_.positions[mesh_.indices[3 * best_t + 2]];
    glm::vec3 n = glm::cross(b - a, c - a);
    const float len = glm::length(n);
    n = len > 0.0f ? n / len : dir;
    if (glm::dot(n, dir) < 0.0f) n = -n;
    return Hit{origin + dir * best, n, best};
  }

  // How far the skin of `regions` reaches along `side` (from `origin`) in the plane through
  // `origin` across `up`: the farthest point where a triangle's edge crosses that plane (the
  // body's silhouette seen from the front, at one height). -infinity when nothing crosses.
  float slice_reach(glm::vec3 origin, glm::vec3 up, glm::vec3 side, unsigned regions) const {
    float reach = -std::numeric_limits<float>::infinity();
    for (const Chunk& chunk : chunks_) {
      if (!(chunk.regions & regions) || !chunk.straddles(origin, up)) continue;
      for (std::size_t t = chunk.first; t < chunk.end; ++t) {
        if (!(region_[t] & regions)) continue;
        for (std::size_t e = 0; e < 3; ++e) {
          const glm::vec3& p = mesh_.positions[mesh_.indices[3 * t + e]];
          const glm::vec3& q = mesh_.positions[mesh_.indices[3 * t + (e + 1) % 3]];
          const float hp = glm::dot(p - origin, up), hq = glm::dot(q - origin, up);
          if (hp * hq > 0.0f || hp == hq) continue;
          reach = std::max(reach, glm::dot(p + (q - p) * (hp / (hp - hq)) - origin, side));
        }
      }
    }
    return reach;
  }

 private:
  // 64 triangles a run: small enough that a run's box hugs one part of the body, large enough
  // that the boxes (a few hundred) cost little next to the triangles they skip.
  static constexpr std::size_t kChunkTriangles = 64;
  // Box margin in metres: far above the rounding of the triangle test (~1e-6 m on a body-sized
  // mesh), so the box test never rejects a triangle the exact test would hit.
  static constexpr float kMargin_m = 1e-3f;

  struct Chunk {
    std::size_t first = 0, end = 0;
    unsigned regions = 0;
    glm::vec3 lo{0.0f}, hi{0.0f};

    // Whether the box (grown by kMargin_m) has corners on both sides of the plane through
    // `origin` across `up`.
    bool straddles(glm::vec3 origin, glm::vec3 up) const {
      float below = std::numeric_limits<float>::max(), above = std::numeric_limits<float>::lowest();
      for (int c = 0; c < 8; ++c) {
        const glm::vec3 corner((c & 1) ? hi.x + kMargin_m : lo.x - kMargin_m, (c & 2) ? hi.y + kMargin_m : lo.y - kMargin_m,
                               (c & 4) ? hi.z + kMargin_m : lo.z - kMargin_m);
        const float h = glm::dot(corner - origin, up);
        below = std::min(below, h);
        above = std::max(above, h);
      }
      return below <= 0.0f && above >= 0.0f;
    }

    // Slab test of the ray against the box grown by kMargin_m, up to the nearest hit so far.
    bool may_hit(glm::vec3 origin, glm::vec3 dir, float max_distance) const {
      float t0 = 0.0f, t1 = max_distance + kMargin_m;
      for (int k = 0; k < 3; ++k) {
        const float lo_k = lo[k] - kMargin_m, hi_k = hi[k] + kMargin_m;
        if (std::abs(dir[k]) < 1e-12f) {
          if (origin[k] < lo_k || origin[k] > hi_k) return false;
          continue;
        }
        const float inv = 1.0f / dir[k];
        float near = (lo_k - origin[k]) * inv, far = (hi_k - origin[k]) * inv;
        if (near > far) std::swap(near, far);
        t0 = std::max(t0, near);
        t1 = std::min(t1, far);
        if (t0 > t1) return false;
      }
      return true;
    }
  };

  const SkinnedMesh& mesh_;
  std::vector<unsigned> region_;
  std::vector<Chunk> chunks_;
};

class AnchorBuilder {
 public:
  AnchorBuilder(const Avatar& avatar, std::vector<std::string>* warnings)
      : avatar_(avatar), warnings_(warnings), surface_(avatar, joint_regions(avatar)) {}

  std::vector<Anchor> build() {
    frame();
    face_heights();
    body_levels();
    neutral_space();
    for (int side = 0; side < 2; ++side) hand(side == 0);
    for (int side = 0; side < 2; ++side) arm(side == 0);
    return std::move(anchors_);
  }

 private:
  const Avatar& avatar_;
  std::vector<std::string>* warnings_;
  Surface surface_;
  std::vector<Anchor> anchors_;
  // Body frame (bind pose): up, the signer's left, forward (facing).
  glm::vec3 up_{0, 1, 0}, left_{1, 0, 0}, forward_{0, 0, 1};
  glm::vec3 hips_{0.0f};
  // Heights along up_, measured from the hips joint.
  float top_h_ = 0, chin_h_ = 0, eyes_h_ = 0, nose_h_ = 0, head_h_ = 0, neck_h_ = 0;
  float shoulder_h_ = 0, leg_h_ = 0;

  static std::vector<unsigned> joint_regions(const Avatar& a) {
    std::vector<unsigned> region(a.skeleton.joints.size(), kCore);
    std::vector<unsigned> marker(a.skeleton.joints.size(), 0);
    auto mark = [&](int id, unsigned r) {
      const int j = a.canonical_to_joint.size() > static_cast<std::size_t>(id) ? a.canonical_to_joint[static_cast<std::size_t>(id)] : -1;
      if (j >= 0) marker[static_cast<std::size_t>(j)] = r;
    };
    mark(skeleton::kLeftUpperArm, kLeftArm);
    mark(skeleton::kRightUpperArm, kRightArm);
    mark(skeleton::kLeftHand, kLeftHand);
    mark(skeleton::kRightHand, kRightHand);
    mark(skeleton::kLeftUpperLeg, kLegs);
    mark(skeleton::kRightUpperLeg, kLegs);
    for (std::size_t j = 0; j < region.size(); ++j) {  // parents first: inherit, markers override
      const int p = a.skeleton.joints[j].parent;
      region[j] = marker[j] ? marker[j] : (p >= 0 ? region[static_cast<std::size_t>(p)] : kCore);
    }
    return region;
  }

  int joint(int canonical) const { return avatar_.canonical_to_joint[static_cast<std::size_t>(canonical)]; }
  // First present joint of a preference list (optional joints fall back to required ones).
  int joint_of(std::initializer_list<int> preference) const {
    for (int id : preference) if (joint(id) >= 0) return joint(id);
    return joint(skeleton::kHips);
  }
  glm::vec3 bind_position(int j) const { return glm::vec3(glm::inverse(avatar_.inverse_bind[static_cast<std::size_t>(j)])[3]); }
  glm::vec3 position(int canonical) const { return bind_position(joint(canonical)); }
  bool has(int canonical) const { return joint(canonical) >= 0; }
  float height(glm::vec3 p) const { return glm::dot(p - hips_, up_); }

  void warn(const std::string& what) {
    if (warnings_) warnings_->push_back(what);
  }

  void add(const std::string& name, int j, glm::vec3 point, glm::vec3 normal) {
    const glm::mat4& ibm = avatar_.inverse_bind[static_cast<std::size_t>(j)];
    Anchor a;
    a.name = name;
    a.joint = j;
    a.offset = glm::vec3(ibm * glm::vec4(point, 1.0f));
    const glm::vec3 n = glm::vec3(ibm * glm::vec4(normal, 0.0f));
    const float len = glm::length(n);
    a.normal = len > 0.0f ? n / len : normal;
    anchors_.push_back(a);
  }

  // A surface point along dir from inside, or (with a warning) the origin pushed out by fallback_m.
  Hit surface(const std::string& name, glm::vec3 origin, glm::vec3 dir, unsigned regions, float fallback_m) {
    if (auto hit = surface_.cast(origin, dir, regions)) return *hit;
    warn(name + ": no surface found, placed " + std::to_string(fallback_m) + " m from inside");
    return Hit{origin + dir * fallback_m, dir, fallback_m};
  }

  void frame() {
    hips_ = position(skeleton::kHips);
    const glm::vec3 head = position(skeleton::kHead);
    up_ = glm::normalize(head - hips_);
    left_ = perpendicular(position(skeleton::kLeftUpperArm) - position(skeleton::kRightUpperArm), up_);
    forward_ = glm::normalize(glm::cross(left_, up_));
    head_h_ = height(head);
    neck_h_ = height(position(skeleton::kNeck));
    shoulder_h_ = 0.5f * (height(position(skeleton::kLeftUpperArm)) + height(position(skeleton::kRightUpperArm)));
    leg_h_ = has(skeleton::kLeftUpperLeg) && has(skeleton::kRightUpperLeg)
                 ? 0.5f * (height(position(skeleton::kLeftUpperLeg)) + height(position(skeleton::kRightUpperLeg)))
                 : std::min(0.0f, shoulder_h_ - 0.5f * (head_h_ + 0.1f));
  }

  // The body's midline at height h: through hips, neck and head joints, vertical beyond them.
  glm::vec3 axis(float h) const {
    const glm::vec3 neck = position(skeleton::kNeck), head = position(skeleton::kHead);
    const float hn = neck_h_, hh = head_h_;
    glm::vec3 base;
    if (h <= 0.0f) base = hips_;
    else if (h <= hn) base = glm::mix(hips_, neck, hn > 0.0f ? h / hn : 0.0f);
    else if (h <= hh) base = glm::mix(neck, head, hh > hn ? (h - hn) / (hh - hn) : 0.0f);
    else base = head;
    return base + up_ * (h - height(base));
  }

  void face_heights() {
    const glm::vec3 head = position(skeleton::kHead);
    const Hit top = surface("body/head_top/centre", head + up_ * 0.01f, up_, kCore, 0.2f);
    top_h_ = height(top.point);
    // The face profile: forward depth every 2 mm from the top of the head down to the neck joint.
    struct Sample { float h, depth; };
    std::vector<Sample> profile;
    for (float h = top_h_ - 0.005f; h >= neck_h_; h -= 0.002f) {
      const auto hit = surface_.cast(axis(h), forward_, kCore);
      profile.push_back({h, hit ? hit->distance : 0.0f});
    }
    const float span = top_h_ - neck_h_;
    float face_depth = 0.0f;
    nose_h_ = neck_h_ + 0.6f * span;
    for (const Sample& s : profile) {
      if (s.h < neck_h_ + 0.35f * span || s.h > top_h_ - 0.15f * span) continue;
      if (s.depth > face_depth) { face_depth = s.depth; nose_h_ = s.h; }
    }
    const float neck_depth = profile.empty() ? 0.0f : profile.back().depth;
    const float threshold = neck_depth + 0.35f * (face_depth - neck_depth);
    chin_h_ = neck_h_ + 0.35f * span;
    bool found_chin = false;
    for (const Sample& s : profile) {
      if (s.h < nose_h_ && s.depth < threshold) { chin_h_ = s.h; found_chin = true; break; }
    }
    if (!found_chin) warn("chin: the face profile has no drop to the neck; estimated from head proportions");
    const float head_height = top_h_ - chin_h_;
    eyes_h_ = top_h_ - 0.48f * head_height;
    if (has(skeleton::kLeftEye) && has(skeleton::kRightEye)) {
      const float h = 0.5f * (height(position(skeleton::kLeftEye)) + height(position(skeleton::kRightEye)));
      if (h > chin_h_ && h < top_h_) eyes_h_ = h;
    }
    // A nose peak outside the plausible band (no nose modelled) falls back to proportions.
    if (nose_h_ > eyes_h_ - 0.1f * head_height || nose_h_ < eyes_h_ - 0.4f * head_height)
      nose_h_ = eyes_h_ - 0.2f * head_height;
  }

  float half_width(float h, float sign, unsigned regions, float fallback_m) {
    const auto hit = surface_.cast(axis(h), left_ * sign, regions);
    return hit ? hit->distance : fallback_m;
  }

  // The five sides of one level: front-surface points across, or lateral/oblique rays for the
  // levels whose sides are on the side of the head (ears, cheeks).
  // `regions`: the parts a level's rays may stop on (below the waist the thighs' skin is there).
  void level(const std::string& name, float h, int j, int j_left, int j_right, float inset_m = 0.0f,
             unsigned regions = kCore) {
    const glm::vec3 o = axis(h);
    const auto reach = [&](int id) {
      const glm::vec3 d = position(id) - o;
      return glm::length(d - up_ * glm::dot(d, up_));
    };
    const float wl = half_width(h, 1.0f, regions, name == "shoulders" ? reach(skeleton::kLeftUpperArm) : 0.08f);
    const float wr = half_width(h, -1.0f, regions, name == "shoulders" ? reach(skeleton::kRightUpperArm) : 0.08f);
    const Hit centre = surface("body/" + name + "/centre", o, forward_, regions, 0.08f);
    const std::string base = "body/" + name + "/";
    Hit left, right;
    if (name == "ears") {
      left = surface(base + "left", o, left_, kCore, wl);
      right = surface(base + "right", o, -left_, kCore, wr);
    } else if (name == "cheeks") {
      left = surface(base + "left", o, glm::normalize(forward_ * 0.8f + left_ * 0.6f), kCore, wl);
      right = surface(base + "right", o, glm::normalize(forward_ * 0.8f - left_ * 0.6f), kCore, wr);
    } else if (name == "shoulders") {
      // The front of each shoulder: three quarters of the way out to the upper-arm joint, where
      // the deltoid (often weighted to the arm) begins.
      const unsigned with_arms = regions | kLeftArm | kRightArm;
      left = surface(base + "left", o + left_ * (0.75f * reach(skeleton::kLeftUpperArm)), forward_, with_arms, centre.distance);
      right = surface(base + "right", o - left_ * (0.75f * reach(skeleton::kRightUpperArm)), forward_, with_arms, centre.distance);
    } else {
      left = surface(base + "left", o + left_ * (0.5f * wl), forward_, regions, centre.distance);
      right = surface(base + "right", o - left_ * (0.5f * wr), forward_, regions, centre.distance);
    }
    // Teeth and tongue sit behind the lips: the lip points moved inward along the normal.
    const auto inside = [&](Hit hit) { hit.point -= forward_ * inset_m; return hit; };
    // Beside: 1.6 half-widths out, and at least kBesideClear_m beyond the body's silhouette at
    // this height (the skin of the trunk, head and legs, arms left out). At the shoulder joints'
    // height the sideways ray runs along a T-posed arm and finds no skin: the half width was
    // then the 8 cm fallback and `shoulders/*_beside` 12.8 cm out, in front of the shoulder
    // (which reaches 23 cm on the project avatar); there the half width is the upper-arm
    // joint's reach instead. Where the shoulders' slope is still beside a neck level, the
    // silhouette keeps the place off it.
    const auto beside = [&](float sign, float w) {
      const float silhouette = surface_.slice_reach(o, up_, left_ * sign, regions | kCore);
      const float out = (regions & kLegs) ? std::min(1.6f * w, silhouette + kBesideLegsClearMax_m) : 1.6f * w;
      return std::max(out, silhouette + kBesideClear_m);
    };
    const float bl = beside(1.0f, wl), br = beside(-1.0f, wr);
    add(base + "right_beside", j_right, o - left_ * br + forward_ * (0.5f * centre.distance), forward_);
    add(base + "right", j_right, inside(right).point, right.normal);
    add(base + "centre", j, inside(centre).point, centre.normal);
    add(base + "left", j_left, inside(left).point, left.normal);
    add(base + "left_beside", j_left, o + left_ * bl + forward_ * (0.5f * centre.distance), forward_);
  }

  void body_levels() {
    const int head = joint(skeleton::kHead);
    const int neck = joint(skeleton::kNeck);
    const int chest = joint_of({skeleton::kUpperChest, skeleton::kChest, skeleton::kSpine});
    const int mid = joint_of({skeleton::kChest, skeleton::kSpine});
    const int spine = joint(skeleton::kSpine);
    const int hips = joint(skeleton::kHips);
    const int lshoulder = joint_of({skeleton::kLeftShoulder, skeleton::kUpperChest, skeleton::kChest, skeleton::kSpine});
    const int rshoulder = joint_of({skeleton::kRightShoulder, skeleton::kUpperChest, skeleton::kChest, skeleton::kSpine});
    const float head_height = top_h_ - chin_h_;
    const float eye_w = half_width(eyes_h_, 1.0f, kCore, 0.08f);

    // above_head: off the body, a hand's breadth over the top, sides across the head's width.
    {
      const glm::vec3 o = axis(top_h_) + up_ * (0.45f * head_height);
      for (int s = 0; s < 5; ++s) {
        const float k = static_cast<float>(s - 2) * 0.75f * eye_w;  // right_beside .. left_beside
        add(std::string("body/above_head/") + kSides[static_cast<std::size_t>(s)], head, o + left_ * k, up_);
      }
    }
    // head_top: rays down onto the crown from above, across the head's width.
    {
      for (int s = 0; s < 5; ++s) {
        const float k = static_cast<float>(s - 2) * 0.5f * eye_w;
        const std::string name = std::string("body/head_top/") + kSides[static_cast<std::size_t>(s)];
        const glm::vec3 above = axis(top_h_) + up_ * 0.05f + left_ * (s == 0 || s == 4 ? 2.4f * k : k);
        if (s == 0 || s == 4) {
          add(name, head, above - up_ * 0.05f, up_);  // beside the top: off the body
        } else {
          const Hit hit = surface(name, above, -up_, kCore, 0.05f);
          add(name, head, hit.point, -hit.normal);  // the ray came from outside: flip
        }
      }
    }
    level("head", top_h_ - 0.15f * head_height, head, head, head);
    level("forehead", eyes_h_ + 0.2f * head_height, head, head, head);
    level("eyebrows", eyes_h_ + 0.1f * head_height, head, head, head);
    level("eyes", eyes_h_, head, head, head);
    level("nose", nose_h_, head, head, head);
    level("ears", 0.5f * (eyes_h_ + nose_h_), head, head, head);
    level("cheeks", 0.4f * eyes_h_ + 0.6f * nose_h_, head, head, head);
    const float mouth_h = chin_h_ + 0.6f * (nose_h_ - chin_h_);
    level("mouth", mouth_h, head, head, head);
    level("lips", mouth_h, head, head, head);
    level("teeth", mouth_h, head, head, head, 0.012f);
    level("tongue", mouth_h, head, head, head, 0.02f);
    level("chin", chin_h_ + 0.08f * head_height, head, head, head);
    const float neck_level = neck_h_ + 0.2f * (chin_h_ - neck_h_);
    under_chin(neck_level, head);
    level("neck", neck_level, neck, neck, neck);
    level("shoulders", shoulder_h_, chest, lshoulder, rshoulder);
    shoulder_top(chest, lshoulder, rshoulder);
    const float torso = shoulder_h_ - leg_h_;
    level("chest", leg_h_ + 0.70f * torso, chest, chest, chest);
    level("stomach", leg_h_ + 0.55f * torso, mid, mid, mid);
    level("belly", leg_h_ + 0.42f * torso, spine, spine, spine);
    level("waist", leg_h_ + 0.32f * torso, spine, spine, spine);
    level("below_waist", leg_h_ + 0.14f * torso, hips, hips, hips, 0.0f, kCore | kLegs);
  }

  // Under the chin: rays up from just in front of the neck onto the jaw's underside.
  void under_chin(float neck_level, int head) {
    const glm::vec3 o = axis(neck_level);
    const Hit neck_front = surface("body/neck/centre", o, forward_, kCore, 0.05f);
    // The chin's front at the chin anchor's height (chin_h_ itself is where the profile has
    // already dropped toward the neck).
    const float chin_point_h = chin_h_ + 0.08f * (top_h_ - chin_h_);
    const Hit chin_front = surface("body/chin/centre", axis(chin_point_h), forward_, kCore, neck_front.distance + 0.03f);
    // Under the jaw: rays up from below a point 1.5 cm behind the chin's front (the neck's front
    // slopes forward toward the jaw, and a ray started nearer the neck stops on that slope).
    const float depth = std::max(chin_front.distance - 0.015f, 0.0f);
    const float w = half_width(neck_level, 1.0f, kCore, 0.05f);
    for (int s = 0; s < 5; ++s) {
      const std::string name = std::string("body/under_chin/") + kSides[static_cast<std::size_t>(s)];
      const float k = static_cast<float>(s - 2) * 0.5f * w;
      const glm::vec3 chin = axis(chin_point_h) + forward_ * depth + left_ * k;
      const glm::vec3 start = chin - up_ * (chin_point_h - neck_level);
      if (s == 0 || s == 4) {
        add(name, head, start + left_ * (2.0f * k), -up_);
        continue;
      }
      auto hit = surface_.cast(start, up_, kCore);
      if (!hit || height(hit->point) > chin_point_h || height(hit->point) < neck_level) {
        warn(name + ": no jaw underside found, placed below the chin");
        add(name, head, chin - up_ * 0.01f, -up_);
      } else {
        add(name, head, hit->point, -hit->normal);
      }
    }
  }

  // Tops of the shoulders: rays down from above the shoulder line; centre at the neck's base.
  void shoulder_top(int chest, int lshoulder, int rshoulder) {
    // Horizontal distance from the midline to the shoulder joints.
    const auto horizontal = [&](glm::vec3 v) { return glm::length(v - up_ * glm::dot(v, up_)); };
    const glm::vec3 centre = axis(shoulder_h_);
    const float reach = 0.5f * (horizontal(position(skeleton::kLeftUpperArm) - centre) +
                                horizontal(position(skeleton::kRightUpperArm) - centre));
    for (int s = 0; s < 5; ++s) {
      const std::string name = std::string("body/shoulder_top/") + kSides[static_cast<std::size_t>(s)];
      const float sign = s < 2 ? -1.0f : 1.0f;
      const int j = s < 2 ? rshoulder : s > 2 ? lshoulder : chest;
      if (s == 2) {
        const Hit hit = surface(name, axis(neck_h_), forward_, kCore, 0.05f);
        add(name, chest, hit.point, hit.normal);
      } else if (s == 0 || s == 4) {
        add(name, j, axis(shoulder_h_) + left_ * (sign * 1.3f * reach) + up_ * 0.05f, up_);
      } else {
        const glm::vec3 above = axis(shoulder_h_) + left_ * (sign * 0.6f * reach) + up_ * 0.3f;
        // Only a hit near the shoulder line is the shoulder's top (not the floor of an open mesh).
        const auto hit = surface_.cast(above, -up_, kCore | kLeftArm | kRightArm);
        if (hit && std::abs(height(hit->point) - shoulder_h_) < 0.12f) {
          add(name, j, hit->point, -hit->normal);
        } else {
          warn(name + ": no shoulder top found, placed at the shoulder line");
          add(name, j, above - up_ * 0.3f, up_);
        }
      }
    }
  }

  void neutral_space() {
    const float torso = shoulder_h_ - leg_h_;
    const float h = leg_h_ + 0.62f * torso;  // between chest and stomach
    const glm::vec3 o = axis(h);
    const Hit front = surface("space/centre", o, forward_, kCore, 0.12f);
    const float arm = 0.5f * (glm::length(position(skeleton::kLeftHand) - position(skeleton::kLeftUpperArm)) +
                              glm::length(position(skeleton::kRightHand) - position(skeleton::kRightUpperArm)));
    const float shoulder_half = 0.5f * glm::length(position(skeleton::kLeftUpperArm) - position(skeleton::kRightUpperArm));
    const int j = joint_of({skeleton::kChest, skeleton::kSpine});
    const float across[5] = {-1.1f, -0.5f, 0.0f, 0.5f, 1.1f};
    for (int s = 0; s < 5; ++s) {
      const glm::vec3 p = o + forward_ * (front.distance + 0.45f * arm) + left_ * (across[s] * shoulder_half);
      add(std::string("space/") + kSides[static_cast<std::size_t>(s)], j, p, forward_);
    }
  }

  void hand(bool left) {
    const std::string side = left ? "left" : "right";
    const unsigned region = left ? kLeftHand : kRightHand;
    const unsigned arm_region = left ? kLeftArm : kRightArm;
    const int hand_id = left ? skeleton::kLeftHand : skeleton::kRightHand;
    const glm::vec3 wrist = position(hand_id);
    const glm::vec3 middle = position(skeleton::finger_joint_id(left, Finger::Middle, FingerSegment::Proximal));
    const glm::vec3 index = position(skeleton::finger_joint_id(left, Finger::Index, FingerSegment::Proximal));
    const glm::vec3 little = position(skeleton::finger_joint_id(left, Finger::Little, FingerSegment::Proximal));
    const glm::vec3 along = glm::normalize(middle - wrist);
    const glm::vec3 thumbward = perpendicular(index - little, along);
    // Palm normal: along × thumbward is palmar for a left hand, dorsal for a right one.
    const glm::vec3 palmar = glm::normalize(glm::cross(along, thumbward)) * (left ? 1.0f : -1.0f);
    const int hand_joint = joint(hand_id);
    const glm::vec3 centre = glm::mix(wrist, middle, 0.5f);
    const std::string base = "hand/" + side + "/";
    const float palm_fallback = 0.015f;
    const glm::vec3 dirs[4] = {palmar, -palmar, thumbward, -thumbward};
    for (int k = 0; k < 4; ++k) {
      const Hit hit = surface(base + kHandPlaces[static_cast<std::size_t>(k)], centre, dirs[k], region, k < 2 ? palm_fallback : 0.04f);
      add(base + kHandPlaces[static_cast<std::size_t>(k)], hand_joint, hit.point, hit.normal);
    }
    const Hit wrist_front = surface(base + "wrist", wrist, palmar, region | arm_region, palm_fallback);
    add(base + "wrist", hand_joint, wrist_front.point, wrist_front.normal);
    const Hit wrist_back = surface(base + "wrist_back", wrist, -palmar, region | arm_region, palm_fallback);
    add(base + "wrist_back", hand_joint, wrist_back.point, wrist_back.normal);
    // HamNoSys hamthumbball: the ball of the thumb (thenar eminence) — on the palm, towards the
    // thumb, nearer the wrist than the knuckles.
    const glm::vec3 thenar = glm::mix(wrist, index, 0.35f) + 0.25f * glm::length(index - little) * thumbward;
    const Hit ball = surface(base + "thumb_ball", thenar, palmar, region, palm_fallback);
    add(base + "thumb_ball", hand_joint, ball.point, ball.normal);

    for (int f = 0; f < 5; ++f) {
      const Finger finger = static_cast<Finger>(f);
      const bool thumb = finger == Finger::Thumb;
      // The finger's knuckles: base (MCP), middle joint (PIP; the thumb's IP), distal, tip.
      const int base_id = skeleton::finger_joint_id(left, finger, FingerSegment::Proximal);
      const int middle_id = skeleton::finger_joint_id(left, finger, thumb ? FingerSegment::Distal : FingerSegment::Intermediate);
      const int distal_id = skeleton::finger_joint_id(left, finger, FingerSegment::Distal);
      const int tip_id = skeleton::finger_joint_id(left, finger, FingerSegment::Tip);
      const glm::vec3 base_p = position(base_id), middle_p = position(middle_id), distal_p = position(distal_id);
      const glm::vec3 tip_p = has(tip_id) ? position(tip_id) : distal_p + (distal_p - middle_p) * 0.8f;
      const glm::vec3 dir = glm::normalize(tip_p - distal_p);
      // Palmar side of this finger; the thumb's pad faces the fingers (across the palm).
      const glm::vec3 pad_dir = perpendicular(thumb ? palmar - thumbward : palmar, dir);
      const glm::vec3 side_dir = perpendicular(thumbward, dir);
      const std::string fname = kFingerNames[static_cast<std::size_t>(f)];
      const glm::vec3 last_mid = glm::mix(distal_p, tip_p, 0.5f);
      const int distal_j = joint(distal_id);
      const Hit tip = surface(base + "tip/" + fname, last_mid, dir, region, 0.5f * glm::length(tip_p - distal_p));
      add(base + "tip/" + fname, distal_j, tip.point, tip.normal);
      const Hit pad = surface(base + "pad/" + fname, last_mid, pad_dir, region, 0.008f);
      add(base + "pad/" + fname, distal_j, pad.point, pad.normal);
      const Hit nail = surface(base + "nail/" + fname, last_mid, -pad_dir, region, 0.008f);
      add(base + "nail/" + fname, distal_j, nail.point, nail.normal);
      const glm::vec3 base_o = glm::mix(base_p, middle_p, 0.2f);
      const Hit fbase = surface(base + "base/" + fname, base_o, perpendicular(pad_dir, glm::normalize(middle_p - base_p)), region, 0.01f);
      add(base + "base/" + fname, joint(base_id), fbase.point, fbase.normal);
      const Hit knuckle = surface(base + "middle_joint/" + fname, middle_p, -pad_dir, region, 0.01f);
      add(base + "middle_joint/" + fname, joint(middle_id), knuckle.point, knuckle.normal);
      const Hit fside = surface(base + "side/" + fname, glm::mix(base_p, middle_p, 0.5f), side_dir, region, 0.01f);
      add(base + "side/" + fname, joint(base_id), fside.point, fside.normal);
    }
  }

  void arm(bool left) {
    const std::string base = std::string("arm/") + (left ? "left" : "right") + "/";
    const unsigned region = left ? kLeftArm : kRightArm;
    const int upper_id = left ? skeleton::kLeftUpperArm : skeleton::kRightUpperArm;
    const int lower_id = left ? skeleton::kLeftLowerArm : skeleton::kRightLowerArm;
    const int hand_id = left ? skeleton::kLeftHand : skeleton::kRightHand;
    const glm::vec3 shoulder = position(upper_id), elbow = position(lower_id), wrist = position(hand_id);
    const glm::vec3 fore_axis = glm::normalize(wrist - elbow);
    const glm::vec3 upper_axis = glm::normalize(elbow - shoulder);
    // The palm's side of the forearm, as the hand's palm normal (rest pose).
    const glm::vec3 middle = position(skeleton::finger_joint_id(left, Finger::Middle, FingerSegment::Proximal));
    const glm::vec3 index = position(skeleton::finger_joint_id(left, Finger::Index, FingerSegment::Proximal));
    const glm::vec3 little = position(skeleton::finger_joint_id(left, Finger::Little, FingerSegment::Proximal));
    const glm::vec3 along = glm::normalize(middle - wrist);
    const glm::vec3 palmar = perpendicular(glm::cross(along, perpendicular(index - little, along)) * (left ? 1.0f : -1.0f), fore_axis);
    const glm::vec3 mid_fore = glm::mix(elbow, wrist, 0.5f);
    const Hit fore = surface(base + "forearm", mid_fore, palmar, region, 0.035f);
    add(base + "forearm", joint(lower_id), fore.point, fore.normal);
    const Hit fore_back = surface(base + "forearm_back", mid_fore, -palmar, region, 0.035f);
    add(base + "forearm_back", joint(lower_id), fore_back.point, fore_back.normal);
    // From just below the joint, so the ray does not graze the seam where the arm's parts meet.
    const Hit tip = surface(base + "elbow", elbow + fore_axis * 0.01f, perpendicular(-forward_, upper_axis), region, 0.04f);
    add(base + "elbow", joint(lower_id), tip.point, tip.normal);
    const glm::vec3 outward = perpendicular(left_ * (left ? 1.0f : -1.0f) + up_, upper_axis);
    const Hit upper = surface(base + "upper_arm", glm::mix(shoulder, elbow, 0.5f), outward, region, 0.045f);
    add(base + "upper_arm", joint(upper_id), upper.point, upper.normal);
    // HamNoSys hamelbowinside: the crook of the elbow, opposite the elbow's tip.
    const Hit crook = surface(base + "elbow_inside", elbow + fore_axis * 0.01f, perpendicular(forward_, upper_axis), region, 0.04f);
    add(base + "elbow_inside", joint(lower_id), crook.point, crook.normal);
  }
};

}  // namespace

std::vector<Anchor> compute_body_anchors(const Avatar& avatar, std::vector<std::string>* warnings) {
  // The loader guarantees the required joints; a hand-built Avatar without them gets no anchors.
  if (avatar.canonical_to_joint.size() != static_cast<std::size_t>(skeleton::kHumanoidJointCount) ||
      avatar.inverse_bind.size() != avatar.skeleton.joints.size()) {
    if (warnings) warnings->push_back("avatar has no canonical joint map: no anchors");
    return {};
  }
  for (int id = 0; id < skeleton::kHumanoidJointCount; ++id) {
    if (skeleton::humanoid_joint_required(id) && avatar.canonical_to_joint[static_cast<std::size_t>(id)] < 0) {
      if (warnings) warnings->push_back("required joint " + std::string(skeleton::humanoid_joint_name(id)) + " missing: no anchors");
      return {};
    }
  }
  return AnchorBuilder(avatar, warnings).build();
}

std::vector<std::string> body_anchor_names() {
  std::vector<std::string> names;
  for (const char* level : kLevels)
    for (const char* side : kSides) names.push_back(std::string("body/") + level + "/" + side);
  for (const char* side : kSides) names.push_back(std::string("space/") + side);
  for (const char* hand : {"left", "right"}) {
    for (const char* place : kHandPlaces) names.push_back(std::string("hand/") + hand + "/" + place);
    for (const char* finger : kFingerNames)
      for (const char* place : kFingerPlaces) names.push_back(std::string("hand/") + hand + "/" + place + "/" + finger);
  }
  for (const char* arm : {"left", "right"})
    for (const char* place : kArmPlaces) names.push_back(std::string("arm/") + arm + "/" + place);
  return names;
}

int find_anchor(const Avatar& avatar, std::string_view name) {
  for (std::size_t i = 0; i < avatar.anchors.size(); ++i)
    if (avatar.anchors[i].name == name) return static_cast<int>(i);
  return -1;
}

std::string body_anchor_name(notation::BodyLevel level, notation::Side side) {
  const auto s = static_cast<std::size_t>(side);
  const std::string side_name = s < kSides.size() ? kSides[s] : "centre";
  if (level == notation::BodyLevel::NeutralSpace) return "space/" + side_name;
  const auto l = static_cast<std::size_t>(level);
  return std::string("body/") + (l < kLevels.size() ? kLevels[l] : "chest") + "/" + side_name;
}

std::string hand_anchor_name(bool left, notation::HandPlace place, notation::Finger finger) {
  using notation::HandPlace;
  const std::string side = left ? "left" : "right";
  const auto f = static_cast<std::size_t>(finger);
  const std::string fname = f < kFingerNames.size() ? kFingerNames[f] : "index";
  switch (place) {
    case HandPlace::Palm: return "hand/" + side + "/palm";
    case HandPlace::BackOfHand: return "hand/" + side + "/back";
    case HandPlace::ThumbSide: return "hand/" + side + "/thumb_side";
    case HandPlace::LittleSide: return "hand/" + side + "/little_side";
    case HandPlace::Fingertip: return "hand/" + side + "/tip/" + fname;
    case HandPlace::FingerPad: return "hand/" + side + "/pad/" + fname;
    case HandPlace::FingerNail: return "hand/" + side + "/nail/" + fname;
    case HandPlace::FingerBase: return "hand/" + side + "/base/" + fname;
    case HandPlace::FingerMiddleJoint: return "hand/" + side + "/middle_joint/" + fname;
    case HandPlace::FingerSide: return "hand/" + side + "/side/" + fname;
    case HandPlace::Wrist: return "hand/" + side + "/wrist";
    case HandPlace::WristBack: return "hand/" + side + "/wrist_back";
    case HandPlace::Forearm: return "arm/" + side + "/forearm";
    case HandPlace::ForearmBack: return "arm/" + side + "/forearm_back";
    case HandPlace::Elbow: return "arm/" + side + "/elbow";
    case HandPlace::UpperArm: return "arm/" + side + "/upper_arm";
    case HandPlace::ThumbBall: return "hand/" + side + "/thumb_ball";
    case HandPlace::ElbowInside: return "arm/" + side + "/elbow_inside";
  }
  return "hand/" + side + "/palm";
}

}  // namespace sw::avatar
