// Face regions: the masks that say how much of the face follows the jaw, shared by the skin
// weights (the jaw joint) and the jawOpen morph, so both open the mouth along the same line.
#pragma once

#include <glm/glm.hpp>

namespace sw::avatar_generator {

// 1 on the chin, lower lip and lower cheeks (the mandible), 0 on the upper lip, the cheeks above
// the mouth corners, the ears and the neck; a sharp step exactly at the lip line between the mouth
// corners (the slit separates the lips) widening to a soft transition towards the jaw angles.
float jaw_mask(glm::vec3 p);

}  // namespace sw::avatar_generator
