// glTF export: turns the layout, the mesh pieces, their skin weights and morphs into the GLB
// document — joint nodes (identity rotations, translations only: the bind-pose convention of
// humanoid_layout.h), one skin with inverse bind matrices, the meshes with PBR materials, and the
// VRMC_vrm 1.0 humanoid mapping.
#pragma once

#include <string>
#include <vector>

#include "avatar_mesh.h"
#include "glb_writer.h"
#include "humanoid_layout.h"
#include "skin_weights.h"

namespace sw::avatar_generator {

struct MorphTargetData {                   // one morph target of one piece
  std::vector<glm::vec3> position_deltas;  // one per vertex of the piece
};

struct ExportPiece {
  const MeshPiece* piece = nullptr;
  SkinWeights skin;
  std::vector<MorphTargetData> morphs;  // empty, or one per name in ExportModel::morph_names
};

struct ExportModel {
  const HumanoidLayout* layout = nullptr;
  std::vector<ExportPiece> body_pieces;  // mesh "body": no morph targets
  std::vector<ExportPiece> face_pieces;  // mesh "face": every piece has all morph targets
  std::vector<std::string> morph_names;
};

// Builds the glTF document into `glb`. Deterministic.
void export_avatar(const ExportModel& model, GlbBuilder& glb);

}  // namespace sw::avatar_generator
