// The `replay` humans' policy: each person walks its recorded track (HumanSpec::track), linearly
// interpolated to the time step, blind to the robot and to everybody (SocNavBench's replay).
#pragma once

#include <span>

#include "crowdsim/params.h"
#include "crowdsim/policy.h"

namespace crowdsim::replay {

class ReplayPolicy final : public Policy {
 public:
  explicit ReplayPolicy(const Params&) {}
  PolicyNeeds Needs() const override;
  void Reset(const EpisodeContext& ctx) override;
  /// The velocity that puts the person on its track at the next step's time.
  Action Decide(const Observation& obs) override;

 private:
  std::span<const TrackPoint> track_;
  double time_step_ = 0.25;
  int agent_id_ = 0;
};

/// No parameters: the world's tracks say everything.
ParamSchema Schema();

}  // namespace crowdsim::replay
