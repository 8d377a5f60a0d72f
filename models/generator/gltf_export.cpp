// glTF export; see gltf_export.h.
#include "gltf_export.h"

#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

namespace sw::avatar_generator {

namespace {

// Materials in sRGB as a designer picks them; glTF base colours are linear (§3.9.2).
glm::vec3 srgb_to_linear(glm::vec3 c) {
  auto f = [](float v) {
    return v <= 0.04045f ? v / 12.92f : std::pow((v + 0.055f) / 1.055f, 2.4f);
  };
  return {f(c.x), f(c.y), f(c.z)};
}

struct MaterialLook {
  glm::vec3 srgb;
  float roughness;
};

// Dark plain clothing, as interpreters wear, so the hands stand out against the torso.
MaterialLook look(Material m) {
  switch (m) {
    case Material::kSkin:
      return {{0.87f, 0.68f, 0.56f}, 0.55f};
    case Material::kTop:
      return {{0.11f, 0.15f, 0.24f}, 0.85f};
    case Material::kTrousers:
      return {{0.20f, 0.20f, 0.23f}, 0.85f};
    case Material::kShoes:
      return {{0.10f, 0.08f, 0.07f}, 0.5f};
    case Material::kHair:
      return {{0.20f, 0.13f, 0.09f}, 0.7f};
    case Material::kLips:
      return {{0.74f, 0.44f, 0.42f}, 0.45f};
    case Material::kBrows:
      return {{0.24f, 0.16f, 0.11f}, 0.8f};
    case Material::kMouthInner:
      return {{0.28f, 0.07f, 0.08f}, 0.6f};
    case Material::kEyeWhite:
      return {{0.93f, 0.92f, 0.89f}, 0.2f};
    case Material::kIris:
      return {{0.22f, 0.14f, 0.09f}, 0.15f};
    case Material::kTongue:
      return {{0.76f, 0.38f, 0.40f}, 0.45f};
    case Material::kTeeth:
      return {{0.92f, 0.90f, 0.84f}, 0.3f};
    case Material::kCount:
      break;
  }
  return {{1, 0, 1}, 1};
}

// VRM 1.0 human bones are the canonical names minus the non-VRM metacarpals of the four
// fingers and the fingertip points (which stay canonical node names).
bool is_vrm_human_bone(const std::string& name) {
  if (name.size() > 3 && name.compare(name.size() - 3, 3, "Tip") == 0) return false;
  if (name.find("Metacarpal") != std::string::npos && name.find("Thumb") == std::string::npos)
    return false;
  return true;
}

}  // namespace

void export_avatar(const ExportModel& model, GlbBuilder& glb) {
  nlohmann::json& doc = glb.document();
  const HumanoidLayout& layout = *model.layout;
  doc["asset"] = {{"version", "2.0"},
                  {"generator", "Signweave avatar-generator (models/generator)"},
                  {"copyright", "Signweave project; generated, no third-party assets"}};

  // Nodes 0..J-1: the joints (the hips is a scene root); then the mesh nodes, also scene roots
  // (a skinned mesh node's own transform is ignored, glTF 2.0 §3.7.3.1). No wrapper node: the
  // skeleton's root is the hips, nothing above it.
  nlohmann::json nodes = nlohmann::json::array();
  nlohmann::json scene_roots = nlohmann::json::array();
  const int joint_base = 0;
  for (size_t j = 0; j < layout.joints.size(); ++j) {
    const LayoutJoint& joint = layout.joints[j];
    const glm::vec3 parent_position =
        joint.parent >= 0 ? layout.joints[static_cast<size_t>(joint.parent)].position
                          : glm::vec3(0);
    const glm::vec3 t = joint.position - parent_position;  // identity rotation: offset only
    nlohmann::json node = {{"name", joint.name}, {"translation", {t.x, t.y, t.z}}};
    nodes.push_back(node);
    if (joint.parent >= 0)
      nodes[static_cast<size_t>(joint_base + joint.parent)]["children"].push_back(
          joint_base + static_cast<int>(j));
    else
      scene_roots.push_back(joint_base + static_cast<int>(j));
  }

  // Skin: inverse bind = translate(-bind position) since bind rotations are identity.
  std::vector<glm::mat4> inverse_bind;
  nlohmann::json skin_joints = nlohmann::json::array();
  for (size_t j = 0; j < layout.joints.size(); ++j) {
    inverse_bind.push_back(glm::translate(glm::mat4(1.0f), -layout.joints[j].position));
    skin_joints.push_back(joint_base + static_cast<int>(j));
  }
  doc["skins"] = nlohmann::json::array({{{"name", "signweave-skeleton"},
                                         {"joints", skin_joints},
                                         {"skeleton", joint_base + layout.find("hips")},
                                         {"inverseBindMatrices", glb.add_mat4(inverse_bind)}}});

  nlohmann::json materials = nlohmann::json::array();
  for (int m = 0; m < static_cast<int>(Material::kCount); ++m) {
    const MaterialLook l = look(static_cast<Material>(m));
    const glm::vec3 c = srgb_to_linear(l.srgb);
    materials.push_back({{"name", material_name(static_cast<Material>(m))},
                         {"pbrMetallicRoughness",
                          {{"baseColorFactor", {c.x, c.y, c.z, 1.0}},
                           {"metallicFactor", 0.0},
                           {"roughnessFactor", l.roughness}}}});
  }
  doc["materials"] = materials;

  nlohmann::json meshes = nlohmann::json::array();
  auto add_mesh = [&](const char* name, const std::vector<ExportPiece>& pieces, bool with_morphs) {
    if (pieces.empty()) return;
    nlohmann::json primitives = nlohmann::json::array();
    for (const ExportPiece& ep : pieces) {
      const MeshPiece& piece = *ep.piece;
      std::vector<std::uint16_t> joints;
      joints.reserve(ep.skin.joints.size() * 4);
      for (const auto& j4 : ep.skin.joints) joints.insert(joints.end(), j4.begin(), j4.end());
      nlohmann::json attributes = {{"POSITION", glb.add_vec3(piece.positions, true, true)},
                                   {"NORMAL", glb.add_vec3(piece.normals, false, true)},
                                   {"JOINTS_0", glb.add_joints_u16(joints)},
                                   {"WEIGHTS_0", glb.add_vec4(ep.skin.weights)}};
      nlohmann::json primitive = {{"attributes", attributes},
                                  {"indices", glb.add_indices(piece.indices)},
                                  {"material", static_cast<int>(piece.material)},
                                  {"mode", 4}};
      if (with_morphs) {
        nlohmann::json targets = nlohmann::json::array();
        for (const MorphTargetData& morph : ep.morphs) {
          bool moves = false;
          for (const glm::vec3& d : morph.position_deltas) moves = moves || d != glm::vec3(0.0f);
          int accessor;
          if (!moves) {
            // A target that does not move this piece: an accessor with no buffer view is all
            // zeros (glTF 2.0 §3.6.2.3), so it costs no bytes.
            nlohmann::json zero = {{"componentType", 5126},
                                   {"count", piece.positions.size()},
                                   {"type", "VEC3"},
                                   {"min", {0, 0, 0}},
                                   {"max", {0, 0, 0}}};
            doc["accessors"].push_back(zero);
            accessor = static_cast<int>(doc["accessors"].size()) - 1;
          } else {
            // Dense, not sparse: the core loader (src/avatar/gltf_loader.cpp) reads no sparse
            // accessors; the face mesh is kept small instead.
            accessor = glb.add_vec3(morph.position_deltas, true, true);
          }
          targets.push_back({{"POSITION", accessor}});
        }
        primitive["targets"] = targets;
      }
      primitives.push_back(primitive);
    }
    nlohmann::json mesh = {{"name", name}, {"primitives", primitives}};
    if (with_morphs) {
      mesh["weights"] = std::vector<float>(model.morph_names.size(), 0.0f);
      mesh["extras"] = {{"targetNames", model.morph_names}};
    }
    meshes.push_back(mesh);
    const int mesh_index = static_cast<int>(meshes.size()) - 1;
    nodes.push_back({{"name", name}, {"mesh", mesh_index}, {"skin", 0}});
    scene_roots.push_back(static_cast<int>(nodes.size()) - 1);
  };
  add_mesh("body", model.body_pieces, false);
  add_mesh("face", model.face_pieces, !model.morph_names.empty());
  doc["meshes"] = meshes;
  doc["nodes"] = nodes;
  doc["scenes"] = nlohmann::json::array({{{"name", "Signweave"}, {"nodes", scene_roots}}});
  doc["scene"] = 0;

  // VRMC_vrm 1.0: the humanoid mapping (and the minimal required meta).
  nlohmann::json human_bones = nlohmann::json::object();
  for (size_t j = 0; j < layout.joints.size(); ++j)
    if (is_vrm_human_bone(layout.joints[j].name))
      human_bones[layout.joints[j].name] = {{"node", joint_base + static_cast<int>(j)}};
  doc["extensionsUsed"] = {"VRMC_vrm"};
  doc["extensions"]["VRMC_vrm"] = {{"specVersion", "1.0"},
                                   {"meta",
                                    {{"name", "Signweave avatar"},
                                     {"version", "1"},
                                     {"authors", {"Signweave project"}},
                                     {"licenseUrl", "https://vrm.dev/licenses/1.0/"},
                                     {"avatarPermission", "everyone"},
                                     {"commercialUsage", "corporation"},
                                     {"allowRedistribution", true},
                                     {"modification", "allowModificationRedistribution"}}},
                                   {"humanoid", {{"humanBones", human_bones}}}};
}

}  // namespace sw::avatar_generator
