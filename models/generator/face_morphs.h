// Face morphs: the morph targets of the face mesh, one per face channel of src/face/channels.h
// (26 ARKit-named expression channels, then the 15 Oculus visemes), named exactly as there.
//
// Each target is a displacement field evaluated at the rest position: Gaussian-masked offsets for
// brows, cheeks, nose and lip corners (FACS action units, see channels.h); rotations about the
// eye centre for the lids (a lid slides over the eyeball, it does not shear through it); a
// rotation about the temporomandibular hinge for jawOpen (the same line as the jaw joint's skin
// weights); the visemes are combinations of the mouth shapes (open, round, stretch, press,
// teeth-on-lip, tongue). Every field is zero outside face_regions' face region.
#pragma once

#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "avatar_mesh.h"
#include "humanoid_layout.h"

namespace sw::avatar_generator {

std::vector<std::string> face_morph_names();  // expression channels, then visemes

// Displacement of one vertex for morph `channel` (index into face_morph_names()) at weight 1.
glm::vec3 face_morph_delta(const HumanoidLayout& layout, int channel, glm::vec3 rest,
                           Material material);

}  // namespace sw::avatar_generator
