// Clip export to BVH and glTF binary: see clip_export.h.
#include "playback/clip_export.h"

#include <algorithm>
#include <cstring>

#include <nlohmann/json.hpp>

#include "playback/clip_sampling_job.h"

namespace sw::playback {

namespace {

// The clip's own frames, as local transforms (rest translations, clip rotations, root translation).
bool frame_locals(const synthesis::Clip& clip, const skeleton::Skeleton& skeleton, int frame,
                  std::vector<math::Transform>* locals, std::string* error) {
  ClipSamplingJob job;
  job.clip = &clip;
  job.skeleton = &skeleton;
  job.time_s = frame / double(clip.fps);
  job.output_locals = *locals;
  if (std::string why = job.validate(); !why.empty()) {
    *error = why;
    return false;
  }
  return job.run();
}

void append_floats(std::vector<std::uint8_t>* bin, const float* values, std::size_t count) {
  const std::size_t at = bin->size();
  bin->resize(at + count * sizeof(float));
  std::memcpy(bin->data() + at, values, count * sizeof(float));
}

}  // namespace

skeleton::Bvh clip_to_bvh(const synthesis::Clip& clip, const skeleton::Skeleton& skeleton, std::string* error) {
  error->clear();
  skeleton::Bvh bvh;
  for (const skeleton::Joint& joint : skeleton.joints) {
    skeleton::BvhJoint j;
    j.name = joint.name;
    j.parent = joint.parent;
    j.offset = glm::dvec3(joint.rest.translation) / kBvhUnitToMetres;
    using C = skeleton::BvhChannel;
    if (joint.parent < 0) j.channels = {C::Xposition, C::Yposition, C::Zposition};
    j.channels.insert(j.channels.end(), {C::Zrotation, C::Xrotation, C::Yrotation});
    bvh.joints.push_back(std::move(j));
  }
  bvh.frame_count = clip.frame_count;
  bvh.frame_time_s = clip.fps > 0.0f ? 1.0 / double(clip.fps) : 0.0;
  bvh.values.assign(std::size_t(bvh.frame_count) * std::size_t(bvh.channel_count()), 0.0);
  std::vector<math::Transform> locals(skeleton.joints.size());
  for (int f = 0; f < clip.frame_count; ++f) {
    if (!frame_locals(clip, skeleton, f, &locals, error) ||
        !skeleton::local_to_frame(locals, kBvhUnitToMetres, bvh, f)) {
      if (error->empty()) *error = "frame " + std::to_string(f) + " could not be converted";
      return {};
    }
  }
  return bvh;
}

std::vector<std::uint8_t> clip_to_glb(const synthesis::Clip& clip, const skeleton::Skeleton& skeleton,
                                      std::string* error) {
  using nlohmann::json;
  error->clear();
  const std::size_t joints = skeleton.joints.size();
  std::vector<math::Transform> locals(joints);
  if (clip.frame_count < 1) {
    *error = "the clip has no frames";
    return {};
  }
  const std::size_t frames = std::size_t(clip.frame_count);
  // Per joint: frames rotations; the root also gets its translation track.
  std::vector<float> times(frames), rotations(joints * frames * 4), root(frames * 3);
  for (std::size_t f = 0; f < frames; ++f) {
    if (!frame_locals(clip, skeleton, int(f), &locals, error)) return {};
    times[f] = float(double(f) / double(clip.fps));
    for (std::size_t j = 0; j < joints; ++j) {
      const glm::quat& q = locals[j].rotation;  // glTF order: x, y, z, w
      float* out = &rotations[(j * frames + f) * 4];
      out[0] = q.x; out[1] = q.y; out[2] = q.z; out[3] = q.w;
    }
    for (int k = 0; k < 3; ++k) root[f * 3 + std::size_t(k)] = locals.empty() ? 0.0f : locals[0].translation[k];
  }

  std::vector<std::uint8_t> bin;
  json buffer_views = json::array(), accessors = json::array();
  auto add_accessor = [&](const float* data, std::size_t count, int components, const char* type, bool with_bounds) {
    const std::size_t offset = bin.size();
    append_floats(&bin, data, count * std::size_t(components));
    buffer_views.push_back({{"buffer", 0}, {"byteOffset", offset}, {"byteLength", count * std::size_t(components) * 4}});
    json accessor{{"bufferView", buffer_views.size() - 1}, {"componentType", 5126}, {"count", count}, {"type", type}};
    if (with_bounds) {  // glTF 2.0 §3.6.2.5: animation input accessors must have min and max
      accessor["min"] = {count ? data[0] : 0.0f};
      accessor["max"] = {count ? data[count - 1] : 0.0f};
    }
    accessors.push_back(accessor);
    return int(accessors.size() - 1);
  };

  json nodes = json::array();
  std::vector<json> children(joints, json::array());
  for (std::size_t j = 0; j < joints; ++j) {
    const int parent = skeleton.joints[j].parent;
    if (parent >= 0) children[std::size_t(parent)].push_back(j);
  }
  json roots = json::array();
  for (std::size_t j = 0; j < joints; ++j) {
    const math::Transform& rest = skeleton.joints[j].rest;
    json node{{"name", skeleton.joints[j].name},
              {"translation", {rest.translation.x, rest.translation.y, rest.translation.z}},
              {"rotation", {rest.rotation.x, rest.rotation.y, rest.rotation.z, rest.rotation.w}}};
    if (!children[j].empty()) node["children"] = children[j];
    nodes.push_back(node);
    if (skeleton.joints[j].parent < 0) roots.push_back(j);
  }

  json samplers = json::array(), channels = json::array();
  if (frames > 0) {
    const int input = add_accessor(times.data(), frames, 1, "SCALAR", true);
    for (std::size_t j = 0; j < joints; ++j) {
      const int output = add_accessor(&rotations[j * frames * 4], frames, 4, "VEC4", false);
      samplers.push_back({{"input", input}, {"output", output}, {"interpolation", "LINEAR"}});
      channels.push_back({{"sampler", samplers.size() - 1}, {"target", {{"node", j}, {"path", "rotation"}}}});
    }
    if (joints > 0) {
      const int output = add_accessor(root.data(), frames, 3, "VEC3", false);
      samplers.push_back({{"input", input}, {"output", output}, {"interpolation", "LINEAR"}});
      channels.push_back({{"sampler", samplers.size() - 1}, {"target", {{"node", 0}, {"path", "translation"}}}});
    }
  }

  json gltf{{"asset", {{"version", "2.0"}, {"generator", "Signweave clip export"}}},
            {"scene", 0},
            {"scenes", json::array({{{"nodes", roots}}})},
            {"nodes", nodes},
            {"buffers", json::array({{{"byteLength", bin.size()}}})},
            {"bufferViews", buffer_views},
            {"accessors", accessors},
            {"animations", json::array({{{"name", "signweave"}, {"samplers", samplers}, {"channels", channels}}})}};
  std::string text = gltf.dump(-1, ' ', false, json::error_handler_t::replace);
  // GLB (glTF 2.0 §4.4): chunks 4-byte aligned, JSON padded with spaces, BIN with zeros.
  while (text.size() % 4) text += ' ';
  while (bin.size() % 4) bin.push_back(0);
  std::vector<std::uint8_t> glb;
  auto u32 = [&glb](std::uint32_t v) {
    for (int k = 0; k < 4; ++k) glb.push_back(std::uint8_t(v >> (8 * k)));
  };
  const std::uint32_t total = 12 + 8 + std::uint32_t(text.size()) + 8 + std::uint32_t(bin.size());
  u32(0x46546C67);  // "glTF"
  u32(2);
  u32(total);
  u32(std::uint32_t(text.size()));
  u32(0x4E4F534A);  // "JSON"
  glb.insert(glb.end(), text.begin(), text.end());
  u32(std::uint32_t(bin.size()));
  u32(0x004E4942);  // "BIN\0"
  glb.insert(glb.end(), bin.begin(), bin.end());
  return glb;
}

}  // namespace sw::playback
