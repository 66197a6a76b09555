// One suite row's episodes stepped with velocities chosen outside the harness (Python): the
// row's world, humans and sensors exactly as `crowdsim-bench run` makes them, with a
// PythonPolicy as the robot. Env holds one; VectorEnv holds one per sub-environment and steps
// them on worker threads (a RowEpisodes is used by one thread at a time).
#pragma once

#include <memory>

#include "crowdsim/bench/episode.h"
#include "crowdsim/bench/plugin_registry.h"
#include "crowdsim/bench/row_instance.h"
#include "crowdsim/bench/suite.h"
#include "python_policy.h"

namespace crowdsim::python {

class RowEpisodes {
 public:
  /// `suite` and `row` must outlive this object (the row's robot must be the Python policy).
  /// Makes the policies of every human up front, so Reset makes no plugin objects.
  RowEpisodes(const Suite& suite, const RowSpec& row, PluginRegistry& registry);

  /// Starts the row's episode `episode` (the suite's episode index) and observes its first
  /// state. Throws std::invalid_argument when the world makes an invalid scenario.
  const Observation& Reset(int episode, bool record);
  /// One step with the robot's velocity (m/s, world frame); the new state is observation().
  StepInfo Step(const Vec2& velocity);
  /// The robot's observation of the current state (made once per state).
  const Observation& observation() { return episode_->ObserveRobot(); }

  bool started() const { return episode_ != nullptr; }
  const Episode& episode() const { return *episode_; }
  const Scenario& scenario() const { return scenario_; }
  int episode_index() const { return episode_index_; }

 private:
  const Suite& suite_;
  const RowSpec& row_;
  std::shared_ptr<WorldSource> world_;
  std::unique_ptr<RowInstance> instance_;
  PythonPolicy* policy_ = nullptr;
  Scenario scenario_;
  std::unique_ptr<Episode> episode_;
  int episode_index_ = -1;
};

}  // namespace crowdsim::python
