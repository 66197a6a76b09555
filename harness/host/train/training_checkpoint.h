// The trainer's checkpoint part (phase, counters, validation history), as text; other parts are
// saved by their owners.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "crowdsim/bench/training/trainer.h"

namespace crowdsim::training {

enum class TrainPhase { kDemonstrations, kImitation, kReinforcement, kDone };

struct CheckpointState {
  std::string config_hash;
  TrainPhase phase = TrainPhase::kDemonstrations;
  int counter = 0;  ///< episodes (demonstrations, RL) or epochs (imitation) done in `phase`
  double best_success = -1.0;  ///< best validation success so far (-1: none)
  int best_episode = -1;
  std::int64_t episode_log_bytes = -1;  ///< flushed size of training_episodes.csv (-1: none)
  int rl_episodes = -1;  ///< the RL length the training ran toward (-1: not recorded, before v4)
  std::vector<ValidationResult> validations;
};

void WriteCheckpointState(const std::filesystem::path& file, const CheckpointState& state);
/// Throws TrainError on a damaged file.
CheckpointState ReadCheckpointState(const std::filesystem::path& file);

/// The validation history as CSV (training_log.csv).
std::string ValidationCsv(const std::vector<ValidationResult>& validations);

}  // namespace crowdsim::training
