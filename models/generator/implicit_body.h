// Implicit body: the avatar's surface as a signed distance field built from smooth unions of round
// cones (capsules with two radii) and ellipsoids, one "part" per body region.
//
// Blending is a tree: a part blends (polynomial smooth minimum) with its parent part only, never
// with its siblings — the fingers blend into the palm but never into each other, which is what
// keeps them separated; the legs blend into the pelvis but not into each other. Carves (eye
// sockets, the mouth slit) are smooth subtractions inside a part.
//
// Not an exact Euclidean distance: ellipsoids and blends give a field whose gradient is close to,
// but not exactly, 1 — enough for polygonisation (sign changes and linear crossings) and for
// normals (the gradient direction). Bounds used for culling carry a safety margin for that.
#pragma once

#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "humanoid_layout.h"

namespace sw::avatar_generator {

// What a surface point is made of; becomes a glTF material / primitive.
enum class Surface : int {
  kSkin = 0,
  kTop,  // long-sleeve top
  kTrousers,
  kShoes,
  kHair,
  kLips,
  kBrows,
  kMouthInner,  // the dark inside of the mouth slit
  kCount
};

// Eye geometry shared by the body, the eyeball meshes and the blink morphs.
constexpr float kEyeballRadius = 0.0120f;
constexpr float kEyelidRadius = 0.0132f;
constexpr float kMouthY = 1.532f;  // height of the lip line (mouth slit centre)

struct ImplicitPrimitive {
  enum class Kind { kRoundCone, kEllipsoid } kind = Kind::kRoundCone;
  glm::vec3 a{0}, b{0};   // round cone: axis end points; ellipsoid: a = centre
  float radius_a = 0.0f;  // round cone radii at a and b
  float radius_b = 0.0f;
  glm::vec3 radii{0};  // ellipsoid semi-axes (model axes)
  // Round cone cross-section squash: distances along `squash_axis` are divided by `squash`
  // (wrists and feet are wider than deep).
  glm::vec3 squash_axis{0, 1, 0};
  float squash = 1.0f;
  int part = 0;            // owning part
  bool carve = false;      // subtracted from its part instead of added
  float carve_k = 0.002f;  // smoothing of the subtraction
  Surface surface = Surface::kSkin;
  // Conservative bounding box including the primitive's own extent.
  glm::vec3 box_min{0}, box_max{0};
};

struct ImplicitPart {
  std::string name;
  int parent = -1;       // parts are ordered parents first
  float blend_k = 0.0f;  // smooth-union radius with the parent part, metres
  float inner_k = 0.0f;  // smooth-union radius between this part's own primitives
};

struct SurfaceSample {
  float distance = 1e9f;
  int nearest_primitive = -1;  // the additive primitive whose raw distance is smallest
};

class ImplicitBody {
 public:
  explicit ImplicitBody(const HumanoidLayout& layout);

  // Field value and nearest primitive, with every primitive active.
  SurfaceSample sample(glm::vec3 p) const;
  // Same with only the listed primitives (the others are treated as infinitely far). Exact on
  // the zero set as long as the culled primitives are farther than cull_margin() from p.
  SurfaceSample sample(glm::vec3 p, const std::vector<int>& active) const;
  glm::vec3 gradient(glm::vec3 p, const std::vector<int>& active, float step) const;
  // Primitives whose bounds come within `margin` of the box.
  std::vector<int> primitives_near(glm::vec3 box_min, glm::vec3 box_max, float margin) const;
  float cull_margin() const { return cull_margin_; }

  const std::vector<ImplicitPrimitive>& primitives() const { return primitives_; }
  const std::vector<ImplicitPart>& parts() const { return parts_; }
  glm::vec3 bounds_min() const { return bounds_min_; }
  glm::vec3 bounds_max() const { return bounds_max_; }

  // Material at a surface point: the nearest primitive's surface, refined by garment lines.
  Surface surface_at(glm::vec3 p, int nearest_primitive) const;

 private:
  int add_part(const std::string& name, int parent, float blend_k, float inner_k);
  void add(ImplicitPrimitive primitive);
  float primitive_distance(const ImplicitPrimitive& primitive, glm::vec3 p) const;

  const HumanoidLayout& layout_;
  std::vector<ImplicitPart> parts_;
  std::vector<ImplicitPrimitive> primitives_;
  glm::vec3 bounds_min_{1e9f}, bounds_max_{-1e9f};
  float cull_margin_ = 0.0f;
};

}  // namespace sw::avatar_generator
