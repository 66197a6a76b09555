// Straight to the goal at the preferred speed: the trivial baseline, and the simplest
// example of a policy plugin.
#pragma once

#include "crowdsim/params.h"
#include "crowdsim/policy.h"

namespace crowdsim::linear {

class LinearPolicy final : public Policy {
 public:
  explicit LinearPolicy(const Params& params);
  PolicyNeeds Needs() const override;
  void Reset(const EpisodeContext& ctx) override;
  Action Decide(const Observation& obs) override;

 private:
  double speed_factor_;
  bool slow_down_;
  double time_step_ = SimConfig{}.time_step;  ///< the episode's (Reset)
};

ParamSchema Schema();

}  // namespace crowdsim::linear
