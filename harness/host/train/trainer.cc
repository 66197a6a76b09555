#include "crowdsim/bench/training/trainer.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <csignal>
#include <fstream>
#include <iterator>
#include <memory>
#include <numeric>
#include <optional>
#include <sstream>

#include "atomic_file.h"
#include "crowdsim/bench/episode.h"
#include "crowdsim/bench/human_attributes.h"
#include "crowdsim/bench/input_files.h"
#include "crowdsim/bench/results.h"
#include "crowdsim/bench/row_instance.h"
#include "crowdsim/rng.h"
#include "crowdsim/trainable.h"
#include "crowdsim/version.h"
#include "loader/blas_kernel.h"
#include "results/json_file.h"
#include "run/output_folder.h"
#include "spec/config_text.h"
#include "train/episode_log.h"
#include "train/replay_memory.h"
#include "train/training_checkpoint.h"
#include "train/training_progress.h"
#include "train/value_targets.h"

namespace crowdsim::training {
namespace fs = std::filesystem;

double Epsilon(const TrainingSettings& t, int episode) {
  if (episode >= t.epsilon_decay_episodes) return t.epsilon_end;
  return t.epsilon_start + (t.epsilon_end - t.epsilon_start) * episode / t.epsilon_decay_episodes;
}

namespace {

volatile std::sig_atomic_t g_signal = 0;
extern "C" void OnSignal(int sig) { g_signal = sig; }

/// Catches SIGINT, SIGTERM and SIGHUP while alive, so the trainer checkpoints before leaving.
class SignalGuard {
 public:
  SignalGuard() {
    g_signal = 0;
    old_int_ = std::signal(SIGINT, OnSignal);
    old_term_ = std::signal(SIGTERM, OnSignal);
    old_hup_ = std::signal(SIGHUP, OnSignal);
  }
  ~SignalGuard() {
    std::signal(SIGINT, old_int_);
    std::signal(SIGTERM, old_term_);
    std::signal(SIGHUP, old_hup_);
  }

 private:
  void (*old_int_)(int);
  void (*old_term_)(int);
  void (*old_hup_)(int);
};

using Clock = std::chrono::steady_clock;

double Since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

/// Where an episode's transitions go: demonstrations store successes and collisions (CrowdNav); RL
/// also timeouts if configured.
std::optional<MemorySource> SourceOf(EpisodeStatus s, bool rl, StoreTimeouts timeouts) {
  switch (s) {
    case EpisodeStatus::kSuccess:
      return rl ? MemorySource::kSuccess : MemorySource::kImitation;
    case EpisodeStatus::kCollisionHuman:
    case EpisodeStatus::kCollisionObstacle:
      return rl ? MemorySource::kCollision : MemorySource::kImitation;
    case EpisodeStatus::kTimeout:
      if (rl && timeouts != StoreTimeouts::kOff) return MemorySource::kTimeout;
      return std::nullopt;
    default:
      return std::nullopt;
  }
}

/// One recorded episode: encoded states before decisions, step rewards, and optionally the final
/// state.
struct Trajectory {
  std::vector<EncodedState> states;
  std::vector<float> rewards;
  std::optional<EncodedState> final_state;
  EpisodeResult result;
};

constexpr std::size_t kProbeStates = 200;

class Trainer {
 public:
  Trainer(const TrainSpec& spec, PluginRegistry& registry, const TrainOptions& options)
      : spec_(spec),
        registry_(registry),
        options_(options),
        t_(spec.training),
        memory_(static_cast<std::size_t>(t_.capacity)),
        progress_(spec.name, options.progress) {
    summary_.out_dir =
        options.out_dir.empty() ? fs::path("results") / "train" / spec.name : options.out_dir;
    Build();
  }

  TrainSummary Run();
  /// PreflightTraining's checks beyond Build.
  void Preflight();

 private:
  void Build();
  Scenario MakeScenario(const char* stream, int index) const;
  Trajectory RunEpisode(Policy* robot, const Scenario& scenario, bool encode,
                        bool observe_timeout_end = false);
  void LogEpisode(const char* phase, int index, double epsilon, const Trajectory& tr, double loss);
  void Demonstrations();
  void Imitation();
  void Reinforcement();
  /// Why RL stops at `episode`: `what` is not finite; where the last good weights are, the fix.
  std::string Diverged(int episode, const std::string& what) const;
  int checkpoint_counter_ = -1;  // RL episodes done when the checkpoint on disk was written
  ValidationResult Validate(int rl_episode);
  double TrainOn(std::span<const std::size_t> indices);
  void SaveCheckpoint();
  std::string CheckpointFailure(const fs::path& tmp, std::string what) const;
  void RefuseOutputsOverInputs() const;
  void LoadCheckpoint();
  /// Accepts a checkpoint whose configuration differs only in training.rl_episodes (throws
  /// otherwise).
  void AcceptNewRlLength(const fs::path& dir);
  void WriteSummaryJson() const;
  void OpenEpisodeLog(std::int64_t keep_bytes);
  void WriteLearningCurve();
  /// True when the run must stop now (signal, or the test hook's episode budget).
  bool ShouldStop() const {
    return g_signal != 0 || (options_.stop_after_episodes >= 0 &&
                             summary_.episodes_run >= options_.stop_after_episodes);
  }
  fs::path Out(const char* name) const { return summary_.out_dir / name; }

  const TrainSpec& spec_;
  PluginRegistry& registry_;
  const TrainOptions& options_;
  const TrainingSettings& t_;

  std::shared_ptr<WorldSource> world_;
  /// The learner, its sensors and the humans, made as a suite row's.
  std::unique_ptr<RowInstance> row_;
  Policy* learner_policy_ = nullptr;
  Trainable* learner_ = nullptr;
  std::shared_ptr<Policy> teacher_;
  /// The row's agents for the most humans an episode may have; robot set per episode.
  EpisodeAgents agents_;

  ReplayMemory memory_;
  ReplayMemory probe_{kProbeStates};  ///< fixed states whose mean value each validation logs
  EpisodeLog episode_log_;
  CheckpointState state_;
  TrainingProgress progress_;
  TrainSummary summary_;
};

void Trainer::Build() {
  const RowSpec& row = spec_.row;
  try {
    world_ = registry_.MakeWorld(*row.world.loaded, row.world.params);
    row_ = std::make_unique<RowInstance>(row, registry_);
    agents_ = row_->Agents(static_cast<size_t>(row.humans.count_max));
  } catch (const PluginError& e) {
    throw TrainRefused(e.what());
  }
  try {
    teacher_ = registry_.MakePolicy(*spec_.teacher.loaded, spec_.teacher.params);
  } catch (const PluginError& e) {
    // Said as the teacher's: the learner's own missing weights read the same.
    throw TrainRefused("the imitation teacher (training.il_policy '" + spec_.teacher.plugin +
                       "' with training.il_params): " + e.what());
  }
  learner_policy_ = &row_->robot();
  learner_ = dynamic_cast<Trainable*>(learner_policy_);
  if (learner_ == nullptr) {
    throw TrainRefused("policy '" + row.policy.plugin +
                       "' cannot be trained: its object does not implement crowdsim::Trainable "
                       "(train cadrl or sarl)");
  }
  if (const std::string unmet = row_->UnmetSensorNeed(); !unmet.empty()) {
    throw TrainRefused(unmet + "; add it to `sensors`");
  }
  if (const std::string unmet = row_->UnmetKinematicsNeed(); !unmet.empty())
    throw TrainRefused(unmet);
  if (const std::string unmet = KinematicsRefusal(teacher_->Needs(), row.kinematics);
      !unmet.empty()) {
    throw TrainRefused("the imitation teacher (training.il_policy '" + spec_.teacher.plugin +
                       "') " + unmet);
  }
  if (const std::string unmet = row_->HumansNeedRobotOnly(); !unmet.empty()) {
    throw TrainRefused(unmet + "; " + kPlainHumansPolicy);
  }
  // The run's constants before imitation (a discounted route prior needs gamma); no map: no
  // episode.
  EpisodeContext constants;
  constants.sim = spec_.sim;
  constants.kinematics = row.kinematics;
  learner_policy_->Reset(constants);
}

void Trainer::Preflight() {
  for (const char* stream : {"il", "val", "rl"}) {
    try {
      CheckScenario(MakeScenario(stream, 0), spec_.sim);
    } catch (const std::exception& e) {
      throw TrainRefused(std::string("the first scenario of the training's '") + stream +
                         "' episodes cannot be made: " + e.what());
    }
  }
  learner_->InitWeights(spec_.seed);
  const Scenario scenario = MakeScenario("il", 0);
  for (Policy* robot : {teacher_.get(), learner_policy_}) {
    agents_.robot = robot;
    Episode episode(scenario, spec_.sim, agents_);
    if (!episode.done()) episode.Step();
    if (episode.result().status == EpisodeStatus::kPolicyError) {
      const std::string who = robot == learner_policy_
                                  ? "the learner ('" + spec_.row.policy.plugin + "')"
                                  : "the teacher (il_policy '" + spec_.teacher.plugin + "')";
      throw TrainRefused(
          who + " fails in the first step of the first episode: " + episode.result().error);
    }
  }
}

Scenario Trainer::MakeScenario(const char* stream, int index) const {
  ScenarioRequest req;
  req.seed =
      DeriveSeed(spec_.seed, world_->Identity() + "/" + stream, static_cast<std::uint64_t>(index));
  req.episode_index = index;
  const HumansSpec& humans = spec_.row.humans;
  req.num_humans = humans.count;
  if (humans.count_max > humans.count) {
    Rng rng(SplitMix64(req.seed ^ 0x68756d616e73ULL));  // "humans"
    req.num_humans += static_cast<int>(rng.Below(humans.count_max - humans.count + 1));
  }
  req.goal_mode = humans.goal_mode;
  req.sim = spec_.sim;
  req.humans = DrawHumanAttributes(humans, spec_.sim, req.seed, req.num_humans);
  Scenario scenario = world_->Make(req);
  CheckHumanCount(req, scenario);
  return scenario;
}

Trajectory Trainer::RunEpisode(Policy* robot, const Scenario& scenario, bool encode,
                               bool observe_timeout_end) {
  agents_.robot = robot;
  Trajectory tr;
  Episode episode(scenario, spec_.sim, agents_);
  while (!episode.done()) {
    const StepInfo info = episode.Step();
    if (episode.result().status == EpisodeStatus::kPolicyError) break;
    if (encode) {
      tr.states.push_back(learner_->Encode(episode.last_robot_observation()));
      tr.rewards.push_back(static_cast<float>(info.reward));
    }
  }
  tr.result = episode.result();
  if (tr.result.status == EpisodeStatus::kPolicyError) {
    // The episode's error already names whose policy or which sensor failed: not prefixed again.
    throw TrainError("episode of scenario seed " + std::to_string(scenario.seed) + ": " +
                     tr.result.error);
  }
  if (encode && observe_timeout_end && tr.result.status == EpisodeStatus::kTimeout) {
    tr.final_state = learner_->Encode(episode.ObserveRobot());
  }
  return tr;
}

void Trainer::LogEpisode(const char* phase, int index, double epsilon, const Trajectory& tr,
                         double loss) {
  EpisodeLogRow row;
  row.phase = phase;
  row.index = index;
  row.epsilon = epsilon;
  row.outcome = EpisodeStatusName(tr.result.status);
  row.discounted_return = tr.result.discounted_return;
  row.steps = tr.result.steps;
  row.loss = loss;
  row.memory_size = memory_.size();
  row.memory = memory_.composition();
  episode_log_.Append(row);
}

void Trainer::Demonstrations() {
  progress_.Phase("IL demonstrations (" + spec_.teacher.plugin + ")", state_.counter,
                  t_.il_episodes);
  const double discount = std::pow(spec_.sim.gamma, spec_.sim.time_step * spec_.sim.robot_v_pref);
  while (state_.counter < t_.il_episodes && !ShouldStop()) {
    const auto t0 = Clock::now();
    Trajectory tr = RunEpisode(teacher_.get(), MakeScenario("il", state_.counter), true);
    if (const auto source = SourceOf(tr.result.status, false, t_.store_timeouts)) {
      const std::vector<float> values = MonteCarloReturns(tr.rewards, discount);
      for (std::size_t i = 0; i < values.size(); ++i)
        memory_.Push(std::move(tr.states[i]), values[i], *source);
    }
    LogEpisode("demonstration", state_.counter, 0.0, tr, 0.0);
    ++state_.counter;
    ++summary_.episodes_run;
    summary_.times.demonstrations += Since(t0);
    progress_.Episode(tr.result.status, 0.0, 0.0);
    if (state_.counter % t_.checkpoint_interval == 0 && state_.counter < t_.il_episodes)
      SaveCheckpoint();
  }
  if (state_.counter >= t_.il_episodes) {
    // Probe states: evenly spread over the demonstrations, fixed for the rest of the training.
    const std::size_t stride = std::max<std::size_t>(1, memory_.size() / kProbeStates);
    for (std::size_t i = 0; i < memory_.size() && probe_.size() < kProbeStates; i += stride) {
      probe_.Push(memory_.state(i), memory_.value(i), MemorySource::kImitation);
    }
    state_.phase = TrainPhase::kImitation;
    state_.counter = 0;
    learner_->SetLearningRate(t_.il_learning_rate, t_.momentum);
  }
}

double Trainer::TrainOn(std::span<const std::size_t> indices) {
  std::vector<const EncodedState*> states;
  std::vector<float> targets;
  states.reserve(indices.size());
  targets.reserve(indices.size());
  for (std::size_t i : indices) {
    states.push_back(&memory_.state(i));
    targets.push_back(memory_.value(i));
  }
  return learner_->TrainBatch(states, targets);
}

void Trainer::Imitation() {
  if (memory_.size() > 0 && state_.counter < t_.il_epochs) {
    progress_.Note("IL: " + std::to_string(t_.il_epochs - state_.counter) + " epochs over " +
                   std::to_string(memory_.size()) + " states");
  } else if (memory_.size() == 0 && t_.il_epochs > 0 && state_.counter == 0) {
    // Said, not silently skipped: the RL phase then starts from random weights.
    progress_.Note("warning: no imitation: " +
                   (t_.il_episodes == 0
                        ? std::string("training.il_episodes is 0")
                        : "none of the teacher's " + std::to_string(t_.il_episodes) +
                              " demonstrations ended in a way that is stored (il_policy '" +
                              spec_.teacher.plugin + "': see training_episodes.csv)") +
                   "; RL starts from the initial weights");
  }
  std::vector<std::size_t> order(memory_.size());
  while (memory_.size() > 0 && state_.counter < t_.il_epochs && g_signal == 0) {
    const auto t0 = Clock::now();
    // A fresh shuffle per epoch (CrowdNav's DataLoader), seeded by the epoch for --resume.
    std::iota(order.begin(), order.end(), std::size_t{0});
    Rng rng(DeriveSeed(spec_.seed, "il_epoch", static_cast<std::uint64_t>(state_.counter)));
    for (std::size_t i = order.size(); i > 1; --i) std::swap(order[i - 1], order[rng.Below(i)]);
    double loss = 0.0;
    int batches = 0;
    for (std::size_t start = 0; start < order.size(); start += t_.batch_size) {
      const std::size_t n = std::min<std::size_t>(t_.batch_size, order.size() - start);
      loss += TrainOn(std::span<const std::size_t>(order.data() + start, n));
      ++batches;
    }
    EpisodeLogRow row;
    row.phase = "imitation";
    row.index = state_.counter;
    row.loss = loss / batches;
    row.memory_size = memory_.size();
    row.memory = memory_.composition();
    episode_log_.Append(row);
    ++state_.counter;
    summary_.times.imitation += Since(t0);
    std::ostringstream os;
    os << "IL epoch " << state_.counter << "/" << t_.il_epochs << "  loss " << loss / batches;
    progress_.Note(os.str());
  }
  if (state_.counter >= t_.il_epochs || memory_.size() == 0) {
    learner_->UpdateTargetNetwork();
    learner_->SaveWeights(Out("il.pt"));
    state_.phase = TrainPhase::kReinforcement;
    state_.counter = 0;
    learner_->SetLearningRate(t_.rl_learning_rate, t_.momentum);
  }
}

ValidationResult Trainer::Validate(int rl_episode) {
  const auto t0 = Clock::now();
  learner_->SetExploration(Exploration{});
  ValidationResult v;
  v.episode = rl_episode;
  double nav = 0.0;
  int success = 0, collision = 0, timeout = 0;
  for (int k = 0; k < t_.validation_episodes; ++k) {
    const Trajectory tr = RunEpisode(learner_policy_, MakeScenario("val", k), false);
    switch (tr.result.status) {
      case EpisodeStatus::kSuccess:
        ++success;
        nav += tr.result.time;
        break;
      case EpisodeStatus::kCollisionHuman:
      case EpisodeStatus::kCollisionObstacle:
        ++collision;
        break;
      default:
        ++timeout;
        break;
    }
  }
  if (probe_.size() > 0) {
    std::vector<const EncodedState*> probe;
    for (std::size_t i = 0; i < probe_.size(); ++i) probe.push_back(&probe_.state(i));
    const std::vector<float> values = learner_->Values(probe);
    double sum = 0.0;
    for (float x : values) sum += x;
    v.probe_value = sum / static_cast<double>(values.size());
  }
  const double n = std::max(1, t_.validation_episodes);
  v.success = success / n;
  v.collision = collision / n;
  v.timeout = timeout / n;
  v.nav_time = success > 0 ? nav / success : spec_.sim.time_limit;
  summary_.times.validation += Since(t0);
  std::ostringstream os;
  os << "validation after " << rl_episode << " RL episodes: success " << v.success << ", collision "
     << v.collision << ", timeout " << v.timeout << ", nav time " << v.nav_time << ", probe value ";
  if (std::isfinite(v.probe_value)) {
    os << v.probe_value;
  } else {
    os << "none (no probe state: nothing stored from imitation)";
  }
  if (v.success > state_.best_success) {
    state_.best_success = v.success;
    state_.best_episode = rl_episode;
    learner_->SaveWeights(Out("best.pt"));
    os << " (best so far)";
  }
  progress_.Note(os.str());
  state_.validations.push_back(v);
  WriteFileAtomically(Out("training_log.csv"), ValidationCsv(state_.validations));
  return v;
}

std::string Trainer::Diverged(int episode, const std::string& what) const {
  std::string kept;
  if (checkpoint_counter_ >= 0) {
    kept = Out("checkpoint").string() + " holds the state after " +
           std::to_string(checkpoint_counter_) + " RL episodes";
  } else {
    kept = "no checkpoint was written yet (il.pt holds the imitation start)";
  }
  if (fs::exists(Out("best.pt"))) kept += ", best.pt the best validation so far";
  return "RL episode " + std::to_string(episode) + ": " + what +
         ": the network diverged. Training stops rather than go on with broken weights; " + kept +
         ". Fix: a lower training.rl_learning_rate (or fewer train_batches), then " +
         (checkpoint_counter_ >= 0 ? "--resume" : "train again");
}

void Trainer::Reinforcement() {
  progress_.Phase("RL", state_.counter, t_.rl_episodes);
  const double discount = std::pow(spec_.sim.gamma, spec_.sim.time_step * spec_.sim.robot_v_pref);
  std::vector<std::size_t> perm;
  while (state_.counter < t_.rl_episodes && !ShouldStop()) {
    const int e = state_.counter;
    if (t_.validation_interval > 0 && e % t_.validation_interval == 0 &&
        (state_.validations.empty() || state_.validations.back().episode != e)) {
      Validate(e);
    }
    const double epsilon = Epsilon(t_, e);
    auto t0 = Clock::now();
    learner_->SetExploration(
        Exploration{epsilon, DeriveSeed(spec_.seed, "explore", static_cast<std::uint64_t>(e)),
                    t_.exploration == ExplorationRule::kCollisionFree});
    const bool bootstrap_timeouts = t_.store_timeouts == StoreTimeouts::kBootstrap;
    Trajectory tr = RunEpisode(learner_policy_, MakeScenario("rl", e), true, bootstrap_timeouts);
    summary_.times.rl_episodes += Since(t0);
    if (const auto source = SourceOf(tr.result.status, true, t_.store_timeouts)) {
      t0 = Clock::now();
      // TD(0): y_i = r_i + gamma' V_target(s_{i+1}); terminal steps keep their reward, truncated
      // timeouts bootstrap.
      std::vector<const EncodedState*> next;
      for (std::size_t i = 1; i < tr.states.size(); ++i) next.push_back(&tr.states[i]);
      if (tr.final_state) next.push_back(&*tr.final_state);
      const std::vector<float> v_next =
          next.empty() ? std::vector<float>{} : learner_->TargetValues(next);
      const std::vector<float> targets = TdTargets(tr.rewards, v_next, discount);
      // A non-finite target would poison the memory, and every later batch with it.
      if (!std::all_of(targets.begin(), targets.end(), [](float y) { return std::isfinite(y); }))
        throw TrainError(Diverged(e, "a TD target is not finite (the target network's value)"));
      for (std::size_t i = 0; i < targets.size(); ++i)
        memory_.Push(std::move(tr.states[i]), targets[i], *source);
      summary_.times.rl_targets += Since(t0);
    }
    t0 = Clock::now();
    double loss = 0.0;
    if (memory_.size() > 0 && t_.train_batches > 0) {
      // Each batch: distinct random memory entries (CrowdNav: a fresh shuffled loader).
      Rng rng(DeriveSeed(spec_.seed, "batches", static_cast<std::uint64_t>(e)));
      perm.resize(memory_.size());
      std::iota(perm.begin(), perm.end(), std::size_t{0});
      const std::size_t b = std::min<std::size_t>(t_.batch_size, memory_.size());
      for (int k = 0; k < t_.train_batches; ++k) {
        for (std::size_t j = 0; j < b; ++j)
          std::swap(perm[j], perm[j + rng.Below(perm.size() - j)]);
        loss += TrainOn(std::span<const std::size_t>(perm.data(), b));
      }
      loss /= t_.train_batches;
      if (!std::isfinite(loss)) throw TrainError(Diverged(e, "the loss is not finite"));
    }
    summary_.times.rl_updates += Since(t0);
    LogEpisode("rl", e, epsilon, tr, loss);
    ++state_.counter;
    ++summary_.episodes_run;
    if (state_.counter % t_.target_update_interval == 0) learner_->UpdateTargetNetwork();
    progress_.Episode(tr.result.status, epsilon, loss);
    if (state_.counter % t_.checkpoint_interval == 0 && state_.counter < t_.rl_episodes)
      SaveCheckpoint();
  }
  if (state_.counter >= t_.rl_episodes) {
    if (t_.validation_interval > 0 &&
        (state_.validations.empty() || state_.validations.back().episode != state_.counter)) {
      Validate(state_.counter);
    }
    learner_->SaveWeights(Out("weights.pt"));
    state_.phase = TrainPhase::kDone;
  }
}

void Trainer::SaveCheckpoint() {
  const auto t0 = Clock::now();
  const fs::path dir = Out("checkpoint");
  const fs::path tmp = Out("checkpoint.tmp");
  try {
    fs::remove_all(tmp);
    fs::create_directories(tmp);
    learner_->SaveWeights(tmp / "model.pt");
    learner_->SaveTrainingState(tmp);
    memory_.Save(tmp / "memory.bin");
    probe_.Save(tmp / "probe.bin");
    // Best weights are state: resume restores them, so best.pt never outruns the checkpoint.
    if (state_.best_episode >= 0 && fs::exists(Out("best.pt")))
      common::CopyFileAtomically(Out("best.pt"), tmp / "best.pt");
    state_.episode_log_bytes = episode_log_.Flush();
    state_.rl_episodes = t_.rl_episodes;
    WriteCheckpointState(tmp / "state.txt", state_);
  } catch (const std::exception& e) {
    throw TrainError(CheckpointFailure(tmp, e.what()));
  }
  // Replace the old checkpoint; LoadCheckpoint accepts a complete checkpoint.tmp after a crash.
  fs::remove_all(dir);
  fs::rename(tmp, dir);
  checkpoint_counter_ = state_.phase == TrainPhase::kReinforcement ? state_.counter : 0;
  WriteLearningCurve();
  summary_.times.checkpoints += Since(t0);
}

// A teacher's or a row's weights in --out would be replaced while the training reads them.
void Trainer::RefuseOutputsOverInputs() const {
  std::vector<NamedInput> inputs = {{spec_.file, "the training file"}};
  AddRowInputFiles(spec_.row, "the training's", &inputs);
  AddPluginInputFiles(spec_.teacher, "the teacher (training.il_policy)", &inputs);
  std::vector<fs::path> outputs;
  for (const char* name :
       {"weights.pt", "best.pt", "il.pt", "summary.json", "training.yaml", "training_episodes.csv",
        "training_log.csv", "learning_curve.png", "learning_curve.svg"})
    outputs.push_back(Out(name));
  if (const std::string over = OutputOverAnInput(outputs, inputs); !over.empty())
    throw TrainRefused(over);
}

// Why a checkpoint could not be written, a full disk said as such; the half-written one is removed.
std::string Trainer::CheckpointFailure(const fs::path& tmp, std::string what) const {
  what = what.substr(0, what.find("\nException raised from"));  // libtorch's stack trace
  std::error_code ec;
  fs::remove_all(tmp, ec);
  const fs::space_info space = fs::space(summary_.out_dir, ec);
  const bool full = !ec && space.available < (std::uintmax_t{4} << 20);
  return "cannot save the checkpoint in '" + tmp.string() + "': " + what +
         (full ? "; the disk is full (" + std::to_string(space.available >> 10) + " kB free)"
               : "") +
         ". " +
         (fs::exists(Out("checkpoint") / "state.txt")
              ? "The previous checkpoint/ is unchanged: free space, then continue with --resume"
              : "No checkpoint was made yet: free space, then start again");
}

void Trainer::AcceptNewRlLength(const fs::path& dir) {
  // The RL length the checkpoint aimed at: in it (v4), else in summary.json.
  int before = state_.rl_episodes;
  if (before < 0)
    before = static_cast<int>(ReadManifestInteger(Out("summary.json"), "/procedure/rl_episodes"));
  if (before < 0 || spec_.ConfigHashWithRlEpisodes(before) != state_.config_hash) {
    // training.yaml in the folder holds the canonical text the checkpoint is made with.
    std::ostringstream started;
    started << std::ifstream(Out("training.yaml")).rdbuf();
    const std::string differs = suite_internal::DescribeConfigDifference(
        started.str(), spec_.canonical, {{"training", kTrainingLineFields}});
    throw TrainRefused("--resume: the checkpoint in '" + dir.string() +
                       "' belongs to another "
                       "configuration (config hash " +
                       state_.config_hash +
                       ", the training file with its --set and --seed options now " +
                       spec_.ConfigHash() + (differs.empty() ? "" : "; what differs: " + differs) +
                       "); resume with the file and --set options it was started with, or train "
                       "into another --out (between runs only training.rl_episodes may change, and "
                       "training.checkpoint_interval, which changes no result)");
  }
  if (state_.phase == TrainPhase::kReinforcement && t_.rl_episodes < state_.counter) {
    throw TrainRefused("--resume: training.rl_episodes is now " + std::to_string(t_.rl_episodes) +
                       ", fewer than the " + std::to_string(state_.counter) +
                       " RL episodes this checkpoint has done; give at least that many");
  }
  progress_.Note("the RL phase is now " + std::to_string(t_.rl_episodes) + " episodes (was " +
                 std::to_string(before) + "): continuing from the checkpoint at RL episode " +
                 std::to_string(state_.phase == TrainPhase::kReinforcement ? state_.counter : 0));
  state_.config_hash = spec_.ConfigHash();
}

void Trainer::LoadCheckpoint() {
  fs::path dir = Out("checkpoint");
  if (!fs::exists(dir / "state.txt") && fs::exists(Out("checkpoint.tmp") / "state.txt")) {
    dir = Out("checkpoint.tmp");
  }
  if (!fs::exists(dir / "state.txt")) {
    throw TrainRefused(
        "--resume: no checkpoint in '" + summary_.out_dir.string() + "'" +
        (fs::exists(Out("weights.pt"))
             ? ": its weights.pt is a model without a training state (copied there, or its "
               "checkpoint/ was removed), which cannot be resumed; train into another folder "
               "with --out (without --resume)"
             : " (start without --resume, or give the --out of the interrupted training)"));
  }
  state_ = ReadCheckpointState(dir / "state.txt");
  checkpoint_counter_ = state_.phase == TrainPhase::kReinforcement ? state_.counter : 0;
  if (state_.config_hash != spec_.ConfigHash()) AcceptNewRlLength(dir);
  try {
    learner_->LoadWeights(dir / "model.pt");
    learner_->LoadTrainingState(dir);
    memory_.Load(dir / "memory.bin");
    if (fs::exists(dir / "probe.bin")) probe_.Load(dir / "probe.bin");
    // The checkpoint's best weights (absent from older checkpoints).
    if (fs::exists(dir / "best.pt")) {
      common::CopyFileAtomically(dir / "best.pt", Out("best.pt"));
    } else if (state_.best_episode < 0) {
      fs::remove(Out("best.pt"));
    }
  } catch (const std::exception& e) {
    // A library's message may carry a stack trace after its first line (libtorch's do).
    std::string what = e.what();
    what = what.substr(0, what.find("\nException raised from"));
    throw TrainError("--resume: " + what);
  }
}

void Trainer::OpenEpisodeLog(std::int64_t keep_bytes) {
  try {
    episode_log_.Open(Out("training_episodes.csv"), keep_bytes);
  } catch (const std::exception& e) {
    throw TrainError(e.what());
  }
}

void Trainer::WriteLearningCurve() {
  if (!options_.on_files_flushed) return;
  // A figure is a convenience: a failure to draw it must not stop hours of training.
  try {
    options_.on_files_flushed(summary_.out_dir, spec_.name);
  } catch (const std::exception& e) {
    progress_.Note(std::string("warning: ") + e.what());
  }
}

void Trainer::WriteSummaryJson() const {
  const TrainTimes& t = summary_.times;
  const TrainingSettings& p = t_;
  nlohmann::ordered_json j;
  j["name"] = spec_.name;
  j["config_hash"] = spec_.ConfigHash();
  j["seed"] = spec_.seed;
  j["procedure"] = {{"il_episodes", p.il_episodes},
                    {"il_epochs", p.il_epochs},
                    {"rl_episodes", p.rl_episodes},
                    {"epsilon_start", p.epsilon_start},
                    {"epsilon_end", p.epsilon_end},
                    {"epsilon_decay_episodes", p.epsilon_decay_episodes},
                    {"store_timeouts", ToString(p.store_timeouts)},
                    {"exploration", ToString(p.exploration)},
                    {"train_batches", p.train_batches},
                    {"validation_interval", p.validation_interval},
                    {"validation_episodes", p.validation_episodes},
                    {"il_learning_rate", p.il_learning_rate},
                    {"rl_learning_rate", p.rl_learning_rate},
                    {"momentum", p.momentum},
                    {"target_update_interval", p.target_update_interval},
                    {"capacity", p.capacity},
                    {"batch_size", p.batch_size},
                    {"checkpoint_interval", p.checkpoint_interval}};
  // The teacher of the imitation phase, with every parameter it ran with.
  nlohmann::ordered_json teacher = nlohmann::ordered_json::object();
  for (const auto& [key, value] : spec_.teacher.params.values()) {
    teacher[key] = FormatParamValue(value);
  }
  j["procedure"]["il_policy"] =
      spec_.teacher.loaded ? spec_.teacher.loaded->descriptor->name : spec_.teacher.plugin;
  j["procedure"]["il_params"] = std::move(teacher);
  j["cpu"] = CpuModel();
  j["blas_coretype"] = BlasCoreType();
  j["commit"] = GitCommit();
  j["finished"] = summary_.finished;
  j["phase"] = static_cast<int>(state_.phase);
  j["counter"] = state_.counter;
  j["memory_size"] = memory_.size();
  j["episodes_this_run"] = summary_.episodes_run;
  j["wall_seconds_this_run"] = summary_.wall_seconds;
  // This run's (a resumed training's earlier runs are not in it), as the keys beside it.
  j["seconds_this_run"] = {{"demonstrations", t.demonstrations}, {"imitation", t.imitation},
                           {"rl_episodes", t.rl_episodes},       {"rl_targets", t.rl_targets},
                           {"rl_updates", t.rl_updates},         {"validation", t.validation},
                           {"checkpoints", t.checkpoints}};
  j["best_validation_success"] = std::max(0.0, state_.best_success);
  j["best_validation_episode"] = state_.best_episode;
  j["best_weights"] =
      state_.best_episode >= 0
          ? "best.pt: the weights after " + std::to_string(state_.best_episode) + " RL episodes"
          : std::string("none: no validation ran (no best.pt)");
  WriteFileAtomically(Out("summary.json"), FormatJson(j));
}

TrainSummary Trainer::Run() {
  const auto start = Clock::now();
  SignalGuard signals;
  std::error_code ec;
  if (options_.resume && !fs::is_directory(summary_.out_dir, ec)) {
    throw TrainRefused("--resume: '" + summary_.out_dir.string() +
                       "' does not exist (give the --out of the interrupted training, or start "
                       "without --resume)");
  }
  fs::create_directories(summary_.out_dir, ec);
  if (ec || !fs::is_directory(summary_.out_dir)) {
    throw TrainError("cannot create the output folder '" + summary_.out_dir.string() +
                     "': " + ec.message());
  }
  RefuseOutputsOverInputs();
  std::string refused;
  const auto lock = ClaimOutputFolder(summary_.out_dir, "a training", &refused);
  if (!lock) throw TrainRefused(refused);
  if (options_.resume) {
    LoadCheckpoint();
    OpenEpisodeLog(state_.episode_log_bytes);
    progress_.Note("resumed from " + (summary_.out_dir / "checkpoint").string());
  } else {
    if (!fs::exists(Out("checkpoint")) && fs::exists(Out("weights.pt"))) {
      throw TrainRefused("'" + summary_.out_dir.string() +
                         "' already holds a weights.pt with no checkpoint/ to resume from (a "
                         "copied model, or a training whose checkpoint was removed); training "
                         "here would replace it: train into another folder with --out");
    }
    if (fs::exists(Out("checkpoint"))) {
      // --resume continues only this configuration: say so when the folder holds another.
      std::ostringstream started;
      started << std::ifstream(Out("training.yaml")).rdbuf();
      const std::string differs = started.str().empty() ? ""
                                                        : suite_internal::DescribeConfigDifference(
                                                              started.str(), spec_.canonical,
                                                              {{"training", kTrainingLineFields}});
      throw TrainRefused(
          "'" + summary_.out_dir.string() + "' already holds " +
          (differs.empty() ? "a training of this configuration; pass --resume to continue it, or "
                             "--out to train into another folder"
                           : "another training (what differs: " + differs +
                                 "); train into another folder with --out"));
    }
    state_.config_hash = spec_.ConfigHash();
    learner_->InitWeights(spec_.seed);
    OpenEpisodeLog(-1);
  }
  WriteFileAtomically(Out("training.yaml"), "# the configuration of " + spec_.file.string() +
                                                " as its config hash reads it (a record, not a " +
                                                "training file: train from the file)\n" +
                                                spec_.canonical);
  progress_.Note(learner_->Describe());
  if (state_.phase == TrainPhase::kDemonstrations) Demonstrations();
  if (state_.phase == TrainPhase::kImitation && !ShouldStop()) Imitation();
  if (state_.phase == TrainPhase::kReinforcement && !ShouldStop()) Reinforcement();
  progress_.Finish();
  summary_.finished = state_.phase == TrainPhase::kDone;
  if (!summary_.finished) SaveCheckpoint();
  summary_.validations = state_.validations;
  summary_.weights = Out("weights.pt");
  if (state_.best_episode >= 0) summary_.best_weights = Out("best.pt");
  summary_.wall_seconds = Since(start);
  episode_log_.Flush();
  WriteLearningCurve();
  WriteSummaryJson();
  if (g_signal != 0) {
    throw TrainingInterrupted("interrupted by signal " + std::to_string(g_signal) +
                              "; checkpoint written to " + Out("checkpoint").string());
  }
  return summary_;
}

}  // namespace

TrainSummary RunTraining(const TrainSpec& spec, PluginRegistry& registry,
                         const TrainOptions& options) {
  Trainer trainer(spec, registry, options);
  return trainer.Run();
}

void PreflightTraining(const TrainSpec& spec, PluginRegistry& registry) {
  const TrainOptions options;
  Trainer trainer(spec, registry, options);
  trainer.Preflight();
}

bool IsFinishedTraining(const fs::path& out_dir, const TrainSpec& spec) {
  const fs::path summary = out_dir / "summary.json";
  if (!fs::is_regular_file(summary) || !fs::is_regular_file(out_dir / "weights.pt")) return false;
  return ReadManifestBool(summary, "finished") == true &&
         ReadManifestField(summary, "config_hash") == spec.ConfigHash();
}

bool HasCheckpoint(const fs::path& out_dir) {
  return fs::exists(out_dir / "checkpoint" / "state.txt") ||
         fs::exists(out_dir / "checkpoint.tmp" / "state.txt");
}

}  // namespace crowdsim::training
