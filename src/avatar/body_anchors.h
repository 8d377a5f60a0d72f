// Body anchors: the 3D points every location of the formal model resolves to (seed 004's levels ×
// sides, HamNoSys locations, places on the hands and arms), computed from the skeleton and the
// mesh of ANY loaded avatar — no per-model tables.
//
// Names (the contract synthesis consumes, brief "Body anchor names"):
//   body/<level>/<side>     level: above_head head_top head forehead eyebrows eyes nose ears cheeks
//                           mouth lips teeth tongue chin under_chin neck shoulders shoulder_top chest
//                           stomach belly waist below_waist; side: right_beside right centre left
//                           left_beside. On the skin, normal outward; `*_beside`, `above_head` off it;
//                           teeth/tongue just behind the lips (inside the mouth).
//   space/<side>            neutral signing space in front of the lower chest.
//   hand/<left|right>/<palm|back|thumb_side|little_side|wrist|wrist_back>
//   hand/<left|right>/<tip|pad|nail|base|middle_joint|side>/<thumb|index|middle|ring|little>
//   arm/<left|right>/<forearm|forearm_back|elbow|upper_arm>
//
// How (so any avatar works): a body frame from the skeleton (up = hips→head, left = right→left
// upper arm, forward = left × up: +Z for the glTF convention, -Z for VRM 0.x and still right);
// heights of the face from the head's measured top and the chin found on the face profile (rays
// cast forward at 2 mm steps: the chin is where the profile drops to the neck; the nose is its
// most forward point), with eye joints used when the rig has them; torso heights as fractions of
// the measured hip-to-shoulder span; points on the skin by casting rays from inside the body part
// against only that part's triangles; sides offset by fractions of the width measured at that
// level. Each anchor is stored relative to the joint it moves with (Anchor::offset is in that
// joint's bind space: world = model_matrix(joint) · offset).
//
// Does NOT: place contact-specific offsets (synthesis adds the hand's distance per Contact), or
// model clothing thickness (the surface is whatever the mesh is).
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "avatar/avatar.h"
#include "notation/sign_spec.h"

namespace sw::avatar {

// Computes every anchor (names above). Warnings list anchors that needed a fallback because a
// ray found no surface (e.g. open fingertip meshes); the anchors still exist.
std::vector<Anchor> compute_body_anchors(const Avatar& avatar, std::vector<std::string>* warnings = nullptr);

// Every anchor name compute_body_anchors produces, in its order.
std::vector<std::string> body_anchor_names();

// Index of the named anchor in avatar.anchors, -1 if absent.
int find_anchor(const Avatar& avatar, std::string_view name);

// Names from the formal model's enums (notation/sign_spec.h).
std::string body_anchor_name(notation::BodyLevel level, notation::Side side);  // NeutralSpace -> space/<side>
// place on the hand or arm of `left` (true: the signer's left hand); finger used for finger places.
std::string hand_anchor_name(bool left, notation::HandPlace place, notation::Finger finger = notation::Finger::Index);

}  // namespace sw::avatar
