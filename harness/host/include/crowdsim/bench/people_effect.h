// The robot's effect on the people (Francis et al. 2023): each person's walk in the episode
// against the same episode replayed without the robot. The harness is deterministic, so the
// replay is the exact counterfactual; it costs the people's decisions of every step once more.
#pragma once

#include <span>
#include <vector>

#include "crowdsim/agent_state.h"
#include "crowdsim/bench/episode.h"
#include "crowdsim/bench/social_metrics.h"

namespace crowdsim {

/// The people's walks, state by state: path length and summed |dv| / dt per person.
class PeopleWalks {
 public:
  explicit PeopleWalks(double dt) : dt_(dt) {}
  /// The first call is time 0 (people start from rest), each next one the state after a step.
  void Observe(std::span<const AgentState> humans);

  std::vector<double> path;
  std::vector<double> accel_sum;
  std::vector<AgentState> last;
  int steps = 0;

 private:
  double dt_;
};

/// Replays `played`'s scenario without the robot (its people's policies reset, the robot
/// invisible and never moving) for as many steps as `played` took, and fills `m`'s people_*
/// metrics from `with` (the people's walks in `played`) against the replay. Leaves them NaN
/// without people, or when the replay fails (a human policy throws).
void FillPeopleEffect(const Episode& played, const PeopleWalks& with, SocialMetrics* m);

}  // namespace crowdsim
