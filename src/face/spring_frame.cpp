#include "face/spring_frame.h"

#include <algorithm>
#include <cmath>

namespace sw::face {

float spring_constant_from_lengths(const std::vector<float>& lengths_per_expression,
                                   float neutral_length, float k_max) {
  if (lengths_per_expression.empty()) return k_max;
  double sum = 0.0;
  for (float l : lengths_per_expression) sum += double(l - neutral_length) * (l - neutral_length);
  const double inverse_k = sum / double(lengths_per_expression.size());
  if (inverse_k <= 1.0 / k_max) return k_max;
  return static_cast<float>(1.0 / inverse_k);
}

float expression_natural_length(float expression_length, float neutral_length,
                                float current_natural_length) {
  if (neutral_length <= 0.0f) return current_natural_length;
  return expression_length / neutral_length * current_natural_length;
}

int SpringFrame::add_point(glm::vec2 position, bool fixed) {
  points_.push_back(SpringPoint{position, fixed, 1.0f});
  return static_cast<int>(points_.size()) - 1;
}

int SpringFrame::add_spring(int a, int b, float k, float natural_length) {
  springs_.push_back(Spring{a, b, k, natural_length});
  return static_cast<int>(springs_.size()) - 1;
}

namespace {

// Spring s's force on its end point `point` (the other end is `other`): F = -k (L - l) along the
// spring (cos theta, sin theta); a zero-length spring pulls straight to the other end point.
// Below this length a spring has no direction.
constexpr float kShortestSpring = 1e-9f;
// The same force given the difference d = point - other and its length.
glm::vec2 spring_force_along(const Spring& s, const glm::vec2& d, float length) {
  if (length > kShortestSpring) return -s.k * (length - s.natural_length) * (d / length);
  if (s.natural_length > 0.0f) return glm::vec2(s.k * s.natural_length, 0.0f);
  return glm::vec2(0.0f);
}
glm::vec2 spring_force(const Spring& s, const glm::vec2& point, const glm::vec2& other) {
  const glm::vec2 d = point - other;
  return spring_force_along(s, d, glm::length(d));
}

}  // namespace

glm::vec2 SpringFrame::net_force(int point) const {
  glm::vec2 total(0.0f);
  for (const Spring& s : springs_) {
    if (s.a != point && s.b != point) continue;
    const int other = s.a == point ? s.b : s.a;
    total += spring_force(s, points_[static_cast<std::size_t>(point)].position,
                          points_[static_cast<std::size_t>(other)].position);
  }
  return total;
}

float SpringFrame::step(float alpha) {
  // One pass over the springs gathers every point's net force and stiffness (per point, the
  // springs are still summed in their order, so the result is net_force's to the bit). Asking
  // net_force per point cost points x springs per step: the face layer's 67 channel springs,
  // stepped once per frame, were a quarter of a sign's synthesis time.
  std::vector<glm::vec2> forces(points_.size(), glm::vec2(0.0f));
  std::vector<float> stiffness(points_.size(), 0.0f);
  for (const Spring& s : springs_) {
    const std::size_t a = static_cast<std::size_t>(s.a), b = static_cast<std::size_t>(s.b);
    const glm::vec2 d = points_[a].position - points_[b].position;
    const float length = glm::length(d);
    // spring_force at each end, worked out once: b's difference is -d to the bit (a rounded
    // difference is odd in its operands), so is its length and, along the spring, its force.
    // Only a spring too short for a direction pulls both ends the same way.
    const glm::vec2 force_on_a = spring_force_along(s, d, length);
    forces[a] += force_on_a;
    stiffness[a] += s.k;
    if (b == a) continue;
    forces[b] += length > kShortestSpring ? -force_on_a : force_on_a;
    stiffness[b] += s.k;
  }
  float largest = 0.0f;
  for (std::size_t i = 0; i < points_.size(); ++i) {
    if (points_[i].fixed) continue;
    largest = std::max(largest, glm::length(forces[i]));
    // Stability: the seed's explicit update overshoots when alpha * k / m exceeds 1 — cap the
    // step per point by its stiffest spring.
    const float stiffest = stiffness[i];
    const float mass = points_[i].mass;
    const float a = stiffest > 0.0f ? std::min(alpha, 0.9f * mass / stiffest) : alpha;
    points_[i].position += a * forces[i] / mass;
  }
  return largest;
}

int SpringFrame::relax(float alpha, float tolerance, int max_steps) {
  for (int i = 0; i < max_steps; ++i)
    if (step(alpha) < tolerance) return i + 1;
  return max_steps;
}

}  // namespace sw::face
