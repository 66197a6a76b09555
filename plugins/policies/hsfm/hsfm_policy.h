// The `hsfm` policy: the Headed Social Force Model (Farina et al. 2017) as a humans' policy
// (and a robot baseline). The heading is the policy's own state, integrated in sub-steps.
#pragma once

#include <vector>

#include "crowdsim/params.h"
#include "crowdsim/policy.h"
#include "hsfm.h"
#include "walking/neighbours.h"
#include "walking/roadmap_guide.h"

namespace crowdsim::hsfm {

/// The plugin's parameters (README.md gives each one's source).
ParamSchema Schema();

class HsfmPolicy final : public Policy {
 public:
  explicit HsfmPolicy(const Params& params);

  PolicyNeeds Needs() const override;
  void Reset(const EpisodeContext& ctx) override;
  Action Decide(const Observation& obs) override;

  /// The person's body after its last decision (tests read the heading).
  const Body& body() const { return body_; }

 private:
  /// The interaction forces (N) on `body` of `radius`: the neighbours, moved on along their
  /// velocities for `elapsed` s, and the rectangles within wall_range.
  Vec2 InteractionForce(const Body& body, double radius, double elapsed) const;
  /// Starts the body from what the harness reports: at the first decision the heading faces
  /// the velocity (standing: the desired velocity), later only the velocity is re-read.
  void SyncBody(const AgentState& self, const Vec2& desired);

  Constants constants_;
  GroupConstants group_constants_;
  double max_speed_factor_;
  double sub_step_;
  double neighbor_dist_;
  int max_neighbors_;
  double wall_range_;
  walking::RoadmapGuide guide_;

  const StaticMap* map_ = nullptr;
  double time_step_ = 0.25;
  bool started_ = false;
  Body body_;
  Vec2 returned_ = Vec2::Zero();  // the velocity the last decision returned
  std::vector<walking::Neighbour> others_;
  std::vector<Vec2> group_;
  std::vector<int> ids_;
};

}  // namespace crowdsim::hsfm
