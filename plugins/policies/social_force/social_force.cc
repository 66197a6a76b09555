#include "social_force.h"

#include <algorithm>
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

Vec2 GroupForce(const Vec2& position, const Vec2& e, std::span<const Vec2> others,
                const GroupConstants& g) {
  if (others.empty()) return Vec2::Zero();
  Vec2 others_sum = Vec2::Zero();
  Vec2 force = Vec2::Zero();
  for (const Vec2& q : others) {
    others_sum += q;
    const Vec2 away = position - q;
    const double d = away.norm();
    if (d > 0.0 && d < g.repulsion_dist) force += g.repulsion * away / d;
  }
  const double n = static_cast<double>(others.size()) + 1.0;
  const Vec2 to_centre = (others_sum + position) / n - position;
  const double centre_dist = to_centre.norm();
  if (centre_dist > 0.5 * (n - 1.0)) force += g.coherence * to_centre / centre_dist;
  const Vec2 to_others = others_sum / (n - 1.0) - position;
  const double others_dist = to_others.norm();
  if (others_dist > 0.0 && e.squaredNorm() > 0.0) {
    const double alpha = std::acos(std::clamp(e.dot(to_others) / others_dist, -1.0, 1.0));
    if (alpha > g.half_view) force -= g.gaze * (alpha - g.half_view) * e;
  }
  return force;
}

}  // namespace crowdsim::social_force
