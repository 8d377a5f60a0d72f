// Head gestures and gaze (seed 002): non-manual head movements (nod, shake, tilt) as rotations
// layered on the head joint, and eyes that keep eye contact — they inherit the head's motion and
// then take the inverse head rotation, so the gaze stays on the addressee.
#pragma once

#include <string_view>

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

namespace sw::face {

enum class HeadGesture { None, Nod, Shake, TiltLeft, TiltRight, Forward, Back };

HeadGesture head_gesture_from_name(std::string_view name);

// The extra head rotation of a gesture at local time u in [0, 1] of its span (model axes: the
// avatar faces +Z, +Y up, +X its left). Nods and shakes are damped oscillations (two cycles);
// tilts ease in and out. Zero at u = 0 and u = 1 so gestures join the clip without a jump.
glm::quat head_gesture_rotation(HeadGesture gesture, float u);

// seed 002: eyes inherit the head motion, then the inverse head rotation keeps the eye contact.
// `head_world` is the head's rotation relative to its rest orientation in model space, `look_dir`
// the direction the eyes should look in model space (e.g. +Z to the addressee). Returns the eye
// joint's model-space rotation relative to its rest, clamped to the eyeball's range.
glm::quat gaze_rotation(const glm::quat& head_world, const glm::vec3& look_dir,
                        float max_angle_rad = 0.6f);

// Direction for a gaze name ("addressee" default, "up", "down", "left", "right").
glm::vec3 gaze_direction(std::string_view name);

}  // namespace sw::face
