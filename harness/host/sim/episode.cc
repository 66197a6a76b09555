#include "crowdsim/bench/episode.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <numeric>
#include <stdexcept>

#include "crowdsim/rng.h"
#include "crowdsim/thread_scratch.h"
#include "sim/decision_clock.h"

namespace crowdsim {

namespace {
// Each episode's history id (SenseInput::history_id): unique in the process, never 0.
std::atomic<std::uint64_t> next_history_id{1};

// Finished episodes' history frames, this thread's: a new history reuses their vectors' memory
// instead of allocating a frame a step. At most kSpareFrames kept.
constexpr std::size_t kSpareFrames = 256;
std::vector<SensedFrame>& SpareFrames() { return ThreadScratch<std::vector<SensedFrame>>(); }

// A non-std::exception throw (`throw 42;`) is a policy_error too, not std::terminate.
constexpr const char* kNonStandardException =
    "threw an exception not derived from std::exception (e.g. `throw 42;`); throw a "
    "std::runtime_error with a message instead";
}  // namespace

const char* EpisodeStatusName(EpisodeStatus s) {
  switch (s) {
    case EpisodeStatus::kRunning:
      return "running";
    case EpisodeStatus::kSuccess:
      return "success";
    case EpisodeStatus::kCollisionHuman:
      return "collision_human";
    case EpisodeStatus::kCollisionObstacle:
      return "collision_obstacle";
    case EpisodeStatus::kTimeout:
      return "timeout";
    case EpisodeStatus::kPolicyError:
      return "policy_error";
    case EpisodeStatus::kPolicyCrash:
      return "policy_crash";
    case EpisodeStatus::kPolicyTimeout:
      return "policy_timeout";
  }
  return "unknown";
}

/// This step's lookahead: human actions are already decided, so every candidate sees the same
/// crowd.
class Episode::StepLookahead final : public Lookahead {
 public:
  explicit StepLookahead(const Episode& e) : e_(e) {}

  void Prepare() {
    const std::span<const AgentState> present = e_.present_humans();
    const std::span<const int> ids = e_.present_ids();
    next_humans_.assign(present.begin(), present.end());
    for (size_t k = 0; k < next_humans_.size(); ++k) {
      const Vec2& v = e_.human_actions_[ids.empty() ? k : static_cast<size_t>(ids[k])].velocity;
      next_humans_[k].velocity = v;
      next_humans_[k].position += v * e_.sim_.time_step;
    }
  }

  std::span<const AgentState> NextHumans() const override { return next_humans_; }

  void Evaluate(std::span<const Action> actions,
                std::vector<LookaheadOutcome>* out) const override {
    out->resize(actions.size());
    const double time_after = e_.time_ + e_.sim_.time_step;
    for (size_t k = 0; k < actions.size(); ++k) {
      LookaheadOutcome& o = (*out)[k];
      const ExecutedMove move = e_.Execute(actions[k]);
      const Vec2& v = move.velocity;
      const StepJudgement j =
          JudgeRobotMove(e_.sim_, e_.world_, e_.robot_, v, e_.present_humans(), time_after);
      o.reward = j.reward;
      o.event = j.event;
      o.robot = e_.robot_;
      o.robot.position += v * e_.sim_.time_step;
      o.robot.velocity = v;
      o.robot.heading = e_.RobotHeading(o.robot, move.heading);
      o.frame = Frame::Make(o.robot.position, o.robot.heading);
      e_.Sense(o.robot, o.frame, next_humans_, e_.present_ids(), e_.step_index_ + 1, &o.readings,
               /*lookahead=*/true);
    }
  }

 private:
  const Episode& e_;
  std::vector<AgentState> next_humans_;
};

namespace {

// Who decided an action: "human i's policy", or the robot's (-1). Spelled out only on failure.
std::string PolicyName(int human) {
  return human < 0 ? std::string("the robot's policy")
                   : "human " + std::to_string(human) + "'s policy";
}

// A policy's decision; failures say whose policy threw. AbortRun passes through to stop the run.
Action DecideNamed(Policy& policy, const Observation& obs, int human) {
  try {
    return policy.Decide(obs);
  } catch (const AbortRun&) {
    throw;
  } catch (const std::exception& e) {
    throw std::runtime_error(PolicyName(human) + " failed: " + e.what());
  } catch (...) {
    throw std::runtime_error(PolicyName(human) + " failed: " + kNonStandardException);
  }
}

[[gnu::noinline, gnu::cold]] void ThrowTooFast(const Vec2& velocity, double v_pref, int human) {
  const double speed = velocity.norm();
  const double limit = kMaxSpeedFactor * v_pref;
  // Four digits, or as many as tell the speed from the limit.
  int digits = 4;
  for (char a[32], b[32]; digits < 17; ++digits) {
    std::snprintf(a, sizeof(a), "%.*g", digits, speed);
    std::snprintf(b, sizeof(b), "%.*g", digits, limit);
    if (std::strcmp(a, b) != 0) break;
  }
  char buf[200];
  std::snprintf(buf, sizeof(buf),
                " returned %.*g m/s, more than %.0f x v_pref (%.*g m/s): an action is "
                "the velocity for the next step, in m/s",
                digits, speed, kMaxSpeedFactor, digits, limit);
  throw std::runtime_error(PolicyName(human) + buf);
}

inline void CheckSpeed(const Vec2& velocity, double v_pref, int human) {
  // Nearly every action is well below the limit: squares decide those without a square root.
  if (NormAbove(velocity, kMaxSpeedFactor * v_pref)) ThrowTooFast(velocity, v_pref, human);
}

}  // namespace

std::string KinematicsRefusal(const PolicyNeeds& needs, const RobotKinematics& k) {
  if (k.Holonomic() || k.track_velocity || needs.non_holonomic != NonHolonomicDrive::kNone)
    return "";
  return std::string("returns world velocities only and cannot drive a ") +
         KinematicsModelName(k.model) +
         " robot: add `track_velocity: true` to the row's kinematics to drive it through the "
         "harness's turn-then-go tracker (docs/kinematics.md), or use a policy that returns "
         "(linear, angular) commands";
}

void CheckScenario(const Scenario& scenario, const SimConfig& sim) {
  // Spelled out only for an error: no string per episode.
  const auto where = [&scenario] {
    return "scenario " + (scenario.map ? scenario.map->name : std::string("(no map)")) + ": ";
  };
  auto text = [](const Vec2& p) {
    char buf[64];
    std::snprintf(buf, sizeof(buf), "(%.3f, %.3f)", p.x(), p.y());
    return std::string(buf);
  };
  if (!scenario.robot_start.allFinite() || !scenario.robot_goal.allFinite()) {
    throw std::invalid_argument(where() + "the robot's start or goal is not a finite point");
  }
  if ((scenario.robot_goal - scenario.robot_start).norm() <= sim.goal_radius) {
    throw std::invalid_argument(
        where() + "the robot starts at its goal " + text(scenario.robot_goal) +
        " (within goal_radius): the episode would be a success without a move");
  }
  if (!scenario.map) return;
  const StaticMap& map = *scenario.map;
  // A disc starting in an obstacle collides at once whatever its policy. `human`: index, or -1.
  auto overlap = [&](const Vec2& p, double radius, int human) {
    for (std::size_t k = 0; k < map.rectangles.size(); ++k) {
      const Rect& r = map.rectangles[k];
      const Vec2 gap(std::max({r.min.x() - p.x(), 0.0, p.x() - r.max.x()}),
                     std::max({r.min.y() - p.y(), 0.0, p.y() - r.max.y()}));
      const double distance = gap.norm();
      if (distance < radius - kStartOverlapTolerance) {
        char buf[96];
        std::snprintf(buf, sizeof(buf), " is %.3f m from obstacle %zu, less than its radius %.3f m",
                      distance, k, radius);
        const std::string who = human < 0 ? std::string("the robot's start")
                                          : "human " + std::to_string(human) + "'s start";
        throw std::invalid_argument(where() + who + " " + text(p) + buf +
                                    ": the world must start agents in free space");
      }
    }
  };
  for (const auto& [name, p] :
       {std::pair{"start", scenario.robot_start}, std::pair{"goal", scenario.robot_goal}}) {
    if (map.bounds.Area() > 0.0 && !map.bounds.Contains(p)) {
      throw std::invalid_argument(where() + "the robot's " + name + " " + text(p) +
                                  " lies outside the map");
    }
    for (std::size_t k = 0; k < map.rectangles.size(); ++k) {
      const Rect& r = map.rectangles[k];
      if (p.x() > r.min.x() && p.x() < r.max.x() && p.y() > r.min.y() && p.y() < r.max.y()) {
        throw std::invalid_argument(where() + "the robot's " + name + " " + text(p) +
                                    " lies inside obstacle " + std::to_string(k));
      }
    }
  }
  overlap(scenario.robot_start, sim.robot_radius, -1);
  for (std::size_t i = 0; i < scenario.humans.size(); ++i) {
    overlap(scenario.humans[i].start, scenario.humans[i].radius, static_cast<int>(i));
  }
}

void CheckHumanCount(const ScenarioRequest& request, const Scenario& scenario) {
  if (static_cast<int>(scenario.humans.size()) == request.num_humans) return;
  throw std::invalid_argument(
      "scenario " + (scenario.map ? scenario.map->name : std::string("(no map)")) +
      ": the world made " + std::to_string(scenario.humans.size()) + " human(s) where " +
      std::to_string(request.num_humans) +
      " were asked for (the row's humans.count): a world must place every human it is asked "
      "for, or fail saying why");
}

Episode::Episode(const Scenario& scenario, const SimConfig& sim, const EpisodeAgents& agents,
                 bool record_trajectory)
    : scenario_(scenario),
      sim_(sim),
      agents_(agents),
      world_(scenario.map),
      record_(record_trajectory) {
  if (agents_.robot == nullptr) throw std::invalid_argument("episode needs a robot policy");
  if (agents_.humans.size() < scenario_.humans.size()) {
    throw std::invalid_argument("episode needs one human policy per human");
  }
  CheckScenario(scenario_, sim_);
  robot_.position = scenario_.robot_start;
  robot_.goal = scenario_.robot_goal;
  robot_.radius = sim_.robot_radius;
  robot_.v_pref = sim_.robot_v_pref;
  robot_.heading = HeadingToGoal(robot_);
  humans_.reserve(scenario_.humans.size());
  for (const auto& h : scenario_.humans) {
    AgentState s;
    s.position = h.start;
    s.goal = h.goals.empty() ? h.start : h.goals.front();
    s.radius = h.radius;
    s.v_pref = h.v_pref;
    s.heading = HeadingToGoal(s);
    s.group = h.group;
    humans_.push_back(s);
  }
  const bool any_unaware = std::any_of(scenario_.humans.begin(), scenario_.humans.end(),
                                       [](const HumanSpec& h) { return h.ignores_robot; });
  if (sim_.robot_visible && any_unaware) unaware_index_ = std::make_unique<AgentIndex>();
  all_present_ = std::all_of(scenario_.humans.begin(), scenario_.humans.end(), AlwaysPresent);
  UpdatePresence();
  human_goal_index_.assign(humans_.size(), 0);
  human_reached_.assign(humans_.size(), false);
  human_actions_.resize(humans_.size());
  lookahead_ = std::make_unique<StepLookahead>(*this);
  for (const MountedSensor& m : agents_.sensors) {
    const int n = m.sensor->HistorySteps();
    if (n < 0 || history_steps_ < 0) {
      history_steps_ = -1;
    } else {
      history_steps_ = std::max(history_steps_, n);
    }
  }
  if (history_steps_ != 0) history_id_ = next_history_id.fetch_add(1, std::memory_order_relaxed);

  robot_needs_ = agents_.robot->Needs();
  if (const std::string refusal = KinematicsRefusal(robot_needs_, agents_.kinematics);
      !refusal.empty()) {
    throw std::invalid_argument("the robot's policy " + refusal);
  }
  if (!agents_.kinematics.Holonomic() && scenario_.robot_heading)
    robot_.heading = *scenario_.robot_heading;
  human_needs_.reserve(humans_.size());
  for (size_t i = 0; i < humans_.size(); ++i) human_needs_.push_back(agents_.humans[i]->Needs());

  try {
    // The map reaches only the policies that declare they need it.
    const StaticMap* map = scenario_.map.get();
    EpisodeContext ctx{robot_needs_.map ? map : nullptr, sim_, AgentRole::kRobot,
                       SplitMix64(scenario_.seed),       0,    agents_.kinematics};
    agents_.robot->Reset(ctx);
    ctx.kinematics = RobotKinematics{};
    for (size_t i = 0; i < humans_.size(); ++i) {
      ctx.map = human_needs_[i].map ? map : nullptr;
      ctx.role = AgentRole::kHuman;
      ctx.agent_id = static_cast<int>(i) + 1;
      ctx.seed = SplitMix64(scenario_.seed + i + 1);
      ctx.track = scenario_.humans[i].track;
      agents_.humans[i]->Reset(ctx);
    }
  } catch (const AbortRun&) {
    throw;  // the whole run stops: no result for this episode
  } catch (const std::exception& e) {
    result_.error = std::string("Reset failed: ") + e.what();
    Finish(EpisodeStatus::kPolicyError);
  } catch (...) {
    result_.error = std::string("Reset failed: a policy ") + kNonStandardException;
    Finish(EpisodeStatus::kPolicyError);
  }
  Record();
}

Episode::~Episode() {
  std::vector<SensedFrame>& spare = SpareFrames();
  for (SensedFrame& f : past_) {
    if (spare.size() >= kSpareFrames) break;
    spare.push_back(std::move(f));
  }
}

void PresentPeople(const EpisodeFrame& f, std::vector<AgentState>* humans, std::vector<int>* ids) {
  ids->clear();
  if (f.present.empty()) {
    humans->assign(f.humans.begin(), f.humans.end());
    return;
  }
  humans->clear();
  for (size_t i = 0; i < f.humans.size(); ++i) {
    if (!f.present[i]) continue;
    humans->push_back(f.humans[i]);
    ids->push_back(static_cast<int>(i));
  }
}

void Episode::Sense(const AgentState& robot, const Frame& frame, std::span<const AgentState> humans,
                    std::span<const int> human_ids, int step, std::vector<SensorReading>* out,
                    bool lookahead) const {
  const std::span<const MountedSensor> sensors = agents_.sensors;
  out->resize(sensors.size());
  const SenseInput input{
      robot,    frame,          humans,     world_,      SensorNoiseSeed(scenario_.seed),
      step,     sim_.time_step, Past(step), history_id_, lookahead,
      human_ids};
  for (size_t s = 0; s < sensors.size(); ++s) {
    SensorReading& r = (*out)[s];
    // Readings are reused step to step and most already carry the name: no copy.
    if (r.sensor != sensors[s].name) r.sensor = sensors[s].name;
    try {
      sensors[s].sensor->Sense(input, &r);
    } catch (const AbortRun&) {
      throw;
    } catch (const std::exception& e) {
      throw std::runtime_error("sensor '" + r.sensor + "' failed: " + e.what());
    } catch (...) {
      throw std::runtime_error("sensor '" + r.sensor + "' failed: " + kNonStandardException);
    }
  }
}

void Episode::DecideHumans() {
  // Humans see each other (and the robot when it is visible) through a neighbour index.
  const std::span<const AgentState> present = present_humans();
  human_view_.assign(present.begin(), present.end());
  if (sim_.robot_visible) human_view_.push_back(robot_);
  human_index_.Rebuild(human_view_);
  if (unaware_index_) unaware_index_->Rebuild(present);
  human_obs_.time = time_;
  human_obs_.agents = &human_index_;
  if (!all_present_) {
    // Only the present decide; the absent stand still.
    const int count = static_cast<int>(present_ids_.size());
    for (int k = 0; k < count; ++k) DecideHuman(present_ids_[k], k);
    return;
  }
  // The count read once: DecideHuman changes no size, but the compiler cannot know that.
  const int count = static_cast<int>(humans_.size());
  for (int i = 0; i < count; ++i) DecideHuman(i, i);
}

void Episode::UpdatePresence() {
  if (all_present_) return;
  if (by_appear_.empty()) {
    // People come in order of `appear` (then index) and each stays until its `leave`, so a
    // step looks at the present and the next to come only: its cost is O(people present).
    present_.assign(humans_.size(), 0);
    by_appear_.resize(humans_.size());
    std::iota(by_appear_.begin(), by_appear_.end(), 0);
    std::stable_sort(by_appear_.begin(), by_appear_.end(), [&](int a, int b) {
      return scenario_.humans[a].appear < scenario_.humans[b].appear;
    });
  }
  std::erase_if(present_ids_, [&](int i) {
    if (PresentAt(scenario_.humans[i], time_)) return false;
    present_[i] = 0;
    left_.push_back(i);
    return true;
  });
  while (next_to_appear_ < by_appear_.size() &&
         time_ >= scenario_.humans[by_appear_[next_to_appear_]].appear - kPresenceTolerance) {
    const int i = by_appear_[next_to_appear_++];
    if (!PresentAt(scenario_.humans[i], time_)) continue;  // its stay fell between two steps
    present_[i] = 1;
    // The present stay in scenario order, what sensors and neighbour queries see.
    present_ids_.insert(std::upper_bound(present_ids_.begin(), present_ids_.end(), i), i);
  }
  present_humans_.resize(present_ids_.size());
  for (size_t k = 0; k < present_ids_.size(); ++k) present_humans_[k] = humans_[present_ids_[k]];
}

void Episode::DecideHuman(int i, int view) {
  // Next goal of a goal sequence once this one is reached.
  AgentState& h = humans_[i];
  const auto& goals = scenario_.humans[i].goals;
  if (NormBelow(h.position - h.goal, h.radius)) {
    human_reached_[i] = true;
    if (human_goal_index_[i] + 1 < goals.size()) h.goal = goals[++human_goal_index_[i]];
  }
  human_obs_.self = h;
  human_obs_.frame = human_needs_[i].heading_frame ? Frame::Make(h.position, HeadingToGoal(h))
                                                   : Frame{.origin = h.position};
  human_obs_.self_index = view;
  human_obs_.agents =
      unaware_index_ && scenario_.humans[i].ignores_robot ? unaware_index_.get() : &human_index_;
  human_actions_[i] = DecideNamed(*agents_.humans[i], human_obs_, i);
  if (!human_actions_[i].velocity.allFinite()) {
    throw std::runtime_error(PolicyName(i) + " returned a non-finite velocity");
  }
  CheckSpeed(human_actions_[i].velocity, h.v_pref, i);
}

double Episode::RobotHeading(const AgentState& robot, double executed_heading) const {
  return agents_.kinematics.Holonomic() ? HeadingToGoal(robot) : executed_heading;
}

ExecutedMove Episode::Execute(const Action& action) const {
  const RobotKinematics& k = agents_.kinematics;
  if (k.Unconstrained() && !action.command) {
    ExecutedMove move;
    move.velocity = action.velocity;
    return move;
  }
  if (k.Holonomic() && action.command) {
    throw std::runtime_error(PolicyName(-1) +
                             " returned a (linear, angular) command, but the robot is holonomic: "
                             "return a world velocity (Action::velocity)");
  }
  const RobotMotion motion{robot_.velocity, robot_.heading, robot_linear_, robot_angular_};
  const double dt = sim_.time_step;
  if (k.Holonomic() || action.command) return ExecuteAction(k, robot_.v_pref, motion, action, dt);
  if (robot_needs_.non_holonomic != NonHolonomicDrive::kTrackVelocity && !k.track_velocity) {
    throw std::runtime_error(PolicyName(-1) + " returned a world velocity, but the robot is " +
                             KinematicsModelName(k.model) +
                             ": return Action::Command(linear, angular), or declare "
                             "NonHolonomicDrive::kTrackVelocity in Needs()");
  }
  return ExecuteAction(k, robot_.v_pref, motion, TrackVelocity(k, motion, action.velocity, dt), dt);
}

void Episode::FillRobotObservation() {
  if (past_.size() == static_cast<std::size_t>(step_index_) + 1) {
    // Record() derived this step's heading and frame from this very state: no second atan2.
    robot_.heading = past_.back().robot.heading;
    robot_obs_.frame = past_.back().frame;
  } else {
    robot_.heading = RobotHeading(robot_, robot_.heading);
    robot_obs_.frame = Frame::Make(robot_.position, robot_.heading);
  }
  robot_obs_.time = time_;
  robot_obs_.self = robot_;
  robot_obs_.linear = robot_linear_;
  robot_obs_.angular = robot_angular_;
  Sense(robot_, robot_obs_.frame, present_humans(), present_ids_, step_index_,
        &robot_obs_.readings);
  robot_obs_.lookahead = nullptr;
}

const Observation& Episode::ObserveRobot() {
  if (!robot_obs_current_) FillRobotObservation();
  robot_obs_.lookahead = nullptr;
  robot_obs_current_ = true;
  return robot_obs_;
}

StepInfo Episode::Step() {
  StepInfo info;
  if (done()) return info;
  const double dt = sim_.time_step;
  ExecutedMove move;
  try {
    DecideHumans();
    // Deciding changes nothing sensed: an observation since the last move is this step's.
    if (!robot_obs_current_) FillRobotObservation();
    robot_obs_current_ = false;  // the move below changes what the robot would see
    if (robot_needs_.lookahead) {
      lookahead_->Prepare();
      robot_obs_.lookahead = lookahead_.get();
    } else {
      robot_obs_.lookahead = nullptr;
    }
    const std::uint64_t t0 = DecisionClock::Now();
    info.robot_action = DecideNamed(*agents_.robot, robot_obs_, -1);
    decision_ticks_ += DecisionClock::Now() - t0;
    const Action& a = info.robot_action;
    if (a.command) {
      if (!std::isfinite(a.linear) || !std::isfinite(a.angular)) {
        throw std::runtime_error(PolicyName(-1) + " returned a non-finite command");
      }
      CheckSpeed(Vec2(a.linear, 0.0), robot_.v_pref, -1);
    } else {
      if (!a.velocity.allFinite()) {
        throw std::runtime_error(PolicyName(-1) + " returned a non-finite velocity");
      }
      CheckSpeed(a.velocity, robot_.v_pref, -1);
    }
    move = Execute(a);
  } catch (const AbortRun&) {
    throw;  // the whole run stops: no result for this episode
  } catch (const std::exception& e) {
    result_.error = e.what();
    Finish(EpisodeStatus::kPolicyError);
    return info;
  } catch (...) {
    result_.error = PolicyName(-1) + " " + kNonStandardException;
    Finish(EpisodeStatus::kPolicyError);
    return info;
  }

  // Check (on the pre-move state, CrowdNav's order), then move everybody at once.
  const double time_after = (step_index_ + 1) * dt;
  const Vec2& v = move.velocity;
  const StepJudgement j = JudgeRobotMove(sim_, world_, robot_, v, present_humans(), time_after);
  info.event = j.event;
  info.reward = j.reward;
  info.min_human_distance = j.min_human_distance;
  result_.collided_human = j.human >= 0 && !all_present_ ? present_ids_[j.human] : j.human;
  result_.collided_rect = j.rect;

  robot_.position += v * dt;
  robot_.velocity = v;
  if (!agents_.kinematics.Holonomic()) robot_.heading = move.heading;
  robot_linear_ = move.linear;
  robot_angular_ = move.angular;
  result_.path_length += v.norm() * dt;
  result_.max_speed = std::max(result_.max_speed, v.norm());
  MoveHumans();

  // Record. Most steps earn +0, which changes no sum, so pow runs only for a reward.
  if (info.reward != 0.0) {
    result_.discounted_return +=
        std::pow(sim_.gamma, step_index_ * dt * sim_.robot_v_pref) * info.reward;
  }
  result_.min_human_distance = std::min(result_.min_human_distance, j.min_human_distance);
  if (j.event == StepEvent::kDanger) ++result_.danger_steps;
  ++step_index_;
  time_ = step_index_ * dt;
  UpdatePresence();
  Record();
  switch (j.event) {
    case StepEvent::kSuccess:
      Finish(EpisodeStatus::kSuccess);
      break;
    case StepEvent::kCollisionHuman:
      Finish(EpisodeStatus::kCollisionHuman);
      break;
    case StepEvent::kCollisionObstacle:
      Finish(EpisodeStatus::kCollisionObstacle);
      break;
    case StepEvent::kTimeout:
      Finish(EpisodeStatus::kTimeout);
      break;
    default:
      break;
  }
  return info;
}

const EpisodeResult& Episode::Run() {
  while (!done()) Step();
  return result_;
}

void Episode::MoveHumans() {
  const double dt = sim_.time_step;
  if (!all_present_) {
    // The absent stand still: those who left at the last step stop now.
    for (const int i : present_ids_) {
      humans_[i].velocity = human_actions_[i].velocity;
      humans_[i].position += human_actions_[i].velocity * dt;
    }
    for (const int i : left_) humans_[i].velocity = Vec2::Zero();
    left_.clear();
    return;
  }
  for (size_t i = 0; i < humans_.size(); ++i) {
    humans_[i].velocity = human_actions_[i].velocity;
    humans_[i].position += human_actions_[i].velocity * dt;
  }
}

void Episode::StepPeopleOnly() {
  DecideHumans();
  MoveHumans();
  ++step_index_;
  time_ = step_index_ * sim_.time_step;
  UpdatePresence();
}

void Episode::Finish(EpisodeStatus status) {
  result_.status = status;
  result_.time = time_;
  result_.steps = step_index_;
  result_.decision_time_us =
      step_index_ > 0 ? DecisionClock::Microseconds(decision_ticks_) / step_index_ : 0.0;
  int at_goal = 0;
  for (size_t i = 0; i < humans_.size(); ++i) {
    // An absent person stands where it was (or will be) present: only a visit counts.
    const bool here = all_present_ || present_[i];
    if (human_reached_[i] ||
        (here && NormBelow(humans_[i].position - humans_[i].goal, humans_[i].radius))) {
      ++at_goal;
    }
  }
  result_.humans_at_goal = at_goal;
}

std::span<const SensedFrame> Episode::Past(int step) const {
  if (history_steps_ == 0) return {};
  // past_ holds steps 0..step_index_; a lookahead senses step_index_ + 1 and gets them all.
  const std::size_t end = std::min(past_.size(), static_cast<std::size_t>(std::max(step, 0)));
  const std::size_t begin =
      history_steps_ < 0 ? 0 : end - std::min(end, static_cast<std::size_t>(history_steps_));
  return std::span<const SensedFrame>(past_).subspan(begin, end - begin);
}

void Episode::Record() {
  if (history_steps_ != 0) {
    // The state as the robot senses it at this step (FillRobotObservation's heading and frame).
    std::vector<SensedFrame>& spare = SpareFrames();
    if (spare.empty()) {
      past_.emplace_back();
    } else {
      past_.push_back(std::move(spare.back()));
      spare.pop_back();
    }
    SensedFrame& f = past_.back();
    f.robot = robot_;
    f.robot.heading = RobotHeading(robot_, robot_.heading);
    f.frame = Frame::Make(f.robot.position, f.robot.heading);
    const std::span<const AgentState> present = present_humans();
    f.humans.assign(present.begin(), present.end());
    f.human_ids.assign(present_ids_.begin(), present_ids_.end());
  }
  if (!record_) return;
  result_.trajectory.push_back(EpisodeFrame{time_, robot_, humans_, present_});
  // A holonomic robot's heading is its goal's direction, set when it senses: set it now.
  AgentState& robot = result_.trajectory.back().robot;
  robot.heading = RobotHeading(robot, robot.heading);
}

}  // namespace crowdsim
