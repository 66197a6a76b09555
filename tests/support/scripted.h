// Scripted policies and hand-made worlds for tests and benchmarks.
#pragma once

#include <memory>
#include <vector>

#include "crowdsim/policy.h"
#include "crowdsim/scenario.h"

namespace crowdsim::testing {

/// Holds a fixed velocity.
class ConstantVelocityPolicy final : public Policy {
 public:
  explicit ConstantVelocityPolicy(Vec2 v) : v_(v) {}
  Action Decide(const Observation&) override { return Action{v_}; }

 private:
  Vec2 v_;
};

/// Straight to the goal at v_pref, slowing down on the last step.
class GoStraightPolicy final : public Policy {
 public:
  void Reset(const EpisodeContext& ctx) override { time_step_ = ctx.sim.time_step; }
  Action Decide(const Observation& obs) override;

 private:
  double time_step_ = SimConfig{}.time_step;
};

/// A map with the given rectangles inside generous bounds.
std::shared_ptr<const StaticMap> MakeMap(std::vector<Rect> rects,
                                         Rect bounds = Rect::FromCorners(-20, -20, 20, 20));

/// A 10 x 10 m room ([-5, 5]^2) with 4 border walls 0.5 m thick and `obstacles` inside.
std::shared_ptr<const StaticMap> MakeRoom(std::vector<Rect> obstacles = {});

/// A scenario from the robot's start/goal and humans' (start, goal) pairs.
Scenario MakeScenario(std::shared_ptr<const StaticMap> map, Vec2 robot_start, Vec2 robot_goal,
                      std::vector<std::pair<Vec2, Vec2>> humans = {});

}  // namespace crowdsim::testing
