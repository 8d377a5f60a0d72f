// SpringFrame: seed 003's spring-frame face model — feature points (fixed on bone, or moving),
// joined by springs that stand in for muscles; an expression changes some springs' natural lengths
// and the moving points relax to the equilibrium, showing the intermediate states on the way.
//
//   spring constant   1/k_i = sum_n (L_i(n) - l_si)^2 / n           (variability across
//   expressions) force             F_i = -k_i (L_i - l_i) acceleration      m d2x/dt2 = sum_i F_i
//   cos(theta_i), m d2y/dt2 = sum_i F_i sin(theta_i) update            x(t+1) = x(t) + alpha * sum
//   d2x/dt2            until sum F -> 0 expression        l_ci = (L_i(n) / l_si) * l_i
//
// The seed iterates positions directly with the force (no velocity state): a damped relaxation that
// cannot overshoot for alpha * k < 1, which is why each spring's alpha*k is capped at 0.9 below.
#pragma once

#include <vector>

#include <glm/glm.hpp>

namespace sw::face {

struct SpringPoint {
  glm::vec2 position{0.0f};
  bool fixed = false;  // seed 003: points on bone do not move
  float mass = 1.0f;
};

struct Spring {
  int a = 0, b = 0;
  float k = 1.0f;               // spring constant
  float natural_length = 0.0f;  // l_i
};

// seed 003: 1/k = sum_n (L(n) - l_s)^2 / n. A spring that never changes length across the
// expressions is bone-like: its constant is capped at `k_max` instead of dividing by zero.
float spring_constant_from_lengths(const std::vector<float>& lengths_per_expression,
                                   float neutral_length, float k_max = 100.0f);

// seed 003: the natural length an expression asks for, l_c = (L(n) / l_s) * l.
float expression_natural_length(float expression_length, float neutral_length,
                                float current_natural_length);

class SpringFrame {
 public:
  int add_point(glm::vec2 position, bool fixed);
  int add_spring(int a, int b, float k, float natural_length);

  // One relaxation step (seed 003's update); returns the largest remaining force magnitude.
  float step(float alpha);
  // Steps until every moving point's net force is below `tolerance` or `max_steps` pass.
  // Returns the number of steps taken.
  int relax(float alpha, float tolerance, int max_steps);

  glm::vec2 net_force(int point) const;
  std::vector<SpringPoint>& points() { return points_; }
  const std::vector<SpringPoint>& points() const { return points_; }
  std::vector<Spring>& springs() { return springs_; }
  const std::vector<Spring>& springs() const { return springs_; }

 private:
  std::vector<SpringPoint> points_;
  std::vector<Spring> springs_;
};

}  // namespace sw::face
