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
#include "walking/neighbours.h"
#include "walking/roadmap_guide.h"

namespace crowdsim::social_force {

/// The plugin's parameters (Helbing & Molnár 1995's values; README.md).
ParamSchema Schema();

class SocialForcePolicy final : public Policy {
 public:
  explicit SocialForcePolicy(const Params& params);

  PolicyNeeds Needs() const override;
  void Reset(const EpisodeContext& ctx) override;
  Action Decide(const Observation& obs) override;

  /// The summed acceleration (m/s^2) on `self` heading for `target` among `others`, its
  /// group's other members at `group` and the map's rectangles: what Decide
  /// integrates over one step.
  Vec2 Acceleration(const AgentState& self, const orca::GuidanceTarget& target,
                    const std::vector<walking::Neighbour>& others,
                    std::span<const Vec2> group = {}) const;

 private:
  Constants constants_;
  GroupConstants group_constants_;
  double max_speed_factor_;
  double neighbor_dist_;
  int max_neighbors_;
  double wall_range_;

  const StaticMap* map_ = nullptr;
  double time_step_ = 0.25;
  walking::RoadmapGuide guide_;
  std::vector<walking::Neighbour> others_;
  std::vector<Vec2> group_;
  std::vector<int> ids_;
};

}  // namespace crowdsim::social_force
