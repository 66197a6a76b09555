#include "value_rl/value_network.h"

#include <torch/nn/modules/activation.h>
#include <torch/nn/modules/linear.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "crowdsim/sim_config.h"
#include "value_rl/state_encoding.h"

namespace crowdsim::value_rl {

torch::nn::Sequential Mlp(int64_t in, std::initializer_list<int64_t> dims, bool last_relu) {
  torch::nn::Sequential seq;
  int64_t width = in;
  size_t i = 0;
  for (int64_t d : dims) {
    seq->push_back(torch::nn::Linear(width, d));
    if (++i < dims.size() || last_relu) seq->push_back(torch::nn::ReLU());
    width = d;
  }
  return seq;
}

StateBatch MakeBatch(const ValueRlConfig& config, std::span<const EncodedState* const> states) {
  const int64_t b = static_cast<int64_t>(states.size());
  const int lidar = config.LidarInputs();
  const int self_dim = SelfInputs(config);
  int64_t rows = 0;
  for (const auto* s : states) rows = std::max<int64_t>(rows, HumanRows(config, *s));
  std::vector<float> self(b * self_dim), lid(b * lidar), humans(b * rows * kHumanDim, 0.0f);
  std::vector<uint8_t> mask(b * rows, 0);
  for (int64_t i = 0; i < b; ++i) {
    const float* v = states[i]->values.data();
    std::copy(v, v + self_dim, self.data() + i * self_dim);
    std::copy(v + self_dim, v + self_dim + lidar, lid.data() + i * lidar);
    const int n = HumanRows(config, *states[i]);
    std::copy(v + self_dim + lidar, v + self_dim + lidar + n * kHumanDim,
              humans.data() + i * rows * kHumanDim);
    std::fill(mask.begin() + i * rows, mask.begin() + i * rows + n, 1);
  }
  StateBatch batch;
  batch.self = torch::from_blob(self.data(), {b, self_dim}).clone();
  if (lidar > 0) batch.lidar = torch::from_blob(lid.data(), {b, lidar}).clone();
  if (UsesPerson(config.sensors)) {
    batch.humans = torch::from_blob(humans.data(), {b, rows, kHumanDim}).clone();
    batch.mask = torch::from_blob(mask.data(), {b, rows}, torch::kUInt8).to(torch::kBool);
  }
  return batch;
}

torch::Tensor ForwardJoined(torch::nn::Sequential& mlp, const torch::Tensor& state,
                            const torch::Tensor& rows, bool state_first) {
  const auto& first = mlp->ptr<torch::nn::LinearImpl>(0);
  const torch::Tensor& w = first->weight;
  const int64_t s = state.size(1), r = rows.size(2);
  const torch::Tensor w_state = w.narrow(1, state_first ? 0 : r, s);
  const torch::Tensor w_rows = w.narrow(1, state_first ? s : 0, r);
  torch::Tensor x =
      torch::linear(rows, w_rows) + torch::linear(state, w_state, first->bias).unsqueeze(1);
  for (auto it = mlp->begin() + 1; it != mlp->end(); ++it) x = it->forward(x);
  return x;
}

ValueNetwork::ValueNetwork(const ValueRlConfig& config)
    : prior_weight_(config.route_prior),
      prior_shape_(config.route_prior_shape),
      gamma_(SimConfig{}.gamma) {}

/// The route prior, a fixed, exact part of the value computed from the route's path distance d
/// (the first route value, right after the 6 self values); the network learns the rest.
/// Linear: -w d, the same as potential-based reward shaping with potential -w d (Ng et al.
/// 1999, leaves the best policy unchanged); the network must still learn how the value falls
/// with d, now plus w d. Discounted: w gamma^d, the value of following the free route at
/// v_pref (CrowdNav's discount gamma^(t v_pref), t = d / v_pref) to a success reward w, so
/// the network learns only how people, turns and the goal's radius change that value.
torch::Tensor ValueNetwork::WithRoutePrior(const torch::Tensor& value, const StateBatch& b) const {
  if (prior_weight_ == 0.0) return value;
  const torch::Tensor d = b.self.select(1, kSelfDim);
  if (prior_shape_ == RoutePriorShape::kLinear) return value - prior_weight_ * d;
  // gamma 0 (allowed): the log of the smallest double keeps 0^0 = 1 instead of 0 x -inf.
  const double log_gamma = std::log(std::max(gamma_, std::numeric_limits<double>::min()));
  return value + prior_weight_ * torch::exp(d * log_gamma);
}

/// CrowdNav's "masked softmax", exp(s) [s != 0] / sum, no max shift, padded rows masked too.
/// Rows where exp under- or overflows (0/0, inf/inf: scores beyond about +-88, likeliest with
/// one person seen) take the max-shifted softmax instead; the other rows keep CrowdNav's values.
torch::Tensor AttentionWeights(const torch::Tensor& scores, const torch::Tensor& mask) {
  const torch::Tensor valid = scores.ne(0).to(torch::kFloat) * mask;
  torch::Tensor w = torch::exp(scores) * valid;
  w = w / w.sum(1, /*keepdim=*/true);
  if (torch::isfinite(w).all().item<bool>()) return w;
  // Recomputed from scratch so that no inf or NaN stays in the graph (0 x inf in backward).
  const torch::Tensor row_ok = torch::isfinite(w).all(1, /*keepdim=*/true).detach();
  const torch::Tensor plain = torch::where(row_ok, scores, torch::zeros_like(scores));
  torch::Tensor kept = torch::exp(plain) * valid;
  kept = kept / torch::where(row_ok, kept.sum(1, true), torch::ones_like(row_ok, torch::kFloat));
  const torch::Tensor shifted = scores.masked_fill(valid.eq(0), -1e30f);
  torch::Tensor stable = torch::softmax(shifted, 1) * valid;
  stable = stable / stable.sum(1, true).clamp_min(std::numeric_limits<float>::min());
  return torch::where(row_ok, kept, stable);
}

namespace {

/// The last layer of an Mlp (a Linear: Mlp's last layer has no ReLU after it).
torch::nn::Linear LastLinear(torch::nn::Sequential& mlp) {
  auto last = std::dynamic_pointer_cast<torch::nn::LinearImpl>(mlp->ptr(mlp->size() - 1));
  if (!last) throw std::logic_error("the value MLP does not end in a Linear layer");
  return torch::nn::Linear(last);
}

/// Self state joined with the lidar feature (when there is a lidar): (B, 6 [+ 3] [+ F]).
class SelfEncoder {
 public:
  SelfEncoder(torch::nn::Module* owner, const ValueRlConfig& c) : dim_(SelfInputs(c)) {
    if (UsesLidar(c.sensors)) {
      lidar_ = owner->register_module(
          "lidar", Mlp(c.lidar_beams, {c.lidar_hidden, c.lidar_features}, /*last_relu=*/true));
      dim_ += c.lidar_features;
    }
  }
  int64_t dim() const { return dim_; }
  torch::Tensor operator()(const StateBatch& b) {
    if (lidar_.is_empty()) return b.self;
    return torch::cat({b.self, lidar_->forward(b.lidar)}, 1);
  }

 private:
  torch::nn::Sequential lidar_{nullptr};
  int64_t dim_;
};

/// CADRL: one value per (robot, human) pair, the minimum over humans.
class Cadrl final : public ValueNetwork {
 public:
  explicit Cadrl(const ValueRlConfig& c)
      : ValueNetwork(c), self_(this, c), humans_(UsesPerson(c.sensors)) {
    mlp_ = register_module("mlp",
                           Mlp(self_.dim() + (humans_ ? kHumanDim : 0), {150, 100, 100, 1}, false));
  }

  torch::Tensor Forward(const StateBatch& b) override {
    torch::Tensor s = self_(b);
    if (!humans_) return WithRoutePrior(mlp_->forward(s).squeeze(1), b);
    torch::Tensor v = ForwardJoined(mlp_, s, b.humans, /*state_first=*/true).squeeze(2);
    v = v.masked_fill(b.mask.logical_not(), std::numeric_limits<float>::infinity());
    return WithRoutePrior(std::get<0>(v.min(1)), b);
  }
  torch::nn::Linear OutputLayer() override { return LastLinear(mlp_); }

 private:
  SelfEncoder self_;
  bool humans_;
  torch::nn::Sequential mlp_{nullptr};
};

/// SARL: per-human embeddings, attention with the mean embedding, crowd feature + self state.
class Sarl final : public ValueNetwork {
 public:
  explicit Sarl(const ValueRlConfig& c)
      : ValueNetwork(c), self_(this, c), humans_(UsesPerson(c.sensors)) {
    if (humans_) {
      mlp1_ = register_module("mlp1", Mlp(SelfInputs(c) + kHumanDim, {150, 100}, true));
      mlp2_ = register_module("mlp2", Mlp(100, {100, 50}, false));
      attention_ = register_module("attention", Mlp(200, {100, 100, 1}, false));
    }
    mlp3_ =
        register_module("mlp3", Mlp(self_.dim() + (humans_ ? 50 : 0), {150, 100, 100, 1}, false));
  }

  torch::Tensor Forward(const StateBatch& b) override {
    torch::Tensor joint = self_(b);
    if (humans_) {
      // The humans' rows carry the plain self state, as CrowdNav's 13-value rows do.
      torch::Tensor e =
          ForwardJoined(mlp1_, b.self, b.humans, /*state_first=*/true);  // (B, N, 100)
      torch::Tensor h = mlp2_->forward(e);                               // (B, N, 50)
      torch::Tensor m = b.mask.to(torch::kFloat).unsqueeze(2);
      torch::Tensor global = (e * m).sum(1) / m.sum(1).clamp_min(1.0);
      // Attention on cat({e, global}): the mean embedding is the per-state part.
      torch::Tensor scores = ForwardJoined(attention_, global, e, /*state_first=*/false).squeeze(2);
      torch::Tensor w = AttentionWeights(scores, m.squeeze(2));
      torch::Tensor crowd = (w.unsqueeze(2) * h).sum(1);
      joint = torch::cat({joint, crowd}, 1);
    }
    return WithRoutePrior(mlp3_->forward(joint).squeeze(1), b);
  }
  torch::nn::Linear OutputLayer() override { return LastLinear(mlp3_); }

 private:
  SelfEncoder self_;
  bool humans_;
  torch::nn::Sequential mlp1_{nullptr}, mlp2_{nullptr}, attention_{nullptr}, mlp3_{nullptr};
};

}  // namespace

std::shared_ptr<ValueNetwork> MakeValueNetwork(const ValueRlConfig& config) {
  if (config.model == Model::kCadrl) return std::make_shared<Cadrl>(config);
  return std::make_shared<Sarl>(config);
}

void CopyParameters(const ValueNetwork& from, ValueNetwork* to) {
  torch::NoGradGuard no_grad;
  const auto src = from.named_parameters();
  for (auto& p : to->named_parameters()) p.value().copy_(src[p.key()]);
}

int64_t ParameterCount(const ValueNetwork& net) {
  int64_t n = 0;
  for (const auto& p : net.parameters()) n += p.numel();
  return n;
}

}  // namespace crowdsim::value_rl
