// avatar-generator: builds models/signweave-avatar.glb from nothing but the code in this folder.
//
//   ./build/native/avatar-generator models/signweave-avatar.glb [--cell-mm 1.5]
//
// BIND POSE CONVENTION (see humanoid_layout.h, models/README.md): every joint's rest local
// rotation is identity; T-pose, arms along ±X (left hand at +X), palms down (-Y), thumbs +Z,
// facing +Z, feet on y = 0, metres. Deterministic: the same build writes the same bytes.
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>

#include "avatar_mesh.h"
#include "face_morphs.h"
#include "face_regions.h"
#include "gltf_export.h"
#include "humanoid_layout.h"
#include "implicit_body.h"
#include "skin_weights.h"

namespace sw::avatar_generator {
namespace {

int usage() {
  std::fprintf(stderr, "usage: avatar-generator OUTPUT.glb [--cell-mm MILLIMETRES]\n");
  return 2;
}

SkinWeights rigid_weights(const MeshPiece& piece) {
  SkinWeights skin;
  skin.joints.assign(piece.positions.size(),
                     {static_cast<std::uint16_t>(piece.rigid_joint), 0, 0, 0});
  skin.weights.assign(piece.positions.size(), glm::vec4(1, 0, 0, 0));
  return skin;
}

int run(int argc, char** argv) {
  if (argc < 2) return usage();
  std::string output = argv[1];
  AvatarMeshSettings settings;
  for (int i = 2; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--cell-mm" && i + 1 < argc) {
      char* end = nullptr;
      const double mm = std::strtod(argv[++i], &end);
      if (end == argv[i] || *end != '\0' || !(mm >= 0.5 && mm <= 20.0)) {
        std::fprintf(stderr, "--cell-mm wants a number of millimetres in [0.5, 20], got '%s'\n",
                     argv[i]);
        return 2;
      }
      settings.cell_m = static_cast<float>(mm / 1000.0);
    } else {
      std::fprintf(stderr, "unknown argument '%s'\n", arg.c_str());
      return usage();
    }
  }

  const auto start = std::chrono::steady_clock::now();
  const HumanoidLayout layout = make_signweave_layout();
  const ImplicitBody body(layout);
  AvatarMeshStats stats;
  const std::vector<MeshPiece> pieces = build_avatar_mesh(body, layout, settings, &stats);

  ExportModel model;
  model.layout = &layout;
  model.morph_names = face_morph_names();
  std::size_t vertices = 0, triangles = 0, face_vertices = 0;
  for (const MeshPiece& piece : pieces) {
    ExportPiece ep;
    ep.piece = &piece;
    ep.skin = piece.rigid_joint >= 0
                  ? rigid_weights(piece)
                  : compute_skin_weights(layout, body, piece.positions, piece.nearest_primitive,
                                         piece.indices, &jaw_mask);
    if (piece.face) {
      for (size_t channel = 0; channel < model.morph_names.size(); ++channel) {
        MorphTargetData target;
        target.position_deltas.reserve(piece.positions.size());
        for (const glm::vec3& p : piece.positions)
          target.position_deltas.push_back(
              face_morph_delta(layout, static_cast<int>(channel), p, piece.material));
        ep.morphs.push_back(std::move(target));
      }
    }
    vertices += piece.positions.size();
    triangles += piece.indices.size() / 3;
    if (piece.face) face_vertices += piece.positions.size();
    (piece.face ? model.face_pieces : model.body_pieces).push_back(std::move(ep));
  }
  GlbBuilder glb;
  export_avatar(model, glb);
  std::string error;
  if (!glb.write(output, &error)) {
    std::fprintf(stderr, "avatar-generator: %s\n", error.c_str());
    return 1;
  }
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf(
      "wrote %s: %zu bytes, %zu joints, %zu vertices (%zu in the face mesh), %zu triangles "
      "(polygonised %zu, body simplified to %zu), %zu morph targets, %.1f s\n",
      output.c_str(), glb.serialise().size(), layout.joints.size(), vertices, face_vertices,
      triangles, stats.raw_triangles, stats.body_triangles, model.morph_names.size(), seconds);
  return 0;
}

}  // namespace
}  // namespace sw::avatar_generator

int main(int argc, char** argv) {
  try {
    return sw::avatar_generator::run(argc, argv);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "avatar-generator: %s\n", e.what());
    return 1;
  }
}
