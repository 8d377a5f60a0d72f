// Signing avatar: an avatar ready for synthesis — loaded from glTF bytes or a file by the avatar
// loader (or from an avatar pack, avatar/avatar_pack.h, told apart by its magic), with its body
// anchors computed (avatar/body_anchors.h) when the file carries none, and checked for the joints
// synthesis needs. The CLI, the WASM API and the server load through here.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "avatar/avatar.h"

namespace sw::synthesis {

struct SigningAvatar {
  avatar::Avatar avatar;
  std::string error;                  // empty on success
  std::vector<std::string> warnings;  // loader and anchor fallbacks
  bool ok() const { return error.empty(); }
};

SigningAvatar load_signing_avatar(const std::uint8_t* bytes, std::size_t size);
SigningAvatar load_signing_avatar_file(const std::string& path);
// Computes the anchors if missing and checks the rig; for avatars built in memory.
void prepare_signing_avatar(SigningAvatar* a);

}  // namespace sw::synthesis
