#include "crowdsim/bench/row_instance.h"

#include <algorithm>
#include <stdexcept>

#include "crowdsim/rng.h"

namespace crowdsim {

RowInstance::RowInstance(const RowSpec& row, PluginRegistry& registry)
    : row_(row), registry_(registry) {
  robot_ = registry_.MakePolicy(*row_.policy.loaded, row_.policy.params);
  agents_.robot = robot_.get();
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

const EpisodeAgents& RowInstance::Agents(size_t humans) {
  while (humans_.size() < humans) {
    humans_.push_back(registry_.MakePolicy(*row_.humans.policy.loaded, row_.humans.policy.params));
    agents_.humans.push_back(humans_.back().get());
  }
  return agents_;
}

ScenarioRequest MakeEpisodeRequest(const Suite& suite, const RowSpec& row, const WorldSource& world,
                                   int episode) {
  ScenarioRequest req;
  req.seed = DeriveSeed(suite.seed, world.Identity(), static_cast<std::uint64_t>(episode));
  req.episode_index = episode;
  req.num_humans = row.humans.count;
  req.goal_mode = row.humans.goal_mode;
  req.sim = suite.sim;
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

Replay ReplayEpisode(const Suite& suite, size_t row_index, int episode, PluginRegistry& registry,
                     bool record_trajectory) {
  if (row_index >= suite.rows.size()) {
    throw std::out_of_range("row " + std::to_string(row_index + 1) +
                            " does not exist; the suite has " + std::to_string(suite.rows.size()) +
                            " rows");
  }
  const RowSpec& row = suite.rows[row_index];
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
