// Embind API of the avatar runtime: load a glTF avatar from bytes, read its static mesh data, pose
// it, set morph weights, skin it — every array a typed-array VIEW into WASM memory (no copies).
// Thin by rule (ARCHITECTURE.md): handle bookkeeping and argument conversion only; the logic is in
// src/avatar (loader, anchors) and src/skinning (pipeline).
//
// JS:
//   const r = core.avatarLoad(uint8Array);          // {id, warnings} or {error: "where: what"}
//   const info = core.avatarInfo(r.id);             // counts, materials, primitives
//   const locals = core.avatarLocals(r.id);         // Float32Array, 10 per joint:
//                                                    //   tx ty tz  qx qy qz qw  sx sy sz (local TRS)
//   core.avatarMorphWeights(r.id)[k] = 0.5;
//   core.avatarUpdate(r.id, true);                  // FK -> palette -> morphs -> LBS (SIMD if built)
//   gl.bufferSubData(..., core.avatarSkinnedPositions(r.id));   // 3 floats per vertex
//   core.avatarFree(r.id);
// Views stay valid until memory grows, which only avatarLoad*/avatarFree can cause: take views
// again after loading. A bad id gives null / empty views / false — never an abort.
#include <emscripten/bind.h>
#include <emscripten/val.h>

#include <cstddef>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "avatar/body_anchors.h"
#include "avatar/gltf_loader.h"
#include "avatar/synthetic_avatar.h"
#include "skeleton/humanoid_names.h"
#include "skeleton/synthetic_humanoid.h"
#include "skinning/avatar_instance.h"

namespace {

using emscripten::typed_memory_view;
using emscripten::val;

// The locals view exposes math::Transform's memory: translation, glm::quat (x, y, z, w), scale.
static_assert(sizeof(sw::math::Transform) == 10 * sizeof(float), "Transform must be 10 packed floats");
static_assert(offsetof(sw::math::Transform, rotation) == 3 * sizeof(float), "rotation after translation");
static_assert(sizeof(glm::vec3) == 12 && sizeof(glm::mat4) == 64, "packed glm types");

struct LoadedAvatar {
  sw::avatar::Avatar avatar;
  std::unique_ptr<sw::skinning::AvatarInstance> instance;  // points into `avatar`
  std::vector<int> parents;
};

std::map<int, std::unique_ptr<LoadedAvatar>>& registry() {
  static std::map<int, std::unique_ptr<LoadedAvatar>> avatars;
  return avatars;
}

LoadedAvatar* find(int id) {
  const auto it = registry().find(id);
  return it == registry().end() ? nullptr : it->second.get();
}

val strings(const std::vector<std::string>& list) {
  val out = val::array();
  for (std::size_t i = 0; i < list.size(); ++i) out.set(static_cast<unsigned>(i), list[i]);
  return out;
}

val register_loaded(sw::avatar::LoadResult result) {
  val out = val::object();
  if (!result.ok()) {
    out.set("error", result.message());
    return out;
  }
  static int next_id = 1;
  auto loaded = std::make_unique<LoadedAvatar>();
  loaded->avatar = std::move(result.avatar);
  std::vector<std::string> warnings = result.warnings;
  loaded->avatar.anchors = sw::avatar::compute_body_anchors(loaded->avatar, &warnings);
  loaded->instance = std::make_unique<sw::skinning::AvatarInstance>(loaded->avatar);
  for (const auto& j : loaded->avatar.skeleton.joints) loaded->parents.push_back(j.parent);
  loaded->instance->update();
  const int id = next_id++;
  registry()[id] = std::move(loaded);
  out.set("id", id);
  out.set("warnings", strings(warnings));
  return out;
}

// Bytes arrive as a Uint8Array (embind passes typed arrays to std::string as raw bytes).
val avatar_load(const std::string& bytes) {
  return register_loaded(sw::avatar::load_avatar(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size()));
}

// The synthetic avatar (avatar/synthetic_avatar.h): the parity tests' input, the same bytes as native.
val avatar_load_synthetic() {
  const std::vector<std::uint8_t> glb = sw::avatar::make_synthetic_avatar_glb();
  return register_loaded(sw::avatar::load_avatar(glb.data(), glb.size()));
}

bool avatar_free(int id) { return registry().erase(id) > 0; }

val avatar_info(int id) {
  LoadedAvatar* a = find(id);
  if (!a) return val::null();
  const auto& mesh = a->avatar.mesh;
  val info = val::object();
  info.set("jointCount", a->avatar.skeleton.joint_count());
  info.set("vertexCount", static_cast<unsigned>(mesh.positions.size()));
  info.set("triangleCount", static_cast<unsigned>(mesh.indices.size() / 3));
  info.set("morphCount", static_cast<unsigned>(a->avatar.morphs.size()));
  info.set("anchorCount", static_cast<unsigned>(a->avatar.anchors.size()));
  val materials = val::array();
  for (std::size_t i = 0; i < mesh.materials.size(); ++i) {
    const auto& m = mesh.materials[i];
    val mat = val::object();
    mat.set("name", m.name);
    val colour = val::array();
    for (int k = 0; k < 4; ++k) colour.set(k, m.base_color[k]);
    mat.set("baseColor", colour);
    mat.set("roughness", m.roughness);
    mat.set("metallic", m.metallic);
    materials.set(static_cast<unsigned>(i), mat);
  }
  info.set("materials", materials);
  val primitives = val::array();
  for (std::size_t i = 0; i < mesh.primitives.size(); ++i) {
    val p = val::object();
    p.set("firstIndex", mesh.primitives[i].first_index);
    p.set("indexCount", mesh.primitives[i].index_count);
    p.set("material", mesh.primitives[i].material);
    primitives.set(static_cast<unsigned>(i), p);
  }
  info.set("primitives", primitives);
  return info;
}

val avatar_joint_names(int id) {
  LoadedAvatar* a = find(id);
  if (!a) return val::null();
  std::vector<std::string> names;
  for (const auto& j : a->avatar.skeleton.joints) names.push_back(j.name);
  return strings(names);
}

// Skeleton index of a canonical joint ("leftHand"), or of any alias; -1 if absent.
int avatar_canonical_joint(int id, const std::string& name) {
  LoadedAvatar* a = find(id);
  const int canonical = sw::skeleton::canonical_joint_id(name);
  if (!a || canonical < 0) return -1;
  return a->avatar.canonical_to_joint[static_cast<std::size_t>(canonical)];
}

val avatar_morph_names(int id) {
  LoadedAvatar* a = find(id);
  if (!a) return val::null();
  std::vector<std::string> names;
  for (const auto& m : a->avatar.morphs) names.push_back(m.name);
  return strings(names);
}

val avatar_anchor_names(int id) {
  LoadedAvatar* a = find(id);
  if (!a) return val::null();
  std::vector<std::string> names;
  for (const auto& anchor : a->avatar.anchors) names.push_back(anchor.name);
  return strings(names);
}

template <typename T>
val float_view(const std::vector<T>& v, std::size_t floats_per_item) {
  return val(typed_memory_view(v.size() * floats_per_item, reinterpret_cast<const float*>(v.data())));
}

val empty_view() { return val(typed_memory_view(0, static_cast<const float*>(nullptr))); }

val avatar_indices(int id) {
  LoadedAvatar* a = find(id);
  if (!a) return empty_view();
  return val(typed_memory_view(a->avatar.mesh.indices.size(), a->avatar.mesh.indices.data()));
}
val avatar_joint_parents(int id) {
  LoadedAvatar* a = find(id);
  if (!a) return empty_view();
  return val(typed_memory_view(a->parents.size(), a->parents.data()));
}
val avatar_rest_positions(int id) { LoadedAvatar* a = find(id); return a ? float_view(a->avatar.mesh.positions, 3) : empty_view(); }
val avatar_rest_normals(int id) { LoadedAvatar* a = find(id); return a ? float_view(a->avatar.mesh.normals, 3) : empty_view(); }
val avatar_weights(int id) { LoadedAvatar* a = find(id); return a ? float_view(a->avatar.mesh.weights, 4) : empty_view(); }
val avatar_skin_joints(int id) {
  LoadedAvatar* a = find(id);
  if (!a) return empty_view();
  const auto& j = a->avatar.mesh.joints;
  return val(typed_memory_view(j.size() * 4, reinterpret_cast<const std::uint16_t*>(j.data())));
}
val avatar_inverse_binds(int id) { LoadedAvatar* a = find(id); return a ? float_view(a->avatar.inverse_bind, 16) : empty_view(); }
val avatar_locals(int id) { LoadedAvatar* a = find(id); return a ? float_view(a->instance->locals(), 10) : empty_view(); }
val avatar_morph_weights(int id) { LoadedAvatar* a = find(id); return a ? float_view(a->instance->morph_weights(), 1) : empty_view(); }
val avatar_skinned_positions(int id) { LoadedAvatar* a = find(id); return a ? float_view(a->instance->positions(), 1) : empty_view(); }
val avatar_skinned_normals(int id) { LoadedAvatar* a = find(id); return a ? float_view(a->instance->normals(), 1) : empty_view(); }
val avatar_joint_matrices(int id) { LoadedAvatar* a = find(id); return a ? float_view(a->instance->model_matrices(), 16) : empty_view(); }
val avatar_anchor_positions(int id) { LoadedAvatar* a = find(id); return a ? float_view(a->instance->anchor_positions(), 1) : empty_view(); }
val avatar_anchor_normals(int id) { LoadedAvatar* a = find(id); return a ? float_view(a->instance->anchor_normals(), 1) : empty_view(); }

void avatar_reset_pose(int id) {
  if (LoadedAvatar* a = find(id)) a->instance->reset_pose();
}

// foundation's deterministic pose (skeleton/synthetic_humanoid.h) on this avatar's skeleton: the
// parity cases pose the avatar identically natively and in WASM without shipping 10 floats a joint.
bool avatar_set_synthetic_pose(int id, unsigned seed, float max_angle_rad) {
  LoadedAvatar* a = find(id);
  if (!a) return false;
  const auto pose = sw::skeleton::make_synthetic_pose(a->avatar.skeleton, seed, max_angle_rad);
  std::copy(pose.begin(), pose.end(), a->instance->locals().begin());
  return true;
}

sw::skinning::SkinningPath path_of(bool simd) {
  return simd ? sw::skinning::SkinningPath::Simd : sw::skinning::SkinningPath::Scalar;
}

bool avatar_update(int id, bool simd) {
  LoadedAvatar* a = find(id);
  return a && a->instance->update(path_of(simd));
}

std::string avatar_error(int id) {
  LoadedAvatar* a = find(id);
  return a ? a->instance->error() : "no avatar with id " + std::to_string(id);
}

// Benchmark helpers: the loop stays in WASM so the figure is the work, not the JS->WASM call.
bool avatar_update_repeatedly(int id, bool simd, int count) {
  LoadedAvatar* a = find(id);
  if (!a) return false;
  bool ok = true;
  for (int i = 0; i < count; ++i) ok = a->instance->update(path_of(simd)) && ok;
  return ok;
}

// LBS only (positions + normals), on the instance's current palette. all_four: every vertex
// blends 4 matrices (weights 0.4/0.3/0.2/0.1), the worst case, whatever the model's weights.
bool avatar_skin_repeatedly(int id, bool simd, int count, bool all_four) {
  LoadedAvatar* a = find(id);
  if (!a) return false;
  static std::vector<glm::vec4> four_weights;
  if (all_four) four_weights.assign(a->avatar.mesh.weights.size(), glm::vec4(0.4f, 0.3f, 0.2f, 0.1f));
  auto& inst = *a->instance;
  const auto& mesh = a->avatar.mesh;
  sw::skinning::SkinningJob job;
  job.vertex_count = static_cast<int>(mesh.positions.size());
  job.skinning_matrices = inst.skinning_matrices().data();
  job.joint_count = static_cast<int>(inst.skinning_matrices().size());
  job.in_positions = mesh.positions.data();
  job.in_normals = mesh.normals.data();
  job.joints = mesh.joints.data();
  job.weights = all_four ? four_weights.data() : mesh.weights.data();
  job.out_positions = const_cast<float*>(inst.positions().data());
  job.out_normals = const_cast<float*>(inst.normals().data());
  job.path = path_of(simd);
  bool ok = true;
  for (int i = 0; i < count; ++i) ok = job.run() && ok;
  return ok;
}

bool avatar_simd_available() { return sw::skinning::simd_available(); }

}  // namespace

EMSCRIPTEN_BINDINGS(avatar_api) {
  emscripten::function("avatarLoad", &avatar_load);
  emscripten::function("avatarLoadSynthetic", &avatar_load_synthetic);
  emscripten::function("avatarFree", &avatar_free);
  emscripten::function("avatarInfo", &avatar_info);
  emscripten::function("avatarJointNames", &avatar_joint_names);
  emscripten::function("avatarJointParents", &avatar_joint_parents);
  emscripten::function("avatarCanonicalJoint", &avatar_canonical_joint);
  emscripten::function("avatarMorphNames", &avatar_morph_names);
  emscripten::function("avatarAnchorNames", &avatar_anchor_names);
  emscripten::function("avatarIndices", &avatar_indices);
  emscripten::function("avatarRestPositions", &avatar_rest_positions);
  emscripten::function("avatarRestNormals", &avatar_rest_normals);
  emscripten::function("avatarSkinJoints", &avatar_skin_joints);
  emscripten::function("avatarWeights", &avatar_weights);
  emscripten::function("avatarInverseBinds", &avatar_inverse_binds);
  emscripten::function("avatarLocals", &avatar_locals);
  emscripten::function("avatarMorphWeights", &avatar_morph_weights);
  emscripten::function("avatarResetPose", &avatar_reset_pose);
  emscripten::function("avatarSetSyntheticPose", &avatar_set_synthetic_pose);
  emscripten::function("avatarUpdate", &avatar_update);
  emscripten::function("avatarError", &avatar_error);
  emscripten::function("avatarSkinnedPositions", &avatar_skinned_positions);
  emscripten::function("avatarSkinnedNormals", &avatar_skinned_normals);
  emscripten::function("avatarJointMatrices", &avatar_joint_matrices);
  emscripten::function("avatarAnchorPositions", &avatar_anchor_positions);
  emscripten::function("avatarAnchorNormals", &avatar_anchor_normals);
  emscripten::function("avatarUpdateRepeatedly", &avatar_update_repeatedly);
  emscripten::function("avatarSkinRepeatedly", &avatar_skin_repeatedly);
  emscripten::function("avatarSimdAvailable", &avatar_simd_available);
}
