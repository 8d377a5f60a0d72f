// Signing avatar: load + anchors + rig check (signing_avatar.h).
#include "synthesis/signing_avatar.h"

#include "avatar/avatar_pack.h"
#include "avatar/body_anchors.h"
#include "avatar/gltf_loader.h"
#include "synthesis/rig.h"

namespace sw::synthesis {

void prepare_signing_avatar(SigningAvatar* a) {
  if (!a->ok()) return;
  if (a->avatar.anchors.empty()) a->avatar.anchors = avatar::compute_body_anchors(a->avatar, &a->warnings);
  Rig rig;
  std::string error;
  if (!build_rig(a->avatar, &rig, &error)) a->error = "avatar: " + error;
}

static SigningAvatar from_load(avatar::LoadResult&& r) {
  SigningAvatar a;
  a.error = r.error;
  a.warnings = std::move(r.warnings);
  a.avatar = std::move(r.avatar);
  prepare_signing_avatar(&a);
  return a;
}

SigningAvatar load_signing_avatar(const std::uint8_t* bytes, std::size_t size) {
  if (avatar::is_avatar_pack(bytes, size)) {
    // Packed at build time with its anchors (avatar/avatar_pack.h): only the rig is checked here.
    avatar::UnpackResult r = avatar::unpack_avatar(bytes, size);
    SigningAvatar a;
    a.error = std::move(r.error);
    a.avatar = std::move(r.avatar);
    prepare_signing_avatar(&a);
    return a;
  }
  return from_load(avatar::load_avatar(bytes, size));
}

SigningAvatar load_signing_avatar_file(const std::string& path) {
  return from_load(avatar::load_avatar_file(path));
}

}  // namespace sw::synthesis
