// The value networks of CrowdNav (reference 1.7) with this project's lidar encoder. Private
// to value_rl: the only header of the plugins that includes libtorch.
#pragma once

#include <torch/nn/module.h>
#include <torch/nn/modules/container/sequential.h>
#include <torch/nn/modules/linear.h>

#include <memory>
#include <span>

#include "crowdsim/trainable.h"
#include "value_rl/config.h"

namespace crowdsim::value_rl {

/// A batch of encoded states as tensors. Person models have at least one human row per
/// state; states with fewer rows than the widest are padded and masked out.
struct StateBatch {
  torch::Tensor self;    ///< (B, 6)
  torch::Tensor lidar;   ///< (B, L) ranges / max_range; undefined without lidar
  torch::Tensor humans;  ///< (B, N, 7); undefined without the person sensor
  torch::Tensor mask;    ///< (B, N) bool, true for real rows
};

/// Packs encoded states (one tensor copy per field).
StateBatch MakeBatch(const ValueRlConfig& config, std::span<const EncodedState* const> states);

/// Linear layers of the given widths with a ReLU after each but the last (CrowdNav's mlp()).
torch::nn::Sequential Mlp(int64_t in, std::initializer_list<int64_t> dims, bool last_relu);

/// `mlp` applied to rows that join a per-state part (B, S), the same for every row of a state,
/// and a per-row part (B, N, R): mlp(cat({state broadcast over N, rows}, 2)), or with the
/// rows first when `state_first` is false, without building the joined rows: the first
/// layer's weight splits into the state's columns, applied once per state, and the rows'
/// columns. Same parameters (and weights files) as the plain MLP, fewer operations.
torch::Tensor ForwardJoined(torch::nn::Sequential& mlp, const torch::Tensor& state,
                            const torch::Tensor& rows, bool state_first);

/// SARL's attention weights over people (B, N) from their scores and the mask of real rows:
/// CrowdNav's masked softmax, max-shifted in rows where it would under- or overflow to NaN.
torch::Tensor AttentionWeights(const torch::Tensor& scores, const torch::Tensor& mask);

/// State value network: V(batch) -> (B), the route prior of its configuration included.
class ValueNetwork : public torch::nn::Module {
 public:
  /// The network's value of each state of the batch.
  virtual torch::Tensor Forward(const StateBatch& batch) = 0;
  /// The run's discount (SimConfig::gamma, per metre at v_pref), which the discounted route
  /// prior uses; set by ValuePolicy::Reset. Default: SimConfig's.
  void SetDiscount(double gamma) { gamma_ = gamma; }
  /// The layer that gives the network's output (before the route prior).
  virtual torch::nn::Linear OutputLayer() = 0;

 protected:
  explicit ValueNetwork(const ValueRlConfig& config);
  /// `value` (B) with the configuration's route prior added; unchanged without one.
  torch::Tensor WithRoutePrior(const torch::Tensor& value, const StateBatch& b) const;

 private:
  double prior_weight_;
  RoutePriorShape prior_shape_;
  double gamma_;
};

/// The network of `config` (CADRL or SARL, with or without lidar / humans), default init.
std::shared_ptr<ValueNetwork> MakeValueNetwork(const ValueRlConfig& config);

/// Copies every parameter of `from` into `to` (same configuration).
void CopyParameters(const ValueNetwork& from, ValueNetwork* to);

/// Number of trainable scalars.
int64_t ParameterCount(const ValueNetwork& net);

}  // namespace crowdsim::value_rl
