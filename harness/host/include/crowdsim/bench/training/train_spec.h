// A training file: a suite row's spec (the policy to train with its sensors, the world and
// humans it trains among; read by the suite's row reader, with its defaults) at the top level,
// plus a `training:` block with the imitation + RL settings (paper / CrowdNav defaults).
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

/// The `training:` keys. Defaults: CrowdNav's train.config with the paper's epsilon, i.e. the
/// paper's literal procedure; the training files under suites/train/ name the procedure that
/// learns (docs/training.md).
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
  /// Read by the suite's row reader: the learner (`row.policy`, e.g. cadrl or sarl) with its
  /// sensors, the world (its train split) and the humans, drawn per episode in
  /// [`row.humans.count`, `row.humans.count_max`].
  RowSpec row;
  PluginUse teacher;  ///< imitation-learning robot (`training.il_policy`)
  TrainingSettings training;
  /// Everything that decides the trained weights; its hash guards --resume.
  std::string canonical;
  std::string ConfigHash() const;
  /// The hash this training would have with another RL length: --resume accepts a checkpoint
  /// that differs only there, so a finished or running training can be lengthened (or
  /// shortened, down to the episodes already done).
  std::string ConfigHashWithRlEpisodes(int rl_episodes) const;
};

struct TrainSpecLoadResult {
  std::optional<TrainSpec> spec;
  std::vector<SuiteError> errors;  ///< every error found (empty when spec is set)
};

/// Reads and validates a training file; loads the plugins it names to check parameters.
/// `overrides` (`key.path=value`, as `train --set` takes them) edit the file's document first.
TrainSpecLoadResult LoadTrainSpec(const std::filesystem::path& file, PluginRegistry& registry,
                                  const std::vector<std::string>& overrides = {});

/// `train --seed N`: the same training with another seed (weights, scenarios, exploration,
/// batches); the canonical text and so the config hash follow.
void OverrideSeed(TrainSpec& spec, std::uint64_t seed);

/// Problems that do not stop a training but likely spoil it (e.g. an epsilon decay longer
/// than the RL phase), one sentence each.
std::vector<std::string> TrainSpecWarnings(const TrainSpec& spec);

/// The keys of the canonical text's "training:" line, whose values it writes without names
/// in this order (kept so that the config hashes of committed models stay valid); messages
/// about a changed configuration name them.
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
