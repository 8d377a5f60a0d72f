// Tests for avatar/avatar_pack.h: the round trip is exact (the synthetic humanoid with its morphs
// and anchors, and the project's avatar), a signing avatar loads the same from a pack as from its
// glTF, and damaged packs give errors naming what was wrong, never a crash (the ASan+UBSan run of
// this suite checks "never an out-of-bounds read").
#include "avatar/avatar_pack.h"

#include <algorithm>
#include <cstring>
#include <fstream>
#include <iterator>
#include <random>

#include <gtest/gtest.h>

#include "avatar/body_anchors.h"
#include "avatar/gltf_loader.h"
#include "avatar/synthetic_avatar.h"
#include "synthesis/signing_avatar.h"

namespace sw::avatar {
namespace {

template <typename T>
bool same_bytes(const std::vector<T>& a, const std::vector<T>& b) {
  return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0);
}

// Field by field, bit for bit (floats compared as bytes: -0.0 and NaN patterns count).
void expect_identical(const Avatar& a, const Avatar& b) {
  ASSERT_EQ(a.skeleton.joints.size(), b.skeleton.joints.size());
  for (std::size_t j = 0; j < a.skeleton.joints.size(); ++j) {
    const skeleton::Joint& x = a.skeleton.joints[j];
    const skeleton::Joint& y = b.skeleton.joints[j];
    EXPECT_EQ(x.name, y.name);
    EXPECT_EQ(x.parent, y.parent);
    EXPECT_EQ(std::memcmp(&x.rest.translation, &y.rest.translation, sizeof(glm::vec3)), 0) << x.name;
    EXPECT_EQ(std::memcmp(&x.rest.rotation, &y.rest.rotation, sizeof(glm::quat)), 0) << x.name;
    EXPECT_EQ(std::memcmp(&x.rest.scale, &y.rest.scale, sizeof(glm::vec3)), 0) << x.name;
  }
  EXPECT_TRUE(same_bytes(a.inverse_bind, b.inverse_bind));
  EXPECT_EQ(a.canonical_to_joint, b.canonical_to_joint);
  EXPECT_TRUE(same_bytes(a.mesh.positions, b.mesh.positions));
  EXPECT_TRUE(same_bytes(a.mesh.normals, b.mesh.normals));
  EXPECT_TRUE(same_bytes(a.mesh.joints, b.mesh.joints));
  EXPECT_TRUE(same_bytes(a.mesh.weights, b.mesh.weights));
  EXPECT_EQ(a.mesh.indices, b.mesh.indices);
  ASSERT_EQ(a.mesh.primitives.size(), b.mesh.primitives.size());
  for (std::size_t i = 0; i < a.mesh.primitives.size(); ++i) {
    EXPECT_EQ(a.mesh.primitives[i].first_index, b.mesh.primitives[i].first_index);
    EXPECT_EQ(a.mesh.primitives[i].index_count, b.mesh.primitives[i].index_count);
    EXPECT_EQ(a.mesh.primitives[i].material, b.mesh.primitives[i].material);
  }
  ASSERT_EQ(a.mesh.materials.size(), b.mesh.materials.size());
  for (std::size_t i = 0; i < a.mesh.materials.size(); ++i) {
    EXPECT_EQ(a.mesh.materials[i].name, b.mesh.materials[i].name);
    EXPECT_EQ(a.mesh.materials[i].base_color, b.mesh.materials[i].base_color);
    EXPECT_EQ(a.mesh.materials[i].roughness, b.mesh.materials[i].roughness);
    EXPECT_EQ(a.mesh.materials[i].metallic, b.mesh.materials[i].metallic);
  }
  ASSERT_EQ(a.morphs.size(), b.morphs.size());
  for (std::size_t i = 0; i < a.morphs.size(); ++i) {
    EXPECT_EQ(a.morphs[i].name, b.morphs[i].name);
    EXPECT_TRUE(same_bytes(a.morphs[i].position_deltas, b.morphs[i].position_deltas)) << a.morphs[i].name;
    EXPECT_TRUE(same_bytes(a.morphs[i].normal_deltas, b.morphs[i].normal_deltas)) << a.morphs[i].name;
  }
  ASSERT_EQ(a.anchors.size(), b.anchors.size());
  for (std::size_t i = 0; i < a.anchors.size(); ++i) {
    EXPECT_EQ(a.anchors[i].name, b.anchors[i].name);
    EXPECT_EQ(a.anchors[i].joint, b.anchors[i].joint);
    EXPECT_EQ(std::memcmp(&a.anchors[i].offset, &b.anchors[i].offset, sizeof(glm::vec3)), 0) << a.anchors[i].name;
    EXPECT_EQ(std::memcmp(&a.anchors[i].normal, &b.anchors[i].normal, sizeof(glm::vec3)), 0) << a.anchors[i].name;
  }
}

Avatar synthetic_with_anchors() {
  const std::vector<std::uint8_t> glb = make_synthetic_avatar_glb();
  LoadResult r = load_avatar(glb.data(), glb.size());
  EXPECT_TRUE(r.ok()) << r.message();
  r.avatar.anchors = compute_body_anchors(r.avatar, nullptr);
  return std::move(r.avatar);
}

TEST(AvatarPack, RoundTripIsExactWithMorphsAndAnchors) {
  const Avatar a = synthetic_with_anchors();
  ASSERT_FALSE(a.morphs.empty());
  ASSERT_FALSE(a.anchors.empty());
  const std::vector<std::uint8_t> bytes = pack_avatar(a);
  EXPECT_TRUE(is_avatar_pack(bytes.data(), bytes.size()));
  const UnpackResult r = unpack_avatar(bytes.data(), bytes.size());
  ASSERT_TRUE(r.ok()) << r.error;
  expect_identical(a, r.avatar);
}

TEST(AvatarPack, MorphsAreStoredSparse) {
  // The synthetic humanoid's blink moves the eyelids only: a dense copy of its deltas would be
  // 12 bytes per vertex per morph; the pack must be much smaller than that.
  const Avatar a = synthetic_with_anchors();
  const std::size_t dense_morph_bytes = a.morphs.size() * a.mesh.positions.size() * 24;
  Avatar without = a;
  without.morphs.clear();
  const std::size_t morph_bytes = pack_avatar(a).size() - pack_avatar(without).size();
  EXPECT_LT(morph_bytes, dense_morph_bytes / 2);
}

TEST(AvatarPack, GltfIsNotAPack) {
  const std::vector<std::uint8_t> glb = make_synthetic_avatar_glb();
  EXPECT_FALSE(is_avatar_pack(glb.data(), glb.size()));
  const UnpackResult r = unpack_avatar(glb.data(), glb.size());
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.error.find("SWAVPACK"), std::string::npos) << r.error;
  EXPECT_FALSE(is_avatar_pack(nullptr, 0));
}

TEST(AvatarPack, SigningAvatarLoadsTheSameFromPackAndGltf) {
  const std::vector<std::uint8_t> glb = make_synthetic_avatar_glb();
  const synthesis::SigningAvatar from_gltf = synthesis::load_signing_avatar(glb.data(), glb.size());
  ASSERT_TRUE(from_gltf.ok()) << from_gltf.error;
  const std::vector<std::uint8_t> pack = pack_avatar(from_gltf.avatar);
  const synthesis::SigningAvatar from_pack = synthesis::load_signing_avatar(pack.data(), pack.size());
  ASSERT_TRUE(from_pack.ok()) << from_pack.error;
  expect_identical(from_gltf.avatar, from_pack.avatar);
}

// Each damage must be refused with a message naming the place.
TEST(AvatarPack, DamagedPacksGiveErrorsNamingWhere) {
  const std::vector<std::uint8_t> good = pack_avatar(synthetic_with_anchors());
  const auto error_of = [](std::vector<std::uint8_t> bytes) {
    const UnpackResult r = unpack_avatar(bytes.data(), bytes.size());
    return r.ok() ? std::string("(accepted)") : r.error;
  };
  {
    std::vector<std::uint8_t> b = good;
    b[8] = 99;   // version
    EXPECT_NE(error_of(b).find("version"), std::string::npos) << error_of(b);
  }
  {
    std::vector<std::uint8_t> b(good.begin(), good.begin() + static_cast<std::ptrdiff_t>(good.size() / 2));
    EXPECT_NE(error_of(b).find("truncated"), std::string::npos) << error_of(b);
  }
  {
    std::vector<std::uint8_t> b = good;
    b.push_back(0);
    EXPECT_NE(error_of(b).find("after the last section"), std::string::npos) << error_of(b);
  }
  {
    std::vector<std::uint8_t> b = good;
    const std::uint32_t huge = 0xFFFFFFF0u;   // joint count
    std::memcpy(b.data() + 12, &huge, 4);
    EXPECT_NE(error_of(b).find("joint count"), std::string::npos) << error_of(b);
  }
  {
    // An index past the vertices: find the mesh's first index through a fresh pack of a copy
    // whose first index is a marker value, then corrupt it in the real bytes.
    Avatar a = synthetic_with_anchors();
    const std::uint32_t marker = a.mesh.indices[0];
    a.mesh.indices[0] = 0x5A5A5A5Au;
    std::vector<std::uint8_t> b = pack_avatar(a);
    const std::uint8_t pattern[4] = {0x5A, 0x5A, 0x5A, 0x5A};
    const auto found = std::search(b.begin(), b.end(), std::begin(pattern), std::end(pattern));
    ASSERT_NE(found, b.end());
    EXPECT_NE(error_of(b).find("indices[0]"), std::string::npos) << error_of(b);
    std::memcpy(&*found, &marker, 4);
    EXPECT_EQ(error_of(b), "(accepted)");
  }
}

TEST(AvatarPack, SurvivesRandomByteCorruption) {
  const std::vector<std::uint8_t> good = pack_avatar(synthetic_with_anchors());
  std::mt19937 rng(20261122);
  std::uniform_int_distribution<std::size_t> where(0, good.size() - 1);
  std::uniform_int_distribution<int> value(0, 255);
  int refused = 0;
  for (int trial = 0; trial < 300; ++trial) {
    std::vector<std::uint8_t> b = good;
    for (int k = 0; k < 4; ++k) b[where(rng)] = static_cast<std::uint8_t>(value(rng));
    if (trial % 3 == 0) b.resize(where(rng));
    const UnpackResult r = unpack_avatar(b.data(), b.size());   // must return, whatever it says
    if (!r.ok()) {
      ++refused;
      EXPECT_EQ(r.error.rfind("avatar pack: ", 0), 0u) << r.error;
      EXPECT_TRUE(r.avatar.mesh.positions.empty());
    }
  }
  EXPECT_GT(refused, 100);   // every truncation at least
}

TEST(AvatarPack, ProjectAvatarRoundTripsAndIsSmallerThanDense) {
  const std::string path = std::string(SIGNWEAVE_SOURCE_DIR) + "/models/signweave-avatar.glb";
  if (!std::ifstream(path).good()) GTEST_SKIP() << "models/signweave-avatar.glb absent (generate it first)";
  const synthesis::SigningAvatar loaded = synthesis::load_signing_avatar_file(path);
  ASSERT_TRUE(loaded.ok()) << loaded.error;
  const std::vector<std::uint8_t> bytes = pack_avatar(loaded.avatar);
  const synthesis::SigningAvatar again = synthesis::load_signing_avatar(bytes.data(), bytes.size());
  ASSERT_TRUE(again.ok()) << again.error;
  expect_identical(loaded.avatar, again.avatar);
  // The page downloads it (gzipped) instead of the .glb: it must not be larger than the glTF.
  std::ifstream in(path, std::ios::binary | std::ios::ate);
  EXPECT_LT(bytes.size(), static_cast<std::size_t>(in.tellg()) * 11 / 10);
}

}  // namespace
}  // namespace sw::avatar
