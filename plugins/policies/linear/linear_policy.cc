#include "linear_policy.h"

#include <algorithm>

namespace crowdsim::linear {

ParamSchema Schema() {
  return {
      {"speed_factor", ParamType::kDouble, 1.0, 0.0, 2.0, {}, "speed as a multiple of v_pref"},
      {"slow_down",
       ParamType::kBool,
       true,
       0,
       1,
       {},
       "shorten the last step so as not to overshoot the goal"},
  };
}

LinearPolicy::LinearPolicy(const Params& params)
    : speed_factor_(params.GetDouble("speed_factor")), slow_down_(params.GetBool("slow_down")) {}

PolicyNeeds LinearPolicy::Needs() const {
  PolicyNeeds needs;
  needs.non_holonomic = NonHolonomicDrive::kTrackVelocity;  // turn towards the goal, then go
  return needs;
}

void LinearPolicy::Reset(const EpisodeContext& ctx) { time_step_ = ctx.sim.time_step; }

Action Decide_(const Observation& obs, double speed_factor, bool slow_down, double time_step) {
  const Vec2 to_goal = obs.self.goal - obs.self.position;
  const double dist = to_goal.norm();
  if (dist < 1e-9) return Action{};
  double speed = speed_factor * obs.self.v_pref;
  if (slow_down && time_step > 0.0) speed = std::min(speed, dist / time_step);
  return Action{to_goal / dist * speed};
}

Action LinearPolicy::Decide(const Observation& obs) {
  return Decide_(obs, speed_factor_, slow_down_, time_step_);
}

}  // namespace crowdsim::linear
