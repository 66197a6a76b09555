#include "social_force.h"

#include <cmath>

namespace crowdsim::social_force {

Vec2 PedestrianRepulsion(const Vec2& r_ab, const Vec2& velocity_b, const Constants& c) {
  const double s = velocity_b.norm() * c.step_time;
  const Vec2 e_b = s > 0.0 ? Vec2(velocity_b / velocity_b.norm()) : Vec2::Zero();
  const Vec2 r_next = r_ab - s * e_b;
  const double d = r_ab.norm();
  const double d_next = r_next.norm();
  const double sum = d + d_next;
  const double b = 0.5 * std::sqrt(std::max(0.0, sum * sum - s * s));
  if (b <= 1e-12 || d <= 0.0 || d_next <= 0.0) return Vec2::Zero();
  // ∂b/∂r = (|r| + |r'|) (r/|r| + r'/|r'|) / (4b), and -dV/db = V0/σ exp(-b/σ).
  const Vec2 db_dr = sum * (r_ab / d + r_next / d_next) / (4.0 * b);
  return db_dr * (c.v0_ped / c.sigma * std::exp(-b / c.sigma));
}

}  // namespace crowdsim::social_force
