// `signweave pack-avatar IN.glb OUT.swavatar`: loads a glTF avatar as the core does (loader, body
// anchors, rig check) and writes it as an avatar pack (avatar/avatar_pack.h), which the page loads
// by copying arrays instead of parsing glTF on its main thread. ./signweave build runs it for
// models/signweave-avatar.glb into web/gen/.
//
// Checks its own output: the written bytes are unpacked again and must give the avatar it packed.
// Exit 0 written, 1 the avatar did not load or the file could not be written, 2 usage.
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <string>
#include <vector>

#include "avatar/avatar_pack.h"
#include "command.h"
#include "synthesis/signing_avatar.h"

namespace sw::cli {
namespace {

int pack_avatar_command(const std::vector<std::string>& args) {
  if (args.size() != 2) {
    std::fprintf(stderr, "usage: signweave pack-avatar IN.glb OUT.swavatar\n");
    return 2;
  }
  sw::synthesis::SigningAvatar loaded = sw::synthesis::load_signing_avatar_file(args[0]);
  if (!loaded.ok()) {
    std::fprintf(stderr, "pack-avatar: %s: %s\n", args[0].c_str(), loaded.error.c_str());
    return 1;
  }
  for (const std::string& w : loaded.warnings) std::fprintf(stderr, "pack-avatar: warning: %s\n", w.c_str());
  const std::vector<std::uint8_t> bytes = sw::avatar::pack_avatar(loaded.avatar);
  const sw::avatar::UnpackResult check = sw::avatar::unpack_avatar(bytes.data(), bytes.size());
  if (!check.ok() || sw::avatar::pack_avatar(check.avatar) != bytes) {
    std::fprintf(stderr, "pack-avatar: the pack does not read back as written: %s\n",
                 check.ok() ? "different bytes" : check.error.c_str());
    return 1;
  }
  // Written beside, then renamed: a reader (the server) never sees half a file.
  const std::string partial = args[1] + ".partial";
  {
    std::ofstream out(partial, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
    if (!out) {
      std::fprintf(stderr, "pack-avatar: cannot write %s\n", partial.c_str());
      return 1;
    }
  }
  if (std::rename(partial.c_str(), args[1].c_str()) != 0) {
    std::fprintf(stderr, "pack-avatar: cannot rename %s to %s: %s\n", partial.c_str(), args[1].c_str(), std::strerror(errno));
    return 1;
  }
  std::printf("pack-avatar: %s -> %s (%zu bytes: %d joints, %zu vertices, %zu morphs, %zu anchors)\n", args[0].c_str(),
              args[1].c_str(), bytes.size(), loaded.avatar.skeleton.joint_count(), loaded.avatar.mesh.positions.size(),
              loaded.avatar.morphs.size(), loaded.avatar.anchors.size());
  return 0;
}

}  // namespace

SW_CLI_COMMAND("pack-avatar", "pack-avatar IN.glb OUT.swavatar   the avatar as a pack the page loads without glTF parsing",
               pack_avatar_command);

}  // namespace sw::cli
