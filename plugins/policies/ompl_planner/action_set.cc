#include "action_set.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace crowdsim::ompl_planner {

std::vector<Vec2> ActionSet(const Vec2& pref, double v_pref) {
  const double base = pref.squaredNorm() > 1e-18 ? std::atan2(pref.y(), pref.x()) : 0.0;
  std::vector<Vec2> out;
  out.reserve(16);
  for (double speed : {v_pref, 0.5 * v_pref}) {
    for (int k = 0; k < 8; ++k) {
      const double a = base + k * std::numbers::pi / 4.0;
      out.emplace_back(speed * std::cos(a), speed * std::sin(a));
    }
  }
  return out;
}

double PredictedDistance(const Vec2& position, const Vec2& velocity, double radius,
                         const orca::OrcaAgent& person, double horizon) {
  const Vec2 p = person.position - position;
  const Vec2 w = person.velocity - velocity;
  const double ww = w.squaredNorm();
  const double t = ww > 1e-12 ? std::clamp(-p.dot(w) / ww, 0.0, horizon) : 0.0;
  return (p + t * w).norm() - radius - person.radius;
}

Vec2 ChooseAction(const Vec2& position, const Vec2& pref, std::span<const orca::OrcaAgent> people,
                  const CollisionWorld& world, const ActionSetParams& params) {
  const double horizon = std::max(params.horizon, params.time_step);
  std::vector<Vec2> candidates = {pref};
  for (const Vec2& v : ActionSet(pref, params.v_pref)) candidates.push_back(v);
  candidates.push_back(Vec2::Zero());

  const Vec2* best_safe = nullptr;
  double best_safe_cost = kInfinity;
  const Vec2* best_fallback = nullptr;
  double best_fallback_distance = -kInfinity;
  for (const Vec2& v : candidates) {
    // A step into a rectangle is never taken (standing still always passes).
    if (v.squaredNorm() > 0.0 &&
        world.SweepDisc(position, position + v * params.time_step, params.radius).fraction !=
            kInfinity) {
      continue;
    }
    double nearest = kInfinity;
    for (const orca::OrcaAgent& person : people) {
      nearest = std::min(nearest, PredictedDistance(position, v, params.radius, person, horizon));
    }
    const double cost = (v - pref).squaredNorm();
    if (nearest >= params.clearance && cost < best_safe_cost) {
      best_safe = &v;
      best_safe_cost = cost;
    }
    if (nearest > best_fallback_distance) {
      best_fallback = &v;
      best_fallback_distance = nearest;
    }
  }
  if (best_safe != nullptr) return *best_safe;
  return best_fallback != nullptr ? *best_fallback : Vec2::Zero();
}

}  // namespace crowdsim::ompl_planner
