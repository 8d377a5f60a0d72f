// Where the project's files (models/, data/) are, for commands run from anywhere.
#pragma once

#include <string>

namespace sw::cli {

// $SIGNWEAVE_ROOT, else the nearest directory above the binary holding
// models/signweave-avatar.glb (the binary lives in build/native/), else ".".
std::string project_root();

}  // namespace sw::cli
