// Parity cases for src/math: Euler angles in every order and seed 004's vector-to-vector angles,
// computed in single precision exactly as the WASM API does (src/wasm/core_api.cpp).
#include <cstdint>
#include <vector>

#include "math/euler.h"
#include "math/vector_rotation.h"
#include "parity.h"

namespace sw::cli {
namespace {

// Integer hash -> [-1, 1): inputs identical on every platform without <random>.
float signed_unit(std::uint32_t& state) {
  state = state * 1664525u + 1013904223u;
  return float(state >> 8) * (2.0f / 16777216.0f) - 1.0f;
}

std::vector<glm::vec3> euler_inputs() {
  std::vector<glm::vec3> inputs;
  std::uint32_t state = 2012;
  for (int i = 0; i < 200; ++i) {
    // One draw per statement: argument evaluation order is unspecified.
    const float x = signed_unit(state) * 3.1f;
    const float y = signed_unit(state) * 3.1f;
    const float z = signed_unit(state) * 3.1f;
    inputs.emplace_back(x, y, z);
  }
  // Gimbal lock in every order: each axis at +-90° (the middle angle of two orders each).
  for (int axis = 0; axis < 3; ++axis) {
    for (float sign : {1.0f, -1.0f}) {
      glm::vec3 a(0.3f, -0.8f, 1.2f);
      a[axis] = sign * 1.5707964f;
      inputs.push_back(a);
    }
  }
  return inputs;
}

nlohmann::json euler_case() {
  const std::vector<glm::vec3> inputs = euler_inputs();
  nlohmann::json json_inputs = nlohmann::json::array();
  for (const glm::vec3& a : inputs) json_inputs.push_back({a.x, a.y, a.z});
  nlohmann::json orders = nlohmann::json::object();
  for (math::EulerOrder order : math::kAllEulerOrders) {
    nlohmann::json quats = nlohmann::json::array(), angles = nlohmann::json::array();
    for (const glm::vec3& a : inputs) {
      const glm::quat q = math::quat_from_euler(a, order);
      quats.push_back({q.w, q.x, q.y, q.z});
      const glm::vec3 back = math::euler_from_quat(q, order);
      angles.push_back({back.x, back.y, back.z});
    }
    orders[math::euler_order_name(order)] = {{"quat_from_euler", quats}, {"euler_from_quat", angles}};
  }
  return {{"inputs_rad", json_inputs}, {"orders", orders}};
}

nlohmann::json vector_rotation_case() {
  std::vector<std::pair<glm::dvec3, glm::dvec3>> pairs;
  std::uint32_t state = 4;
  for (int i = 0; i < 100; ++i) {
    glm::dvec3 a, b;
    for (int k = 0; k < 3; ++k) a[k] = signed_unit(state);
    for (int k = 0; k < 3; ++k) b[k] = signed_unit(state);
    pairs.emplace_back(a, b);
  }
  pairs.emplace_back(glm::dvec3(0, 1, 0), glm::dvec3(0, 2, 0));    // parallel
  pairs.emplace_back(glm::dvec3(0, 1, 0), glm::dvec3(0, -1, 0));   // opposite
  pairs.emplace_back(glm::dvec3(1, 2, 3), glm::dvec3(-1, -2, -3));  // opposite, off-axis
  nlohmann::json json_pairs = nlohmann::json::array();
  for (const auto& [a, b] : pairs) json_pairs.push_back({{a.x, a.y, a.z}, {b.x, b.y, b.z}});
  nlohmann::json orders = nlohmann::json::object();
  for (math::EulerOrder order : math::kAllEulerOrders) {
    nlohmann::json angles = nlohmann::json::array();
    for (const auto& [a, b] : pairs) {
      const glm::dvec3 e = math::euler_between(a, b, order);
      angles.push_back({e.x, e.y, e.z});
    }
    orders[math::euler_order_name(order)] = angles;
  }
  return {{"pairs", json_pairs}, {"orders", orders}};
}

}  // namespace

SW_PARITY_CASE("euler", "six orders: float angles -> quat -> angles, incl. gimbal lock", euler_case);
SW_PARITY_CASE("vector_rotation", "seed 004: Euler angles taking r1 onto r2, every order", vector_rotation_case);

}  // namespace sw::cli
