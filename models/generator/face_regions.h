// Face regions: the masks that say which parts of the face move together, shared by the skin
// weights (the jaw joint) and the morph targets (face_morphs.h), so a jaw rotation and the jawOpen
// morph open the mouth along the same line.
#pragma once

#include <glm/glm.hpp>

namespace sw::avatar_generator {

// 1 below the lip line (lower lip, lower wall of the mouth slit), 0 above; a sharp step exactly
// at the lip line between the mouth corners (the slit separates the lips), widening beyond the
// corners and rising along the mandible towards the hinge.
float below_lip_line(glm::vec3 p);

// 1 on the chin, lower lip and lower cheeks (the mandible), 0 on the upper lip, the cheeks above
// the mouth corners, the ears and the neck.
float jaw_mask(glm::vec3 p);

// The part of the head whose vertices go into the "face" mesh (the one with morph targets). Every
// morph is zero outside it, so the seam with the body mesh never opens.
bool in_face_region(glm::vec3 p);

}  // namespace sw::avatar_generator
