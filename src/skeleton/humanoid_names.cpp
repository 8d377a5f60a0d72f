// Humanoid names: canonical id table and the alias tables (Mixamo, VRM 0.x, Biped, BVH, Unreal,
// Rigify/Blender suffixes). See humanoid_names.h.
#include "skeleton/humanoid_names.h"

#include <array>
#include <cctype>
#include <string>
#include <unordered_map>

namespace sw::skeleton {
namespace {

constexpr std::array<std::string_view, kHumanoidJointCount> kNames = {
#define X(id, name) std::string_view(name),
    SW_HUMANOID_JOINTS
#undef X
};

// Lower-case, without separators: the form both the alias keys and the looked-up names take.
std::string squash(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (char c : text) {
    const unsigned char u = static_cast<unsigned char>(c);
    if (std::isalnum(u)) out.push_back(static_cast<char>(std::tolower(u)));
  }
  return out;
}

bool is_separator(char c) { return c == ' ' || c == '_' || c == '.' || c == '-'; }

// Normalised form of a rig's joint name: namespace prefixes dropped ("mixamorig:", "Armature|"),
// rig prefixes dropped ("Bip01 ", "DEF-"), a separate side token ("L", "_r", ".L", "Left") moved
// to the front as "left"/"right", then lower-cased without separators.
std::string normalise(std::string_view name) {
  const std::size_t cut = name.find_last_of(":|");
  if (cut != std::string_view::npos) name.remove_prefix(cut + 1);

  std::vector<std::string> tokens;
  std::string current;
  for (char c : name) {
    if (is_separator(c)) {
      if (!current.empty()) tokens.push_back(current), current.clear();
    } else {
      current.push_back(static_cast<char>(std::tolower(static_cast<unsigned char>(c))));
    }
  }
  if (!current.empty()) tokens.push_back(current);

  static const std::array<std::string_view, 7> kRigPrefixes = {
      "mixamorig", "bip01", "bip001", "def", "org", "armature", "mixamo"};
  std::string side;
  std::string body;
  for (std::size_t i = 0; i < tokens.size(); ++i) {
    std::string& token = tokens[i];
    bool is_prefix = false;
    if (i == 0) {
      for (std::string_view prefix : kRigPrefixes) {
        if (token == prefix) {
          is_prefix = true;
          break;
        }
        // "mixamorigLeftArm", "Bip01Spine": a prefix glued to the rest.
        if (token.size() > prefix.size() && token.compare(0, prefix.size(), prefix) == 0 &&
            (prefix == "mixamorig" || prefix == "bip01" || prefix == "bip001")) {
          token.erase(0, prefix.size());
          break;
        }
      }
    }
    if (is_prefix) continue;
    if (side.empty() && (token == "l" || token == "left")) {
      side = "left";
      continue;
    }
    if (side.empty() && (token == "r" || token == "right")) {
      side = "right";
      continue;
    }
    for (char c : token) {
      if (std::isalnum(static_cast<unsigned char>(c))) body.push_back(c);
    }
  }
  return side + body;
}

// Alias patterns in normalised form: '@' expands to left/right, '#' to l/r. The canonical side
// pattern uses '@' for left/right too ("@UpperArm" -> "leftUpperArm").
struct Alias {
  std::string_view pattern;
  std::string_view canonical;
};

constexpr Alias kAliases[] = {
    // Torso and head: Mixamo, cgspeed/CMU BVH, Biped, Unreal.
    {"pelvis", "hips"},
    {"hip", "hips"},
    {"spine1", "chest"},
    {"spine2", "upperChest"},
    {"spine01", "spine"},
    {"spine02", "chest"},
    {"spine03", "upperChest"},
    {"lowerback", "spine"},
    {"upperback", "chest"},
    {"thorax", "upperChest"},
    {"lowerneck", "neck"},
    {"neck01", "neck"},
    {"neck1", "neck"},
    // Arms.
    {"@arm", "@UpperArm"},
    {"@forearm", "@LowerArm"},
    {"@shoulder", "@Shoulder"},
    {"@clavicle", "@Shoulder"},
    {"@collar", "@Shoulder"},
    {"@elbow", "@LowerArm"},
    {"@wrist", "@Hand"},
    {"#clavicle", "@Shoulder"},
    {"#humerus", "@UpperArm"},
    {"#radius", "@LowerArm"},
    {"#hand", "@Hand"},
    {"#thumb", "@ThumbMetacarpal"},
    // Legs.
    {"@upleg", "@UpperLeg"},
    {"@leg", "@LowerLeg"},
    {"@thigh", "@UpperLeg"},
    {"@calf", "@LowerLeg"},
    {"@shin", "@LowerLeg"},
    {"@knee", "@LowerLeg"},
    {"@hip", "@UpperLeg"},
    {"@ankle", "@Foot"},
    {"@toebase", "@Toes"},
    {"@toe", "@Toes"},
    {"@toe0", "@Toes"},
    {"@ball", "@Toes"},
    {"#femur", "@UpperLeg"},
    {"#tibia", "@LowerLeg"},
    {"#foot", "@Foot"},
    {"#toes", "@Toes"},
};

void add_expanded(std::unordered_map<std::string, int>& table, std::string_view pattern,
                  int left_id, int right_id, bool sided) {
  if (!sided) {
    table.emplace(squash(pattern), left_id);
    return;
  }
  for (int s = 0; s < 2; ++s) {
    std::string key;
    for (char c : pattern) {
      if (c == '@')
        key += s == 0 ? "left" : "right";
      else if (c == '#')
        key += s == 0 ? "l" : "r";
      else
        key.push_back(c);
    }
    table.emplace(squash(key), s == 0 ? left_id : right_id);
  }
}

int id_of_canonical(std::string_view name) {
  for (int i = 0; i < kHumanoidJointCount; ++i) {
    if (kNames[static_cast<std::size_t>(i)] == name) return i;
  }
  return -1;
}

const std::unordered_map<std::string, int>& alias_table() {
  static const std::unordered_map<std::string, int> table = [] {
    std::unordered_map<std::string, int> t;
    // Canonical names first so they win over any alias (emplace keeps the first).
    for (int i = 0; i < kHumanoidJointCount; ++i)
      t.emplace(squash(kNames[static_cast<std::size_t>(i)]), i);
    for (const Alias& alias : kAliases) {
      const std::string_view c = alias.canonical;
      if (!c.empty() && c[0] == '@') {
        const std::string rest(c.substr(1));
        add_expanded(t, alias.pattern, id_of_canonical("left" + rest),
                     id_of_canonical("right" + rest), true);
      } else {
        add_expanded(t, alias.pattern, id_of_canonical(c), -1, false);
      }
    }
    // Fingers, generated per convention. Segments 0..4: metacarpal, proximal, intermediate,
    // distal, tip; numbered joints count from the first bone each rig has.
    const std::array<std::array<std::string_view, 3>, kFingerCount> finger_words = {
        {{"thumb", "thumb", "thumb"},
         {"index", "index", "index"},
         {"middle", "middle", "middle"},
         {"ring", "ring", "ring"},
         {"little", "pinky", "pinkie"}}};
    for (int side = 0; side < 2; ++side) {
      const bool left = side == 0;
      const std::string s = left ? "left" : "right";
      for (int f = 0; f < kFingerCount; ++f) {
        const Finger finger = static_cast<Finger>(f);
        // Numbered bones 1..3 (+ 4 = the end point): thumb starts at its metacarpal,
        // the other fingers at their proximal phalanx (Mixamo, Unreal, Rigify).
        const std::array<FingerSegment, 4> numbered =
            finger == Finger::Thumb
                ? std::array<FingerSegment, 4>{FingerSegment::Metacarpal, FingerSegment::Proximal,
                                               FingerSegment::Distal, FingerSegment::Tip}
                : std::array<FingerSegment, 4>{FingerSegment::Proximal, FingerSegment::Intermediate,
                                               FingerSegment::Distal, FingerSegment::Tip};
        for (std::string_view word : finger_words[static_cast<std::size_t>(f)]) {
          const std::string w(word);
          for (int k = 0; k < 4; ++k) {
            const int id = finger_joint_id(left, finger, numbered[static_cast<std::size_t>(k)]);
            const std::string n = std::to_string(k + 1);
            t.emplace(s + "hand" + w + n, id);     // Mixamo, cgspeed BVH: LeftHandIndex1
            t.emplace(s + w + n, id);              // leftIndex1
            t.emplace(s + w + "0" + n, id);        // Unreal index_01_l, Rigify thumb.01.L
            t.emplace(s + "f" + w + "0" + n, id);  // Rigify f_index.01.L
          }
          t.emplace(s + w + "metacarpal", finger_joint_id(left, finger, FingerSegment::Metacarpal));
          t.emplace(s + w + "tip", finger_joint_id(left, finger, FingerSegment::Tip));
          // VRM 0.x: ThumbIntermediate is the VRM 1.0 ThumbProximal (unambiguous).
          if (finger == Finger::Thumb) {
            t.emplace(s + w + "intermediate",
                      finger_joint_id(left, finger, FingerSegment::Proximal));
          } else {
            t.emplace(s + w + "proximal", finger_joint_id(left, finger, FingerSegment::Proximal));
            t.emplace(s + w + "intermediate",
                      finger_joint_id(left, finger, FingerSegment::Intermediate));
            t.emplace(s + w + "distal", finger_joint_id(left, finger, FingerSegment::Distal));
          }
        }
        // 3ds Max Biped: Finger0 = thumb, Finger1 = index ...; "Finger0", "Finger01", "Finger02",
        // "Finger0Nub".
        const std::string biped = s + "finger" + std::to_string(f);
        t.emplace(biped, finger_joint_id(left, finger, numbered[0]));
        t.emplace(biped + std::to_string(1), finger_joint_id(left, finger, numbered[1]));
        t.emplace(biped + std::to_string(2), finger_joint_id(left, finger, numbered[2]));
        t.emplace(biped + "nub", finger_joint_id(left, finger, numbered[3]));
        // Rigify palm.01..04: metacarpals of index..little.
        if (f > 0) {
          t.emplace(s + "palm0" + std::to_string(f),
                    finger_joint_id(left, finger, FingerSegment::Metacarpal));
        }
      }
    }
    return t;
  }();
  return table;
}

bool is_vrm0_thumb_name(const std::string& normalised, std::string_view segment) {
  const std::string suffix = "thumb" + std::string(segment);
  return normalised.size() > suffix.size() &&
         normalised.compare(normalised.size() - suffix.size(), suffix.size(), suffix) == 0;
}

}  // namespace

std::string_view humanoid_joint_name(int id) {
  if (id < 0 || id >= kHumanoidJointCount) return {};
  return kNames[static_cast<std::size_t>(id)];
}

int canonical_joint_id(std::string_view any_name) {
  const std::string key = normalise(any_name);
  if (key.empty()) return -1;
  const auto& table = alias_table();
  const auto it = table.find(key);
  return it == table.end() ? -1 : it->second;
}

int canonical_joint_id_vrm0(std::string_view vrm0_bone_name) {
  const std::string key = normalise(vrm0_bone_name);
  const bool left = key.rfind("left", 0) == 0;
  const bool right = key.rfind("right", 0) == 0;
  if (left || right) {
    // VRM 0.x thumb: Proximal/Intermediate/Distal = VRM 1.0 Metacarpal/Proximal/Distal.
    if (is_vrm0_thumb_name(key, "proximal"))
      return finger_joint_id(left, Finger::Thumb, FingerSegment::Metacarpal);
    if (is_vrm0_thumb_name(key, "intermediate"))
      return finger_joint_id(left, Finger::Thumb, FingerSegment::Proximal);
  }
  return canonical_joint_id(vrm0_bone_name);
}

std::vector<int> map_humanoid_names(const std::vector<std::string>& names) {
  bool vrm0_thumbs = false;
  for (const std::string& name : names) {
    if (is_vrm0_thumb_name(normalise(name), "intermediate")) vrm0_thumbs = true;
  }
  std::vector<int> ids(names.size(), -1);
  std::vector<bool> taken(kHumanoidJointCount, false);
  for (std::size_t i = 0; i < names.size(); ++i) {
    const int id = vrm0_thumbs ? canonical_joint_id_vrm0(names[i]) : canonical_joint_id(names[i]);
    if (id < 0 || taken[static_cast<std::size_t>(id)]) continue;
    taken[static_cast<std::size_t>(id)] = true;
    ids[i] = id;
  }
  return ids;
}

int finger_joint_id(bool left, Finger finger, FingerSegment segment) {
  const int base = left ? kLeftThumbMetacarpal : kRightThumbMetacarpal;
  const int f = static_cast<int>(finger);
  const int seg = static_cast<int>(segment);
  if (f < 0 || f >= kFingerCount || seg < 0 || seg >= kFingerSegmentCount) return -1;
  if (finger == Finger::Thumb) {
    switch (segment) {
      case FingerSegment::Metacarpal:
        return base + 0;
      case FingerSegment::Proximal:
        return base + 1;
      case FingerSegment::Intermediate:
        return -1;
      case FingerSegment::Distal:
        return base + 2;
      case FingerSegment::Tip:
        return base + 3;
    }
    return -1;
  }
  return base + 4 + (f - 1) * kFingerSegmentCount + seg;
}

int humanoid_parent(int id) {
  if (id < 0 || id >= kHumanoidJointCount) return -1;
  switch (id) {
    case kHips:
      return -1;
    case kSpine:
      return kHips;
    case kChest:
      return kSpine;
    case kUpperChest:
      return kChest;
    case kNeck:
      return kUpperChest;
    case kHead:
      return kNeck;
    case kJaw:
    case kLeftEye:
    case kRightEye:
      return kHead;
    case kLeftShoulder:
    case kRightShoulder:
      return kUpperChest;
    case kLeftUpperLeg:
    case kRightUpperLeg:
      return kHips;
    default:
      break;
  }
  // Chains: each arm, hand and leg joint's parent is the joint before it, except a finger's first
  // segment, whose parent is the hand.
  const bool left_arm = id >= kLeftShoulder && id <= kLeftLittleTip;
  const bool right_arm = id >= kRightShoulder && id <= kRightLittleTip;
  if (left_arm || right_arm) {
    const bool left = left_arm;
    const int hand = left ? kLeftHand : kRightHand;
    if (id <= hand) return id - 1;
    const int thumb_meta = finger_joint_id(left, Finger::Thumb, FingerSegment::Metacarpal);
    if (id == thumb_meta) return hand;
    for (int f = 1; f < kFingerCount; ++f) {
      if (id == finger_joint_id(left, static_cast<Finger>(f), FingerSegment::Metacarpal))
        return hand;
    }
    return id - 1;
  }
  return id - 1;  // legs: upperLeg -> lowerLeg -> foot -> toes
}

bool humanoid_joint_required(int id) {
  switch (id) {
    case kHips:
    case kSpine:
    case kNeck:
    case kHead:
    case kLeftUpperArm:
    case kLeftLowerArm:
    case kLeftHand:
    case kRightUpperArm:
    case kRightLowerArm:
    case kRightHand:
      return true;
    default:
      break;
  }
  for (int side = 0; side < 2; ++side) {
    for (int f = 0; f < kFingerCount; ++f) {
      const Finger finger = static_cast<Finger>(f);
      for (FingerSegment seg : {FingerSegment::Metacarpal, FingerSegment::Proximal,
                                FingerSegment::Intermediate, FingerSegment::Distal}) {
        if (seg == FingerSegment::Metacarpal && finger != Finger::Thumb) continue;
        if (finger_joint_id(side == 0, finger, seg) == id) return true;
      }
    }
  }
  return false;
}

}  // namespace sw::skeleton
