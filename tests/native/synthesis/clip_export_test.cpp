// Clip sampling and export: slerp between frames, BVH that the BVH reader reads back to the same
// rotations, GLB that the glTF loader reads back with the skeleton and a valid animation.
#include "synthesis/clip_export.h"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <cstring>

#include "avatar/gltf_loader.h"
#include "skeleton/bvh.h"
#include "synthesis/clip_sampler.h"
#include "synthesis/phrase_text.h"
#include "synthesis/synthesize.h"
#include "synthesis_fixture.h"

namespace sw::synthesis {
namespace {

using namespace testing;

SynthesisResult sample_sign(const avatar::Avatar& av) {
  notation::SignSpec s = sign_at(index_point(), notation::BodyLevel::Chin, notation::Side::Centre,
                                 notation::Contact::Touch);
  return synthesize_sign(s, av);
}

TEST(SynthesisClip, SamplerHitsFramesAndSlerpsBetweenThem) {
  avatar::Avatar av = make_reference_humanoid();
  SynthesisResult r = sample_sign(av);
  ASSERT_TRUE(r.ok());
  const Clip& c = r.clip;
  const int J = c.joint_count();
  std::vector<glm::quat> q(J), mid(J);
  sample_clip(c, 5.0 / c.fps, q.data(), nullptr, nullptr);
  for (int j = 0; j < J; ++j) EXPECT_LT(rotation_angle(glm::conjugate(q[j]) * c.rotations[5 * J + j]), 1e-4f);
  sample_clip(c, 5.5 / c.fps, mid.data(), nullptr, nullptr);
  for (int j = 0; j < J; ++j) {
    float a = rotation_angle(glm::conjugate(c.rotations[5 * J + j]) * mid[j]);
    float b = rotation_angle(glm::conjugate(mid[j]) * c.rotations[6 * J + j]);
    float ab = rotation_angle(glm::conjugate(c.rotations[5 * J + j]) * c.rotations[6 * J + j]);
    EXPECT_NEAR(a, 0.5f * ab, 1e-3f);
    EXPECT_NEAR(b, 0.5f * ab, 1e-3f);
  }
  // Clamped outside the clip.
  sample_clip(c, -3.0, q.data(), nullptr, nullptr);
  EXPECT_LT(rotation_angle(glm::conjugate(q[0]) * c.rotations[0]), 1e-4f);
  std::vector<math::Transform> local(J);
  EXPECT_TRUE(sample_clip_local(c, av.skeleton, 0.3, local.data()));
  EXPECT_FALSE(sample_clip_local(c, skeleton::Skeleton{}, 0.3, local.data()));
}

TEST(SynthesisClip, BvhRoundTripsTheRotations) {
  avatar::Avatar av = make_rotated_variant(1.0f);  // non-identity rest rotations
  SynthesisResult r = sample_sign(av);
  ASSERT_TRUE(r.ok());
  ExportResult e = export_bvh(r.clip, av);
  ASSERT_TRUE(e.ok()) << e.error;
  std::string text(e.bytes.begin(), e.bytes.end());
  skeleton::BvhReadResult back = skeleton::read_bvh(text);
  ASSERT_TRUE(back.ok) << back.error.format();
  ASSERT_EQ(back.bvh.frame_count, r.clip.frame_count);
  const int J = r.clip.joint_count();
  std::vector<math::Transform> local(J);
  for (int f : {0, r.clip.frame_count / 2, r.clip.frame_count - 1}) {
    ASSERT_TRUE(skeleton::frame_to_local(back.bvh, f, 0.01, local));
    for (int j = 0; j < J; ++j) {
      int b = back.bvh.find(r.clip.joint_names[j]);  // the writer orders joints depth-first
      ASSERT_GE(b, 0) << r.clip.joint_names[j];
      EXPECT_LT(rotation_angle(glm::conjugate(local[b].rotation) * r.clip.rotations[static_cast<size_t>(f) * J + j]), 1e-3f)
          << "frame " << f << " joint " << j;
    }
    EXPECT_NEAR(glm::length(local[back.bvh.find(r.clip.joint_names[0])].translation - r.clip.root_translation[f]), 0.0f, 1e-4f);
  }
}

TEST(SynthesisClip, GlbIsAValidGltfWithSkeletonAndAnimation) {
  avatar::Avatar av = make_reference_humanoid();
  SynthesisResult r = sample_sign(av);
  ASSERT_TRUE(r.ok());
  ExportResult e = export_glb(r.clip, av);
  ASSERT_TRUE(e.ok()) << e.error;
  ASSERT_GT(e.bytes.size(), 20u);
  EXPECT_EQ(std::string(e.bytes.begin(), e.bytes.begin() + 4), "glTF");
  std::uint32_t total = e.bytes[8] | (e.bytes[9] << 8) | (e.bytes[10] << 16) | (e.bytes[11] << 24);
  EXPECT_EQ(total, e.bytes.size());
  std::uint32_t json_len = e.bytes[12] | (e.bytes[13] << 8) | (e.bytes[14] << 16) | (e.bytes[15] << 24);
  nlohmann::json j = nlohmann::json::parse(std::string(e.bytes.begin() + 20, e.bytes.begin() + 20 + json_len));
  EXPECT_EQ(j["nodes"].size(), av.skeleton.joints.size());
  ASSERT_EQ(j["animations"].size(), 1u);
  EXPECT_EQ(j["animations"][0]["channels"].size(), av.skeleton.joints.size() + 1);
  const auto& time_acc = j["accessors"][j["animations"][0]["samplers"][0]["input"].get<int>()];
  EXPECT_NEAR(time_acc["max"][0].get<double>(), r.clip.duration_s(), 1e-4);
  // The project's loader reads it back with the same skeleton (no mesh: the reference has none).
  avatar::LoadResult back = avatar::load_avatar(e.bytes.data(), e.bytes.size());
  if (back.ok()) {
    EXPECT_EQ(back.avatar.skeleton.joint_count(), av.skeleton.joint_count());
  }
}

// The GLB carries the face: the avatar's morph targets (sparse, read back exactly) and the clip's
// morph weights as a "weights" channel on the mesh node. Before, the export dropped both, so a
// downloaded clip signed with a frozen face.
TEST(SynthesisClip, GlbCarriesTheFaceMorphTargetsAndTheirWeights) {
  ProjectAvatar project = load_project_avatar();
  if (!project.present) GTEST_SKIP() << "models/signweave-avatar.glb is not in this checkout";
  ASSERT_TRUE(project.error.empty()) << project.error;
  const avatar::Avatar& av = project.avatar;
  ASSERT_FALSE(av.morphs.empty());
  Synthesizer synth(av);
  ASSERT_TRUE(synth.ok()) << synth.error();
  PhraseText t = phrase_from_text("R(H(flat), Loc(chin, centre, touch), M(straight, o)) N(mouth=\"thank you\", expression=happy:0.8)", {});
  ASSERT_TRUE(t.ok());
  SynthesisResult r = synth.phrase(t.items, {});
  ASSERT_TRUE(r.ok());
  ASSERT_GT(r.clip.morph_count(), 0);
  ExportResult e = export_glb(r.clip, av);
  ASSERT_TRUE(e.ok()) << e.error;
  auto u32 = [&](size_t at) {
    return static_cast<std::uint32_t>(e.bytes[at] | (e.bytes[at + 1] << 8) | (e.bytes[at + 2] << 16) | (e.bytes[at + 3] << 24));
  };
  const std::uint32_t json_len = u32(12);
  const nlohmann::json j = nlohmann::json::parse(std::string(e.bytes.begin() + 20, e.bytes.begin() + 20 + json_len));
  const std::uint8_t* bin = e.bytes.data() + 20 + json_len + 8;
  auto view_data = [&](int view) { return bin + j["bufferViews"][view].value("byteOffset", 0); };
  // Targets: one per morph, named, on every primitive.
  const auto& mesh = j["meshes"][0];
  ASSERT_EQ(mesh["extras"]["targetNames"].size(), av.morphs.size());
  for (const auto& p : mesh["primitives"]) ASSERT_EQ(p["targets"].size(), av.morphs.size());
  // A sparse POSITION target reads back to the avatar's dense deltas exactly.
  size_t moved = 0;
  for (size_t m = 0; m < av.morphs.size(); ++m) {
    EXPECT_EQ(mesh["extras"]["targetNames"][m], av.morphs[m].name);
    const auto& acc = j["accessors"][mesh["primitives"][0]["targets"][m]["POSITION"].get<int>()];
    std::vector<glm::vec3> dense(av.mesh.positions.size(), glm::vec3(0.0f));
    if (acc.contains("sparse")) {
      const size_t n = acc["sparse"]["count"];
      const std::uint8_t* idx = view_data(acc["sparse"]["indices"]["bufferView"]);
      const std::uint8_t* val = view_data(acc["sparse"]["values"]["bufferView"]);
      for (size_t k = 0; k < n; ++k) {
        std::uint32_t v;
        std::memcpy(&v, idx + 4 * k, 4);
        ASSERT_LT(v, dense.size());
        std::memcpy(&dense[v], val + 12 * k, 12);
      }
      moved += n;
    }
    EXPECT_EQ(dense, av.morphs[m].position_deltas) << av.morphs[m].name;
  }
  EXPECT_GT(moved, 0u);
  // The weights channel: on the mesh node, frame-major, the clip's weights matched by name.
  const auto& anim = j["animations"][0];
  const nlohmann::json* weights = nullptr;
  for (const auto& c : anim["channels"])
    if (c["target"]["path"] == "weights") weights = &c;
  ASSERT_NE(weights, nullptr);
  EXPECT_EQ((*weights)["target"]["node"].get<size_t>(), av.skeleton.joints.size());
  const auto& out = j["accessors"][anim["samplers"][(*weights)["sampler"].get<int>()]["output"].get<int>()];
  const size_t M = av.morphs.size();
  ASSERT_EQ(out["count"].get<size_t>(), static_cast<size_t>(r.clip.frame_count) * M);
  const std::uint8_t* wdata = view_data(out["bufferView"]);
  float driven = 0.0f;
  for (int f = 0; f < r.clip.frame_count; f += 7) {
    for (int c = 0; c < r.clip.morph_count(); ++c) {
      for (size_t m = 0; m < M; ++m) {
        if (av.morphs[m].name != r.clip.morph_names[c]) continue;
        float got;
        std::memcpy(&got, wdata + 4 * (static_cast<size_t>(f) * M + m), 4);
        const float want = r.clip.morph_weights[static_cast<size_t>(f) * r.clip.morph_count() + c];
        EXPECT_EQ(got, want) << r.clip.morph_names[c] << " frame " << f;
        driven = std::max(driven, want);
      }
    }
  }
  EXPECT_GT(driven, 0.1f);  // the mouthing and the smile really move the face
  // Sparse keeps the download small: the dense targets alone would be ~17 MB.
  EXPECT_LT(e.bytes.size(), 6u * 1024 * 1024);
  RecordProperty("glb_bytes", std::to_string(e.bytes.size()));
}

TEST(SynthesisClip, ExportRejectsAClipOfAnotherSkeleton) {
  avatar::Avatar av = make_reference_humanoid();
  SynthesisResult r = sample_sign(av);
  ASSERT_TRUE(r.ok());
  r.clip.joint_names[3] = "somethingElse";
  EXPECT_FALSE(export_bvh(r.clip, av).ok());
  EXPECT_FALSE(export_glb(r.clip, av).ok());
  Clip empty;
  EXPECT_NE(export_glb(empty, av).error, "");
}

}  // namespace
}  // namespace sw::synthesis
