// A training file: a row spec at top level (learner, sensors, world, humans) plus a `training:`
// block (paper / CrowdNav defaults).
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "crowdsim/bench/plugin_registry.h"
#include "crowdsim/bench/suite.h"
#include "crowdsim/sim_config.h"

namespace crowdsim::training {

/// What the RL phase does with an episode that ran out of time (`store_timeouts`).
enum class StoreTimeouts {
  kOff,        ///< not stored (CrowdNav, the paper): wandering never meets its consequence
  kTerminal,   ///< stored like a collision: the last transition's target is its own reward
  kBootstrap,  ///< stored as a truncation: the last target bootstraps from the state reached
};
const char* ToString(StoreTimeouts s);

/// Which random actions the RL phase's epsilon-greedy exploration draws from (`exploration`).
enum class ExplorationRule {
  kUniform,        ///< any action (CrowdNav, the paper)
  kCollisionFree,  ///< those the one-step lookahead does not show colliding (docs/training.md)
};
const char* ToString(ExplorationRule e);

/// The `training:` keys. Defaults: CrowdNav's train.config with the paper's epsilon; suites/train/
/// holds procedures that learn.
struct TrainingSettings {
  int il_episodes = 3000;  ///< demonstrations of the teacher
  int il_epochs = 50;      ///< passes over the memory after the demonstrations
  double il_learning_rate = 0.01;
  int rl_episodes = 10000;
  double rl_learning_rate = 0.001;
  double momentum = 0.9;       ///< SGD momentum (both phases)
  double epsilon_start = 0.9;  ///< paper: linear 0.9 -> 0.5 over the first 5k episodes
  double epsilon_end = 0.5;
  int epsilon_decay_episodes = 5000;
  int target_update_interval = 50;  ///< RL episodes between target network copies
  int capacity = 100000;            ///< replay memory size
  int batch_size = 100;
  int train_batches = 100;         ///< SGD steps after each RL episode
  int validation_interval = 1000;  ///< RL episodes between validations (0: none)
  int validation_episodes = 100;
  int checkpoint_interval = 500;  ///< episodes between checkpoints
  StoreTimeouts store_timeouts = StoreTimeouts::kOff;
  ExplorationRule exploration = ExplorationRule::kUniform;
};

/// A validated training file: a row spec (what trains, among what) plus a `training:` block.
struct TrainSpec {
  std::string name;
  std::string description;
  std::filesystem::path file;
  std::uint64_t seed = 0;
  SimConfig sim;
  /// The learner (`row.policy`), sensors, world (train split) and humans, drawn per episode in
  /// [`row.humans.count`, `row.humans.count_max`].
  RowSpec row;
  PluginUse teacher;  ///< imitation-learning robot (`training.il_policy`)
  TrainingSettings training;
  /// Everything that decides the trained weights; its hash guards --resume.
  std::string canonical;
  std::string ConfigHash() const;
  /// The hash with another RL length: --resume accepts checkpoints differing only there, so
  /// trainings can be lengthened or shortened.
  std::string ConfigHashWithRlEpisodes(int rl_episodes) const;
};

struct TrainSpecLoadResult {
  std::optional<TrainSpec> spec;
  std::vector<SuiteError> errors;  ///< every error found (empty when spec is set)
};

/// Reads and validates a training file, loading its plugins. `overrides` (`train --set`) apply
/// first.
TrainSpecLoadResult LoadTrainSpec(const std::filesystem::path& file, PluginRegistry& registry,
                                  const std::vector<std::string>& overrides = {});

/// `train --seed N`: the same training with another seed; canonical text and hash follow.
void OverrideSeed(TrainSpec& spec, std::uint64_t seed);

/// Problems that likely spoil a training without stopping it (e.g. epsilon decay beyond RL).
std::vector<std::string> TrainSpecWarnings(const TrainSpec& spec);

/// Keys of the canonical "training:" line's unnamed values, in fixed order (committed models'
/// hashes depend on it); messages name them.
inline const std::vector<std::string> kTrainingLineFields = {"il_episodes",
                                                             "il_epochs",
                                                             "il_learning_rate",
                                                             "rl_episodes",
                                                             "rl_learning_rate",
                                                             "momentum",
                                                             "epsilon_start",
                                                             "epsilon_end",
                                                             "epsilon_decay_episodes",
                                                             "target_update_interval",
                                                             "capacity",
                                                             "batch_size",
                                                             "train_batches",
                                                             "validation_interval",
                                                             "validation_episodes"};

}  // namespace crowdsim::training
