// What a learnable policy implements beside Policy, so the generic trainer can train it without
// knowing its network or library.
#pragma once

#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <vector>

#include "crowdsim/export.h"
#include "crowdsim/observation.h"

namespace crowdsim {

/// One state as the value network sees it: opaque to the harness, stored as is.
struct CROWDSIM_SDK_API EncodedState {
  std::vector<float> values;
};

/// How Decide explores while the trainer collects RL episodes.
struct CROWDSIM_SDK_API Exploration {
  double epsilon = 0.0;    ///< probability in [0, 1] of a random action at a step; 0 = greedy
  std::uint64_t seed = 0;  ///< of the stream the random draws come from
  /// Explore among actions the lookahead shows not colliding (all if each collides); false: among
  /// all (CrowdNav).
  bool avoid_collisions = false;
};

/// Implemented by value-based robot policies; the host finds it by dynamic_cast from Policy.
class CROWDSIM_SDK_API Trainable {
 public:
  virtual ~Trainable();

  /// Model, sensors and sizes in one line (logs, checkpoint checks).
  virtual std::string Describe() const = 0;
  /// Fresh weights from `seed` (model and target network equal); the same seed gives the
  /// same weights.
  virtual void InitWeights(std::uint64_t seed) = 0;
  /// The state of a robot observation (the one its Decide saw), encoded for the network.
  virtual EncodedState Encode(const Observation& obs) const = 0;
  /// Epsilon-greedy exploration in Decide (`Exploration`); epsilon 0 = greedy.
  virtual void SetExploration(const Exploration& exploration) = 0;
  /// Starts a new optimiser with this learning rate (CrowdNav: a new SGD per phase).
  virtual void SetLearningRate(double learning_rate, double momentum) = 0;
  /// One optimiser step on the mean squared error of the model's values; returns the loss.
  virtual double TrainBatch(std::span<const EncodedState* const> states,
                            std::span<const float> targets) = 0;
  /// Values of the target network for `states` (one batch), in order.
  virtual std::vector<float> TargetValues(std::span<const EncodedState* const> states) = 0;
  /// Values of the model (the network being trained) for `states`, in order (diagnostics).
  virtual std::vector<float> Values(std::span<const EncodedState* const> states) = 0;
  /// Target network = copy of the model.
  virtual void UpdateTargetNetwork() = 0;

  /// The model's weights with their metadata (the file a suite's `weights` names).
  virtual void SaveWeights(const std::filesystem::path& file) const = 0;
  /// Loads SaveWeights' file; throws std::runtime_error naming the file and mismatch (model,
  /// sensors, size).
  virtual void LoadWeights(const std::filesystem::path& file) = 0;
  /// Everything besides the weights that resuming needs (optimiser, target network), as
  /// files inside the existing folder `dir`.
  virtual void SaveTrainingState(const std::filesystem::path& dir) const = 0;
  /// Restores what SaveTrainingState wrote (after LoadWeights of the same checkpoint).
  virtual void LoadTrainingState(const std::filesystem::path& dir) = 0;
};

}  // namespace crowdsim
