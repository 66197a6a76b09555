#include "value_rl/value_policy.h"

#include <ATen/Parallel.h>
#include <c10/core/InferenceMode.h>
#include <dlfcn.h>
#include <malloc.h>
#include <torch/nn/modules/linear.h>
#include <torch/optim/sgd.h>
#include <torch/serialize.h>

#include <cmath>
#include <limits>
#include <mutex>
#include <numbers>
#include <stdexcept>

#include "crowdsim/lookahead.h"
#include "crowdsim/rng.h"
#include "value_rl/action_space.h"
#include "value_rl/state_encoding.h"
#include "value_rl/value_network.h"
#include "value_rl/weights_file.h"

namespace crowdsim::value_rl {
namespace fs = std::filesystem;

struct ValuePolicy::Impl {
  explicit Impl(const ValueRlConfig& c) : config(c), rng(0) {}

  ValueRlConfig config;
  std::shared_ptr<ValueNetwork> model;
  std::shared_ptr<ValueNetwork> target;
  std::unique_ptr<torch::optim::SGD> optimizer;
  double learning_rate = 0.0;
  double momentum = 0.0;

  double gamma = 0.9;
  double time_step = SimConfig{}.time_step;  ///< the episode's, s between decisions (Reset)
  Exploration exploration;
  Rng rng;
  double actions_v_pref = -1.0;
  std::vector<Action> actions;
  std::vector<LookaheadOutcome> outcomes;
  std::vector<EncodedState> candidates;
  std::vector<const EncodedState*> candidate_ptrs;
  std::vector<float> action_values;
  std::vector<size_t> safe_actions;  ///< exploration: indices of the non-colliding actions

  void NewNetworks() {
    model = MakeValueNetwork(config);
    target = MakeValueNetwork(config);
    if (optimizer) MakeOptimizer();
  }

  void MakeOptimizer() {
    optimizer = std::make_unique<torch::optim::SGD>(
        model->parameters(), torch::optim::SGDOptions(learning_rate).momentum(momentum));
  }

  std::vector<float> Evaluate(ValueNetwork& net, std::span<const EncodedState* const> states) {
    c10::InferenceMode guard;
    net.eval();
    torch::Tensor v = net.Forward(MakeBatch(config, states)).contiguous();
    const float* p = v.data_ptr<float>();
    return std::vector<float>(p, p + v.numel());
  }
};

ValuePolicy::ValuePolicy(Model model, const Params& params)
    : ValuePolicy(ConfigFromParams(model, params)) {}

namespace {

/// OpenBLAS (libtorch's BLAS on Debian) keeps its own thread pool, which at::set_num_threads
/// does not control. With torch_threads = 1 it gets one thread too: on a busy 2-core machine
/// its spinning threads more than doubled the wall time of a batch-100 SGD step (4.2 ms ->
/// 1.8 ms measured) at the same CPU time. Looked up at run time, because the BLAS behind
/// libblas.so.3 is a Debian alternative and may not be OpenBLAS at all.
void SetBlasThreads(int threads) {
  using SetThreads = void (*)(int);
  for (const char* lib : {"libopenblas.so.0", "libblas.so.3"}) {
    if (void* handle = dlopen(lib, RTLD_LAZY | RTLD_NOLOAD)) {
      auto fn = reinterpret_cast<SetThreads>(dlsym(handle, "openblas_set_num_threads"));
      dlclose(handle);
      if (fn != nullptr) {
        fn(threads);
        return;
      }
    }
  }
}

}  // namespace

/// Every SGD step allocates and frees the same few tensors of a few hundred KB (activations and
/// gradients of 500 human rows). Above glibc's mmap threshold, and with the heap top trimmed
/// back after each step, each of them came from fresh zeroed pages: a batch-100 step of SARL++
/// took 4.1-4.7 ms with a spread of ~0.5-1 ms, 3.0 ms with a spread of 0.01 ms once the memory
/// is kept (learning_bench, docs/training.md). Set once per process; it changes no result.
void KeepFreedMemoryForReuse() {
  static std::once_flag once;
  std::call_once(once, [] {
    constexpr int kBytes = 512 << 20;
    mallopt(M_MMAP_THRESHOLD, kBytes);
    mallopt(M_TRIM_THRESHOLD, kBytes);
  });
}

ValuePolicy::ValuePolicy(const ValueRlConfig& config) : impl_(std::make_unique<Impl>(config)) {
  KeepFreedMemoryForReuse();
  at::set_num_threads(config.torch_threads);
  SetBlasThreads(config.torch_threads);
  impl_->NewNetworks();
  if (config.weights.empty()) {
    InitWeights(config.init_seed);
  } else {
    LoadWeights(config.weights);
  }
}

ValuePolicy::~ValuePolicy() = default;

const ValueRlConfig& ValuePolicy::config() const { return impl_->config; }

PolicyNeeds ValuePolicy::Needs() const {
  PolicyNeeds needs;
  needs.lookahead = true;
  needs.sensors = SensorPlugins(impl_->config);
  // Holonomic actions reach a unicycle robot through turn-then-go tracking (docs/kinematics.md).
  needs.non_holonomic = impl_->config.unicycle_actions ? NonHolonomicDrive::kCommands
                                                       : NonHolonomicDrive::kTrackVelocity;
  return needs;
}

void ValuePolicy::Reset(const EpisodeContext& ctx) {
  if (impl_->config.unicycle_actions && ctx.role == AgentRole::kRobot &&
      ctx.kinematics.Holonomic()) {
    throw std::runtime_error(std::string(ModelName(impl_->config.model)) +
                             ": action_space unicycle turns a heading a holonomic robot does not "
                             "have; give the row `kinematics: unicycle` or use holonomic actions");
  }
  if (impl_->config.unicycle_actions && ctx.role == AgentRole::kRobot &&
      impl_->config.rotation_samples > 1 &&
      std::numbers::pi / 4.0 > ctx.kinematics.angular_speed_max * ctx.sim.time_step * (1 + 1e-12)) {
    throw std::runtime_error(std::string(ModelName(impl_->config.model)) +
                             ": action_space unicycle turns up to 45 degrees per step, " +
                             std::to_string(std::numbers::pi / 4.0 / ctx.sim.time_step) +
                             " rad/s at this time_step, more than the robot's angular_speed_max " +
                             std::to_string(ctx.kinematics.angular_speed_max) +
                             " rad/s: raise angular_speed_max, or lengthen time_step");
  }
  if (impl_->time_step != ctx.sim.time_step) impl_->actions_v_pref = -1.0;  // rotations per step
  impl_->gamma = ctx.sim.gamma;
  impl_->time_step = ctx.sim.time_step;
  impl_->model->SetDiscount(ctx.sim.gamma);
  impl_->target->SetDiscount(ctx.sim.gamma);
}

Action ValuePolicy::Decide(const Observation& obs) {
  Impl& m = *impl_;
  if (obs.lookahead == nullptr) {
    throw std::runtime_error(std::string(ModelName(m.config.model)) +
                             ": no lookahead in the observation (robot policies only)");
  }
  if (m.actions_v_pref != obs.self.v_pref) {
    m.actions = m.config.unicycle_actions
                    ? BuildUnicycleActionSpace(m.config.speed_samples, m.config.rotation_samples,
                                               m.config.stop_action, obs.self.v_pref, m.time_step)
                    : BuildActionSpace(m.config.speed_samples, m.config.rotation_samples,
                                       m.config.stop_action, obs.self.v_pref);
    m.actions_v_pref = obs.self.v_pref;
  }
  if (m.exploration.epsilon > 0.0 && m.rng.Uniform() < m.exploration.epsilon) {
    m.action_values.clear();
    if (!m.exploration.avoid_collisions) return m.actions[m.rng.Below(m.actions.size())];
    obs.lookahead->Evaluate(m.actions, &m.outcomes);
    m.safe_actions.clear();
    for (size_t k = 0; k < m.outcomes.size(); ++k) {
      const StepEvent e = m.outcomes[k].event;
      if (e != StepEvent::kCollisionHuman && e != StepEvent::kCollisionObstacle)
        m.safe_actions.push_back(k);
    }
    if (m.safe_actions.empty()) return m.actions[m.rng.Below(m.actions.size())];
    return m.actions[m.safe_actions[m.rng.Below(m.safe_actions.size())]];
  }
  obs.lookahead->Evaluate(m.actions, &m.outcomes);
  m.candidates.resize(m.outcomes.size());
  m.candidate_ptrs.resize(m.outcomes.size());
  for (size_t k = 0; k < m.outcomes.size(); ++k) {
    const LookaheadOutcome& o = m.outcomes[k];
    m.candidates[k] = EncodeState(m.config, o.robot, o.frame, o.readings);
    m.candidate_ptrs[k] = &m.candidates[k];
  }
  const std::vector<float> next = m.Evaluate(*m.model, m.candidate_ptrs);
  const double discount = std::pow(m.gamma, m.time_step * obs.self.v_pref);
  m.action_values.resize(next.size());
  for (size_t k = 0; k < next.size(); ++k) {
    m.action_values[k] = static_cast<float>(m.outcomes[k].reward + discount * next[k]);
  }
  return m.actions[EarliestBest(m.action_values)];
}

size_t EarliestBest(std::span<const float> values) {
  float top = -std::numeric_limits<float>::infinity();
  for (float v : values) top = std::max(top, v);
  size_t best = 0;
  while (best + 1 < values.size() && values[best] < top - ValuePolicy::kTieTolerance) ++best;
  return best;
}

std::string ValuePolicy::Describe() const {
  const ValueRlConfig& c = impl_->config;
  return std::string(ModelName(c.model)) + " sensors=" + SensorsLabel(c) +
         " actions=" + std::to_string(c.ActionCount()) +
         " lidar_beams=" + std::to_string(c.LidarInputs()) +
         (c.route_prior != 0.0 ? " route_prior=" + std::to_string(c.route_prior) : "") +
         (c.route_prior_shape != RoutePriorShape::kLinear
              ? std::string(" route_prior_shape=") + RoutePriorShapeName(c.route_prior_shape)
              : "") +
         " parameters=" + std::to_string(ParameterCount());
}

void ValuePolicy::InitWeights(std::uint64_t seed) {
  // PyTorch's default Linear init, U(+-1/sqrt(fan_in)) for weights and biases, drawn from the
  // project's portable generator: same weights on every machine and thread, no global state.
  Rng rng(seed);
  torch::NoGradGuard no_grad;
  for (const auto& module : impl_->model->modules(/*include_self=*/false)) {
    auto* linear = module->as<torch::nn::Linear>();
    if (linear == nullptr) continue;
    const double bound = 1.0 / std::sqrt(static_cast<double>(linear->weight.size(1)));
    for (torch::Tensor* t : {&linear->weight, &linear->bias}) {
      float* p = t->data_ptr<float>();
      for (int64_t i = 0; i < t->numel(); ++i)
        p[i] = static_cast<float>(rng.Uniform(-bound, bound));
    }
  }
  if (impl_->config.route_prior_shape == RoutePriorShape::kDiscounted) {
    // The network is a correction to the discounted route prior: it starts at none, so the
    // untrained policy follows the route exactly (a random output layer's differences
    // between candidate states exceed the prior's ~1% per step and it stalls).
    torch::nn::Linear out = impl_->model->OutputLayer();
    out->weight.zero_();
    out->bias.zero_();
  }
  UpdateTargetNetwork();
}

EncodedState ValuePolicy::Encode(const Observation& obs) const {
  return EncodeState(impl_->config, obs.self, obs.frame, obs.readings);
}

void ValuePolicy::SetExploration(const Exploration& exploration) {
  impl_->exploration = exploration;
  impl_->rng = Rng(exploration.seed);
}

void ValuePolicy::SetLearningRate(double learning_rate, double momentum) {
  impl_->learning_rate = learning_rate;
  impl_->momentum = momentum;
  impl_->MakeOptimizer();
}

double ValuePolicy::TrainBatch(std::span<const EncodedState* const> states,
                               std::span<const float> targets) {
  Impl& m = *impl_;
  if (!m.optimizer) throw std::logic_error("TrainBatch before SetLearningRate");
  m.model->train();
  const StateBatch batch = MakeBatch(m.config, states);
  const torch::Tensor target =
      torch::from_blob(const_cast<float*>(targets.data()), {static_cast<int64_t>(targets.size())})
          .clone();
  m.optimizer->zero_grad();
  torch::Tensor loss = torch::mse_loss(m.model->Forward(batch), target);
  loss.backward();
  m.optimizer->step();
  return loss.item<double>();
}

std::vector<float> ValuePolicy::TargetValues(std::span<const EncodedState* const> states) {
  return impl_->Evaluate(*impl_->target, states);
}

std::vector<float> ValuePolicy::Values(std::span<const EncodedState* const> states) {
  return impl_->Evaluate(*impl_->model, states);
}

void ValuePolicy::UpdateTargetNetwork() { CopyParameters(*impl_->model, impl_->target.get()); }

void ValuePolicy::SaveWeights(const fs::path& file) const {
  SaveWeightsFile(*impl_->model, MetaOf(impl_->config), file);
}

void ValuePolicy::LoadWeights(const fs::path& file) {
  LoadWeightsFile(MetaOf(impl_->config), file, impl_->model.get());
  UpdateTargetNetwork();
}

void ValuePolicy::SaveTrainingState(const fs::path& dir) const {
  const Impl& m = *impl_;
  SaveWeightsFile(*m.target, MetaOf(m.config), dir / "target.pt");
  torch::serialize::OutputArchive archive;
  archive.write("learning_rate", c10::IValue(m.learning_rate));
  archive.write("momentum", c10::IValue(m.momentum));
  archive.write("has_optimizer", c10::IValue(m.optimizer != nullptr));
  if (m.optimizer) m.optimizer->save(archive);
  SaveArchive(archive, dir / "optimizer.pt");
}

void ValuePolicy::LoadTrainingState(const fs::path& dir) {
  Impl& m = *impl_;
  for (const char* file : {"target.pt", "optimizer.pt"}) {
    if (!fs::is_regular_file(dir / file)) {
      throw std::runtime_error("the checkpoint " + dir.string() + " lacks " + file +
                               " (incomplete or damaged): restart the training without --resume");
    }
  }
  LoadWeightsFile(MetaOf(m.config), dir / "target.pt", m.target.get());
  torch::serialize::InputArchive archive;
  try {
    archive.load_from((dir / "optimizer.pt").string());
  } catch (const c10::Error& e) {
    throw std::runtime_error("cannot read " + (dir / "optimizer.pt").string() + " (" +
                             e.what_without_backtrace() +
                             "): restart the training without --resume");
  }
  c10::IValue lr, momentum, has;
  archive.read("learning_rate", lr);
  archive.read("momentum", momentum);
  archive.read("has_optimizer", has);
  m.learning_rate = lr.toDouble();
  m.momentum = momentum.toDouble();
  m.optimizer.reset();
  if (has.toBool()) {
    m.MakeOptimizer();
    m.optimizer->load(archive);
  }
}

const std::vector<float>& ValuePolicy::last_action_values() const { return impl_->action_values; }

std::int64_t ValuePolicy::ParameterCount() const { return value_rl::ParameterCount(*impl_->model); }

std::unique_ptr<Policy> MakeValuePolicy(Model model, const Params& params) {
  return std::make_unique<ValuePolicy>(model, params);
}

}  // namespace crowdsim::value_rl
