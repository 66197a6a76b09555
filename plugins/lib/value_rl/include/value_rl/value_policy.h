// The value-based robot policy shared by the `cadrl` and `sarl` plugins: one-step lookahead
// over a discrete holonomic action space, the best r + gamma^(dt v_pref) V(s') (CrowdNav's
// predict), and the Trainable side the harness's trainer drives. No libtorch in this header.
#pragma once

#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "crowdsim/params.h"
#include "crowdsim/policy.h"
#include "crowdsim/trainable.h"
#include "value_rl/config.h"

namespace crowdsim::value_rl {

class ValuePolicy final : public Policy, public Trainable {
 public:
  /// Action values closer than this to the best one are ties, which go to the earliest action.
  static constexpr float kTieTolerance = 1e-5f;

  /// From validated plugin parameters (loads `weights` when given).
  ValuePolicy(Model model, const Params& params);
  /// From a configuration (tests, benchmarks).
  explicit ValuePolicy(const ValueRlConfig& config);
  ~ValuePolicy() override;

  PolicyNeeds Needs() const override;
  void Reset(const EpisodeContext& ctx) override;
  Action Decide(const Observation& obs) override;

  std::string Describe() const override;
  void InitWeights(std::uint64_t seed) override;
  EncodedState Encode(const Observation& obs) const override;
  void SetExploration(const Exploration& exploration) override;
  void SetLearningRate(double learning_rate, double momentum) override;
  double TrainBatch(std::span<const EncodedState* const> states,
                    std::span<const float> targets) override;
  std::vector<float> TargetValues(std::span<const EncodedState* const> states) override;
  void UpdateTargetNetwork() override;
  void SaveWeights(const std::filesystem::path& file) const override;
  void LoadWeights(const std::filesystem::path& file) override;
  void SaveTrainingState(const std::filesystem::path& dir) const override;
  void LoadTrainingState(const std::filesystem::path& dir) override;

  const ValueRlConfig& config() const;
  /// The model's values of `states`, one batch (no gradients).
  std::vector<float> Values(std::span<const EncodedState* const> states) override;
  /// r + gamma^(dt v_pref) V(s') of every candidate at the last lookahead decision.
  const std::vector<float>& last_action_values() const;
  /// Trainable scalars of the model.
  std::int64_t ParameterCount() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

/// Index of the earliest of `values` within ValuePolicy::kTieTolerance of the largest: BLAS
/// kernels give the rows of one batch (and different CPUs the same row) values that differ in
/// the last bits, so exact comparison would let a CPU's kernel choice break ties.
size_t EarliestBest(std::span<const float> values);

/// The plugin factory of both plugins.
std::unique_ptr<Policy> MakeValuePolicy(Model model, const Params& params);

}  // namespace crowdsim::value_rl
