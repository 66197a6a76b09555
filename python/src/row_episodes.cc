#include "row_episodes.h"

#include <stdexcept>
#include <string>

namespace crowdsim::python {

RowEpisodes::RowEpisodes(const Suite& suite, const RowSpec& row, PluginRegistry& registry)
    : suite_(suite),
      row_(row),
      world_(registry.MakeWorld(*row.world.loaded, row.world.params)),
      instance_(std::make_unique<RowInstance>(row, registry)),
      policy_(dynamic_cast<PythonPolicy*>(&instance_->robot())) {
  if (policy_ == nullptr)
    throw std::logic_error("RowEpisodes: the row's robot is not the Python policy");
  instance_->Agents(static_cast<size_t>(row.humans.count));
  if (const std::string unmet = instance_->HumansNeedRobotOnly(); !unmet.empty()) {
    throw std::invalid_argument(unmet + "; " + kPlainHumansPolicy);
  }
}

const Observation& RowEpisodes::Reset(int episode, bool record) {
  if (episode < 0)
    throw std::invalid_argument("episode must be >= 0, got " + std::to_string(episode));
  episode_.reset();
  try {
    scenario_ = MakeEpisodeScenario(suite_, row_, *world_, episode);
    CheckScenario(scenario_, suite_.sim);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument("episode " + std::to_string(episode) + ": " + e.what());
  }
  episode_ = std::make_unique<Episode>(scenario_, suite_.sim,
                                       instance_->Agents(scenario_.humans.size()), record);
  episode_index_ = episode;
  return episode_->ObserveRobot();
}

StepInfo RowEpisodes::Step(const Vec2& velocity) {
  policy_->SetNextVelocity(velocity);
  return episode_->Step();
}

}  // namespace crowdsim::python
