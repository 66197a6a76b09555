// An example robot policy plugin: straight to the goal, slowing down when a person is ahead
// and close. It reads the person sensor (declared in Needs, so a suite without it is refused
// before the first episode) and takes two parameters, validated by the harness from Schema().
#include <algorithm>
#include <cmath>

#include "crowdsim/plugin_abi.h"

namespace my_policy {

using crowdsim::Action;
using crowdsim::Observation;
using crowdsim::Params;
using crowdsim::ParamSchema;
using crowdsim::ParamType;
using crowdsim::Vec2;

ParamSchema Schema() {
  return {
      {"slow_distance",
       ParamType::kDouble,
       1.5,
       0.0,
       10.0,
       {},
       "m; a person ahead closer than this slows the robot down (0: never slows)"},
      {"min_speed_factor",
       ParamType::kDouble,
       0.2,
       0.0,
       1.0,
       {},
       "the slowest speed, as a fraction of v_pref"},
  };
}

class YieldingStraight final : public crowdsim::Policy {
 public:
  explicit YieldingStraight(const Params& params)
      : slow_distance_(params.GetDouble("slow_distance")),
        min_speed_factor_(params.GetDouble("min_speed_factor")) {}

  crowdsim::PolicyNeeds Needs() const override {
    crowdsim::PolicyNeeds needs;
    needs.sensors = {"person"};
    return needs;
  }

  // No state between steps; Reset keeps the episode's constants (here the time step).
  void Reset(const crowdsim::EpisodeContext& ctx) override { time_step_ = ctx.sim.time_step; }

  Action Decide(const Observation& obs) override {
    const Vec2 to_goal = obs.self.goal - obs.self.position;
    const double dist = to_goal.norm();
    if (dist < 1e-9) return Action{};
    // People are given in the sensor frame: x points at the goal, so "ahead" is x > 0.
    double nearest_ahead = slow_distance_;
    if (const auto* reading = obs.Reading("person")) {
      for (const auto& person : reading->people) {
        if (person.position.x() <= 0.0) continue;
        const double gap = person.position.norm() - person.radius - obs.self.radius;
        nearest_ahead = std::min(nearest_ahead, std::max(0.0, gap));
      }
    }
    // Full speed when nobody is closer than slow_distance (also when it is 0: never slows).
    const double factor = nearest_ahead >= slow_distance_
                              ? 1.0
                              : std::max(min_speed_factor_, nearest_ahead / slow_distance_);
    double speed = factor * obs.self.v_pref;
    if (time_step_ > 0.0) speed = std::min(speed, dist / time_step_);  // stop on the goal
    return Action{to_goal / dist * speed};
  }

 private:
  double slow_distance_;
  double min_speed_factor_;
  double time_step_ = crowdsim::SimConfig{}.time_step;
};

extern "C++" const crowdsim::PluginDescriptor kDescriptor =
    crowdsim::PolicyPlugin<YieldingStraight>(
        "yielding_straight", "example: straight to the goal, slowing for people ahead", &Schema);

}  // namespace my_policy

CROWDSIM_EXPORT_PLUGIN(my_policy::kDescriptor)
