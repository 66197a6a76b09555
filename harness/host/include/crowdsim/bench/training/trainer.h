// The generic trainer behind `crowdsim-bench train`: imitation, then epsilon-greedy RL with TD(0),
// target network and replay memory (CrowdNav). Drives any Trainable policy.
#pragma once

#include <filesystem>
#include <functional>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "crowdsim/bench/plugin_registry.h"
#include "crowdsim/bench/training/train_spec.h"

namespace crowdsim::training {

/// Stops the whole training (bad configuration, failing policy, unreadable checkpoint).
class TrainError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// A training refused before starting (bad --resume, a folder holding a training). The CLI exits 2.
class TrainRefused : public TrainError {
 public:
  using TrainError::TrainError;
};

/// Thrown after SIGINT / SIGTERM once the checkpoint is written.
class TrainingInterrupted : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct TrainOptions {
  std::filesystem::path out_dir;  ///< default: results/train/<name>/
  bool resume = false;            ///< continue from out_dir/checkpoint
  bool progress = true;           ///< progress line on stderr
  /// Tests: checkpoint and return after this many episodes, as if interrupted; -1: run to the end.
  int stop_after_episodes = -1;
  /// Called with (out_dir, name) after each checkpoint and at the end (the CLI draws the curve; the
  /// core links no figure library). Its exceptions only warn.
  std::function<void(const std::filesystem::path&, const std::string&)> on_files_flushed;
};

/// One validation pass (greedy, fixed scenarios).
struct ValidationResult {
  int episode = 0;  ///< RL episodes done when it ran
  double success = 0, collision = 0, timeout = 0;
  double nav_time = 0;  ///< s, mean over successes (time_limit if none)
  /// The model's mean value over fixed probe states: drift shows values collapsing or inflating;
  /// NaN before probes.
  double probe_value = std::numeric_limits<double>::quiet_NaN();
};

/// Wall time by activity (profiling).
struct TrainTimes {
  double demonstrations = 0;  ///< teacher episodes
  double imitation = 0;       ///< IL epochs
  double rl_episodes = 0;     ///< learner episodes (lookahead and value evaluation)
  double rl_targets = 0;      ///< TD targets from the target network
  double rl_updates = 0;      ///< SGD steps
  double validation = 0;
  double checkpoints = 0;
};

struct TrainSummary {
  std::filesystem::path out_dir;
  std::filesystem::path weights;       ///< last weights (weights.pt)
  std::filesystem::path best_weights;  ///< best validation (best.pt), empty without validation
  bool finished = false;               ///< false when stopped by stop_after_episodes
  int episodes_run = 0;                ///< this call, demonstrations + RL
  std::vector<ValidationResult> validations;
  TrainTimes times;
  double wall_seconds = 0;
};

/// Runs (or resumes) a training. Throws TrainError, or TrainingInterrupted on a signal.
TrainSummary RunTraining(const TrainSpec& spec, PluginRegistry& registry,
                         const TrainOptions& options);

/// `validate` for a training file: builds what `train` builds, draws each stream's first scenario,
/// steps teacher and untrained learner once. Throws TrainRefused.
void PreflightTraining(const TrainSpec& spec, PluginRegistry& registry);

/// The folder holds a finished training of this configuration, so a campaign skips it (more RL
/// episodes asked: it resumes).
bool IsFinishedTraining(const std::filesystem::path& out_dir, const TrainSpec& spec);

/// The folder holds a checkpoint to resume from (also one left as checkpoint.tmp by a crash).
bool HasCheckpoint(const std::filesystem::path& out_dir);

/// Epsilon of RL episode `episode`: linear from start to end over `decay` episodes, then end.
double Epsilon(const TrainingSettings& t, int episode);

}  // namespace crowdsim::training
