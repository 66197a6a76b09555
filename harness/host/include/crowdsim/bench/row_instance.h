// The plugin objects of one row spec, made for one thread, and the exact scenario of any
// (row, episode): shared by suite runs, trainings, replays (rendering) and tools.
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

  /// The first sensor the robot policy needs (Policy::Needs) that the row does not configure,
  /// as "policy 'cadrl' needs the sensor 'lidar2d'"; "" when every need is met. Suite runs and
  /// trainings both check it before their first episode.
  std::string UnmetSensorNeed() const;

  /// What the humans' policy needs that only the robot is given (PolicyNeeds::sensors and
  /// ::lookahead: a human sees the others through Observation::agents), as "the humans' policy
  /// 'x' needs the sensor 'person', which only the robot is given"; "" when it needs neither,
  /// when the row has no humans (the policy never runs), or before Agents made a human. Suite
  /// runs, trainings and the Python env check it before their first episode, and say the fix,
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

/// The request a suite run makes for episode `episode` of `row` (seed from the suite seed,
/// the world's identity and the episode index).
ScenarioRequest MakeEpisodeRequest(const Suite& suite, const RowSpec& row, const WorldSource& world,
                                   int episode);

/// The world's scenario for that request, checked to hold the humans asked for
/// (CheckHumanCount); `request` (optional) receives the request. Throws what the world throws,
/// or std::invalid_argument.
Scenario MakeEpisodeScenario(const Suite& suite, const RowSpec& row, const WorldSource& world,
                             int episode, ScenarioRequest* request = nullptr);

/// Every plugin a row's episodes call, with its role there ("policy", "humans' policy",
/// "world", "sensor").
std::vector<std::pair<std::string, const PluginUse*>> RowPlugins(const RowSpec& row);
/// Whether every plugin of the row is the harness's own (PluginRegistry::IsHarnessPlugin).
bool AllHarnessPlugins(const RowSpec& row);
/// Whether the row's episodes must run in worker processes under isolation `mode` (the suite's,
/// or a run's override): on; or auto with an episode_timeout_s or a plugin that is not the
/// harness's own. What is not, the harness may step in its own process (validate's first step,
/// a replay for render).
bool RowNeedsIsolation(const Suite& suite, const RowSpec& row, IsolationMode mode);

/// Re-simulates one episode of a suite exactly as `crowdsim-bench run` does, optionally
/// recording the trajectory. Throws PluginError or std::out_of_range for a bad row index. A row
/// that `run` would isolate (a plugin not the harness's own, a timeout, isolation: on) is first
/// played in a worker process (`probe`): a plugin that crashes or hangs there is a
/// std::runtime_error naming the episode, not the end of the caller.
struct Replay {
  Scenario scenario;
  EpisodeResult result;
};
Replay ReplayEpisode(const Suite& suite, size_t row, int episode, PluginRegistry& registry,
                     bool record_trajectory, bool probe = true);

}  // namespace crowdsim
