#include "crowdsim/bench/row_instance.h"

#include <algorithm>
#include <optional>
#include <stdexcept>
#include <string>

#include "crowdsim/bench/human_attributes.h"
#include "crowdsim/bench/runner.h"
#include "crowdsim/rng.h"
#include "run/worker_process.h"

namespace crowdsim {

RowInstance::RowInstance(const RowSpec& row, PluginRegistry& registry)
    : row_(row), registry_(registry) {
  robot_ = registry_.MakePolicy(*row_.policy.loaded, row_.policy.params);
  agents_.robot = robot_.get();
  agents_.kinematics = row_.kinematics;
  for (const auto& s : row_.sensors) {
    sensors_.push_back(registry_.MakeSensor(*s.loaded, s.params));
    agents_.sensors.push_back({s.loaded->descriptor->name, sensors_.back().get()});
  }
}

std::string RowInstance::UnmetSensorNeed() const {
  for (const auto& needed : robot_->Needs().sensors) {
    const bool have =
        std::any_of(row_.sensors.begin(), row_.sensors.end(),
                    [&](const PluginUse& s) { return s.loaded->descriptor->name == needed; });
    if (!have) return "policy '" + row_.policy.plugin + "' needs the sensor '" + needed + "'";
  }
  return "";
}

std::string RowInstance::UnmetKinematicsNeed() const {
  const std::string refusal = KinematicsRefusal(robot_->Needs(), row_.kinematics);
  return refusal.empty() ? "" : "policy '" + row_.policy.plugin + "' " + refusal;
}

std::string RowInstance::HumansNeedRobotOnly() const {
  if (humans_.empty() || row_.humans.count_max <= 0) return "";
  const PolicyNeeds needs = humans_.front()->Needs();
  const std::string who = "the humans' policy '" + row_.humans.policy.plugin + "'";
  if (!needs.sensors.empty()) {
    return who + " needs the sensor '" + needs.sensors.front() + "', which only the robot is given";
  }
  if (needs.lookahead) return who + " needs the lookahead, which only the robot is given";
  return "";
}

const EpisodeAgents& RowInstance::Agents(size_t humans) {
  while (humans_.size() < humans) {
    humans_.push_back(registry_.MakePolicy(*row_.humans.policy.loaded, row_.humans.policy.params));
    agents_.humans.push_back(humans_.back().get());
  }
  return agents_;
}

std::vector<std::pair<std::string, const PluginUse*>> RowPlugins(const RowSpec& row) {
  std::vector<std::pair<std::string, const PluginUse*>> uses = {
      {"policy", &row.policy}, {"humans' policy", &row.humans.policy}, {"world", &row.world}};
  for (const auto& s : row.sensors) uses.push_back({"sensor", &s});
  return uses;
}

bool AllHarnessPlugins(const RowSpec& row) {
  const auto uses = RowPlugins(row);
  return std::all_of(uses.begin(), uses.end(), [](const auto& use) {
    return PluginRegistry::IsHarnessPlugin(*use.second->loaded);
  });
}

bool RowNeedsIsolation(const Suite& suite, const RowSpec& row, IsolationMode mode) {
  if (mode != IsolationMode::kAuto) return mode == IsolationMode::kOn;
  return suite.episode_timeout_s > 0 || !AllHarnessPlugins(row);
}

double IsolatedEpisodeTimeoutS(const Suite& suite) {
  return suite.episode_timeout_s > 0 ? suite.episode_timeout_s : kDefaultEpisodeTimeoutS;
}

ScenarioRequest MakeEpisodeRequest(const Suite& suite, const RowSpec& row, const WorldSource& world,
                                   int episode) {
  ScenarioRequest req;
  req.seed = DeriveSeed(suite.seed, world.Identity(), static_cast<std::uint64_t>(episode));
  req.episode_index = episode;
  req.num_humans = row.humans.count;
  req.goal_mode = row.humans.goal_mode;
  req.sim = suite.sim;
  req.humans = DrawHumanAttributes(row.humans, suite.sim, req.seed, req.num_humans);
  return req;
}

Scenario MakeEpisodeScenario(const Suite& suite, const RowSpec& row, const WorldSource& world,
                             int episode, ScenarioRequest* request) {
  const ScenarioRequest req = MakeEpisodeRequest(suite, row, world, episode);
  Scenario scenario = world.Make(req);
  CheckHumanCount(req, scenario);
  if (request != nullptr) *request = req;
  return scenario;
}

namespace {

/// Plays the episode once in a worker (with episode_timeout_s), so a plugin crash or hang throws
/// here instead of ending the caller. The replay is deterministic: nothing is kept.
void ProbeInWorker(const Suite& suite, size_t row_index, int episode, PluginRegistry& registry) {
  const std::optional<WorkerLoss> lost =
      RunOnceInWorker(IsolatedEpisodeTimeoutS(suite), [&]() -> std::string {
        try {
          ReplayEpisode(suite, row_index, episode, registry, false,
                        /*probe=*/false);
        } catch (const std::exception&) {
          // The replay in the caller's process throws the same, with its message.
        }
        return "done";
      }).loss;
  if (!lost) return;
  if (lost->Interrupted()) {
    throw std::runtime_error("the replay of episode " + std::to_string(episode) + " of row '" +
                             suite.rows[row_index].label +
                             "' was stopped from outside (its "
                             "worker process " +
                             lost->Describe() + ")");
  }
  const std::string status =
      lost->kind == WorkerLoss::Kind::kTimeout ? "policy_timeout" : "policy_crash";
  throw std::runtime_error("episode " + std::to_string(episode) + " of row '" +
                           suite.rows[row_index].label +
                           "' cannot be replayed: a run records it as " + status +
                           " (the worker process that replayed it here: " + lost->Describe() +
                           "); pick another episode, or fix the plugin");
}

}  // namespace

Replay ReplayEpisode(const Suite& suite, size_t row_index, int episode, PluginRegistry& registry,
                     bool record_trajectory, bool probe) {
  if (row_index >= suite.rows.size()) {
    throw std::out_of_range("row " + std::to_string(row_index + 1) +
                            " does not exist; the suite has " + std::to_string(suite.rows.size()) +
                            " rows");
  }
  const RowSpec& row = suite.rows[row_index];
  if (probe && RowNeedsIsolation(suite, row, suite.isolation)) {
    ProbeInWorker(suite, row_index, episode, registry);
  }
  auto world = registry.MakeWorld(*row.world.loaded, row.world.params);
  RowInstance instance(row, registry);
  Replay replay;
  replay.scenario = MakeEpisodeScenario(suite, row, *world, episode);
  Episode ep(replay.scenario, suite.sim, instance.Agents(replay.scenario.humans.size()),
             record_trajectory);
  replay.result = ep.Run();
  return replay;
}

}  // namespace crowdsim
