// One row's plugin objects for one thread, and the exact scenario of any (row, episode); shared by
// runs, trainings, replays and tools.
#pragma once

#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "crowdsim/bench/episode.h"
#include "crowdsim/bench/suite.h"

namespace crowdsim {

/// Robot policy, sensors and human policies of one row; never shared between threads.
class RowInstance {
 public:
  /// Makes the robot policy and sensors. Throws PluginError.
  RowInstance(const RowSpec& row, PluginRegistry& registry);

  /// The agents for an episode with `humans` humans (human policies made on demand).
  const EpisodeAgents& Agents(size_t humans);
  Policy& robot() { return *robot_; }

  /// The first sensor the robot policy needs (Policy::Needs) that the row lacks, as "policy 'cadrl'
  /// needs the sensor 'lidar2d'"; "" if none.
  std::string UnmetSensorNeed() const;
  /// "policy 'X' returns world velocities only ...": the robot policy cannot drive the row's
  /// kinematics; "" when it can.
  std::string UnmetKinematicsNeed() const;

  /// What the humans' policy needs that only the robot gets (sensors, lookahead; humans see others
  /// via Observation::agents), as "the humans' policy 'x' needs the sensor 'person', which only the
  /// robot is given"; "" when none, the row has no humans, or before Agents made one. The fix:
  /// kPlainHumansPolicy.
  std::string HumansNeedRobotOnly() const;

 private:
  const RowSpec& row_;
  PluginRegistry& registry_;
  std::shared_ptr<Policy> robot_;
  std::vector<std::shared_ptr<Sensor>> sensors_;
  std::vector<std::shared_ptr<Policy>> humans_;
  EpisodeAgents agents_;
};

/// The fix for what HumansNeedRobotOnly reports.
inline constexpr char kPlainHumansPolicy[] =
    "give the humans a policy that needs neither, e.g. humans: {policy: orca}";

/// A suite run's request for episode `episode` of `row`, seeded from suite seed, world identity and
/// episode index.
ScenarioRequest MakeEpisodeRequest(const Suite& suite, const RowSpec& row, const WorldSource& world,
                                   int episode);

/// The world's scenario for that request, checked for the humans asked (CheckHumanCount); `request`
/// optionally receives it. Throws the world's errors or std::invalid_argument.
Scenario MakeEpisodeScenario(const Suite& suite, const RowSpec& row, const WorldSource& world,
                             int episode, ScenarioRequest* request = nullptr);

/// Every plugin a row's episodes call, with its role there ("policy", "humans' policy",
/// "world", "sensor").
std::vector<std::pair<std::string, const PluginUse*>> RowPlugins(const RowSpec& row);
/// Whether every plugin of the row is the harness's own (PluginRegistry::IsHarnessPlugin).
bool AllHarnessPlugins(const RowSpec& row);
/// Whether the row's episodes need worker processes under `mode`: on, or auto with a timeout or a
/// plugin not the harness's own.
bool RowNeedsIsolation(const Suite& suite, const RowSpec& row, IsolationMode mode);

/// An isolated episode's wall-clock limit: the suite's episode_timeout_s, else the default.
double IsolatedEpisodeTimeoutS(const Suite& suite);

/// Re-simulates one suite episode exactly as `run` does, optionally recording the trajectory.
/// Throws PluginError, or std::out_of_range for a bad row. A row `run` would isolate is first
/// played in a worker (`probe`): a crash or hang there is a std::runtime_error naming the episode.
struct Replay {
  Scenario scenario;
  EpisodeResult result;
};
Replay ReplayEpisode(const Suite& suite, size_t row, int episode, PluginRegistry& registry,
                     bool record_trajectory, bool probe = true);

}  // namespace crowdsim
