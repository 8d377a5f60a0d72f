#include "project_root.h"

#include <unistd.h>

#include <cstdlib>
#include <fstream>

namespace sw::cli {

std::string project_root() {
  if (const char* env = std::getenv("SIGNWEAVE_ROOT")) return env;
  char buf[4096];
  const ssize_t n = readlink("/proc/self/exe", buf, sizeof(buf) - 1);
  if (n > 0) {
    std::string dir(buf, static_cast<std::size_t>(n));
    for (int up = 0; up < 3; ++up) {
      const std::size_t slash = dir.rfind('/');
      if (slash == std::string::npos) break;
      dir = dir.substr(0, slash);
      if (std::ifstream(dir + "/models/signweave-avatar.glb").good()) return dir;
    }
  }
  return ".";
}

}  // namespace sw::cli
