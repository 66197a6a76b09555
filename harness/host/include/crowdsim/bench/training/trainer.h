// The generic trainer behind `crowdsim-bench train`: imitation learning from a teacher robot
// policy, then epsilon-greedy RL with TD(0) targets from a target network and a replay
// memory (CrowdNav's procedure, the paper's settings). It drives any policy whose object is
// also a Trainable; it never sees the network or its library.
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

/// A training refused before it did anything: --resume without a checkpoint or with another
/// configuration, a folder that already holds a training. The CLI exits 2 for it.
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
  /// Tests: write a checkpoint and return after this many episodes (demonstrations + RL) of
  /// this call, as an interruption would; -1 = run to the end.
  int stop_after_episodes = -1;
  /// Called with (out_dir, training name) after every checkpoint and at the end, once the logs
  /// are flushed (the CLI draws the learning curve there; the core links no figure library).
  /// An exception it throws is reported as a warning and training goes on.
  std::function<void(const std::filesystem::path&, const std::string&)> on_files_flushed;
};

/// One validation pass (greedy, fixed scenarios).
struct ValidationResult {
  int episode = 0;  ///< RL episodes done when it ran
  double success = 0, collision = 0, timeout = 0;
  double nav_time = 0;  ///< s, mean over successes (time_limit if none)
  /// Mean value the model gives a fixed set of probe states (taken from the demonstrations
  /// once they end): drifts show the values collapsing or inflating; NaN before there is one.
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

/// What `validate` checks of a training file, without training: the learner, its sensors, the
/// teacher and the world made as `train` makes them (a policy that cannot be trained, a missing
/// weights file), the first scenario of each episode stream (a floor plan without training
/// pairs), and the first step of the first episode with the teacher and with the learner at
/// its initial weights (a sensor that does not fit the learner's input). Throws TrainRefused.
void PreflightTraining(const TrainSpec& spec, PluginRegistry& registry);

/// The folder holds a finished training of exactly this configuration (its summary.json says
/// finished, with spec's config hash): a campaign skips it. A finished training whose file now
/// asks for more RL episodes is not (it resumes and goes on).
bool IsFinishedTraining(const std::filesystem::path& out_dir, const TrainSpec& spec);

/// The folder holds a checkpoint to resume from (also one left as checkpoint.tmp by a crash).
bool HasCheckpoint(const std::filesystem::path& out_dir);

/// Epsilon of RL episode `episode`: linear from start to end over `decay` episodes, then end.
double Epsilon(const TrainingSettings& t, int episode);

}  // namespace crowdsim::training
