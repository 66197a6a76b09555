// The `social_force` policy: Helbing & Molnár's social force model (1995) as a humans' policy
// (and a robot baseline), with the ORCA humans' roadmap for global guidance around rectangles.
#pragma once

#include <memory>
#include <span>
#include <vector>

#include "crowdsim/params.h"
#include "crowdsim/policy.h"
#include "orca/guidance.h"
#include "social_force.h"

namespace crowdsim::social_force {

/// The plugin's parameters (Helbing & Molnár 1995's values; README.md).
ParamSchema Schema();

class SocialForcePolicy final : public Policy {
 public:
  explicit SocialForcePolicy(const Params& params);

  PolicyNeeds Needs() const override;
  void Reset(const EpisodeContext& ctx) override;
  Action Decide(const Observation& obs) override;

  /// The summed acceleration (m/s^2) on `self` heading for `target` among `others` (position,
  /// velocity), its group's other members at `group` and the map's rectangles: what Decide
  /// integrates over one step.
  Vec2 Acceleration(const AgentState& self, const orca::GuidanceTarget& target,
                    const std::vector<std::pair<Vec2, Vec2>>& others,
                    std::span<const Vec2> group = {}) const;

 private:
  /// Fills others_ with the neighbours' (position, velocity): ground truth for a human, the
  /// person sensor's people for the robot.
  void GatherOthers(const Observation& obs);
  /// `velocity` less its part into any rectangle it would touch within the step (it slides along
  /// the edge); zero when sliding still touches one (a corner, two rectangles).
  Vec2 SlideAlongRectangles(const Vec2& position, double radius, Vec2 velocity) const;

  Constants constants_;
  GroupConstants group_constants_;
  double max_speed_factor_;
  double neighbor_dist_;
  int max_neighbors_;
  double wall_range_;
  bool guidance_enabled_;
  double guidance_margin_;

  const StaticMap* map_ = nullptr;
  double time_step_ = 0.25;
  double roadmap_radius_ = -1.0;
  orca::Guidance guidance_;
  std::vector<std::pair<Vec2, Vec2>> others_;
  std::vector<Vec2> group_;
  std::vector<int> ids_;
};

}  // namespace crowdsim::social_force
