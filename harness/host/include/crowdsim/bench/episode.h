// The episode loop: sense -> decide (robot + humans) -> move all -> check -> record.
#pragma once

#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "crowdsim/agent_index.h"
#include "crowdsim/bench/social_metrics.h"
#include "crowdsim/collision_world.h"
#include "crowdsim/kinematics.h"
#include "crowdsim/lookahead.h"
#include "crowdsim/policy.h"
#include "crowdsim/rng.h"
#include "crowdsim/scenario.h"
#include "crowdsim/sensor.h"
#include "crowdsim/sim_config.h"
#include "crowdsim/world_source.h"

namespace crowdsim {

/// kPolicyCrash and kPolicyTimeout come from the runner: an isolated worker died or timed out.
enum class EpisodeStatus {
  kRunning,
  kSuccess,
  kCollisionHuman,
  kCollisionObstacle,
  kTimeout,
  kPolicyError,
  kPolicyCrash,
  kPolicyTimeout
};

const char* EpisodeStatusName(EpisodeStatus s);

/// A velocity above this multiple of v_pref is a policy_error: a unit or sign bug (linear allows
/// 2x).
inline constexpr double kMaxSpeedFactor = 10.0;

/// The sensors' noise stream of an episode (SenseInput::noise_seed), apart from the agents'.
inline std::uint64_t SensorNoiseSeed(std::uint64_t scenario_seed) {
  return SplitMix64(scenario_seed ^ 0x73656e736f727321ULL);  // "sensors!"
}

/// Throws std::invalid_argument for a scenario without a meaningful episode: robot start or goal
/// off-map or blocked, a start disc overlapping beyond kStartOverlapTolerance, start within
/// goal_radius.
void CheckScenario(const Scenario& scenario, const SimConfig& sim);

/// How far (m) a start disc may reach into an obstacle: floor-plan points are within tenths of a
/// millimetre.
inline constexpr double kStartOverlapTolerance = 1e-3;

/// Throws std::invalid_argument when a world made other than the requested number of humans
/// (humans.count would misdescribe the episode).
void CheckHumanCount(const ScenarioRequest& request, const Scenario& scenario);

/// A sensor configured on the robot.
struct MountedSensor {
  std::string name;  ///< plugin name, copied into SensorReading::sensor
  const Sensor* sensor = nullptr;
};

/// The policies and sensors of one episode (not owned; reused across episodes by a worker).
struct EpisodeAgents {
  Policy* robot = nullptr;
  std::vector<Policy*> humans;  ///< one per human in the scenario (or more)
  std::vector<MountedSensor> sensors;
  RobotKinematics kinematics;  ///< the robot's motion model (the row's `kinematics:`)
};

/// Why a policy with `needs` cannot drive a robot with `k` ("" when it can): the fix included.
std::string KinematicsRefusal(const PolicyNeeds& needs, const RobotKinematics& k);

/// Positions of everybody at one time (rendering, tests).
struct EpisodeFrame {
  double time = 0.0;
  AgentState robot;
  std::vector<AgentState> humans;
  std::vector<char> present;  ///< per human, whether present (recorded crowds); empty: everybody
  /// Whether human i is present in this frame.
  bool Present(std::size_t i) const { return present.empty() || present[i] != 0; }
};

/// The people present in `f` and their scenario indices (`ids` empty when everybody is): what
/// the sensors were handed at that step.
void PresentPeople(const EpisodeFrame& f, std::vector<AgentState>* humans, std::vector<int>* ids);

/// An episode's status and metrics: what episodes.csv stores and rows aggregate (kEpisodeColumns).
struct EpisodeOutcome {
  EpisodeStatus status = EpisodeStatus::kRunning;
  double time = 0.0;  ///< s at the end
  int steps = 0;
  int danger_steps = 0;                   ///< steps with a human closer than discomfort_dist
  double path_length = 0.0;               ///< m travelled by the robot
  double min_human_distance = kInfinity;  ///< min surface distance robot-human over the episode
  double discounted_return = 0.0;         ///< sum_t gamma^(t*dt*v_pref) r_t
  double decision_time_us = 0.0;          ///< mean wall time of the robot's Decide
  int humans_at_goal = 0;                 ///< humans that reached their (first) goal
  double max_speed = 0.0;                 ///< m/s; the robot's highest speed over the episode
  std::string error;                      ///< policy_error message
  SocialMetrics social;                   ///< when the suite asks for them (docs/metrics.md)
};

/// An outcome plus what only a live episode knows: whom it hit and, when recording, the trajectory.
struct EpisodeResult : EpisodeOutcome {
  int collided_human = -1;  ///< collision_human: which human (index into the scenario's)
  int collided_rect = -1;   ///< collision_obstacle: which rectangle of the map
  std::vector<EpisodeFrame> trajectory;  ///< when recording
};

/// What one step did.
struct StepInfo {
  StepEvent event = StepEvent::kNone;
  double reward = 0.0;
  Action robot_action;  ///< as decided (a command may be clipped by the kinematics' limits)
  double min_human_distance = kInfinity;  ///< this step's swept surface distance
};

/// A running episode. Owns the state; the policies are borrowed.
class Episode {
 public:
  Episode(const Scenario& scenario, const SimConfig& sim, const EpisodeAgents& agents,
          bool record_trajectory = false);
  ~Episode();

  bool done() const { return result_.status != EpisodeStatus::kRunning; }
  /// Advances one step (no-op when done). A plugin's exception ends the episode as policy_error;
  /// AbortRun passes through.
  StepInfo Step();
  /// Runs to the end.
  const EpisodeResult& Run();
  /// Moves the people one step as if there were no robot: their decisions and moves alone, no
  /// robot decision, judgement or end (throws what a human policy throws). With
  /// sim.robot_visible false it is the world without the robot (the people effect's replay).
  void StepPeopleOnly();

  const EpisodeResult& result() const { return result_; }
  double time() const { return time_; }
  const AgentState& robot() const { return robot_; }
  /// Every human of the scenario, present or not (indices are the scenario's).
  std::span<const AgentState> humans() const { return humans_; }
  /// The humans present now: what the sensors, the judgement and the other people see. Every
  /// human unless the scenario's people appear and leave (HumanSpec::appear, leave).
  std::span<const AgentState> present_humans() const {
    return all_present_ ? std::span<const AgentState>(humans_) : present_humans_;
  }
  /// The scenario index of each of present_humans(); empty when everybody is always present.
  std::span<const int> present_ids() const { return present_ids_; }
  const CollisionWorld& world() const { return world_; }
  const Scenario& scenario() const { return scenario_; }
  const SimConfig& sim() const { return sim_; }
  const RobotKinematics& kinematics() const { return agents_.kinematics; }
  const EpisodeAgents& agents() const { return agents_; }
  int steps() const { return step_index_; }
  /// The robot observation the last Step() gave to the robot policy.
  const Observation& last_robot_observation() const { return robot_obs_; }
  /// The robot's observation now, without decision or lookahead (e.g. to bootstrap from). It
  /// replaces last_robot_observation(); the next Step() decides on it without sensing again.
  const Observation& ObserveRobot();

 private:
  class StepLookahead;
  /// The sensors' readings at step `step` (a lookahead's: the next one, predicted).
  void Sense(const AgentState& robot, const Frame& frame, std::span<const AgentState> humans,
             std::span<const int> human_ids, int step, std::vector<SensorReading>* out,
             bool lookahead = false) const;
  void DecideHumans();
  /// Who is present at time_ (present_humans_, present_ids_); nothing when all always are.
  void UpdatePresence();
  /// Every human moves with its decided velocity for one step.
  void MoveHumans();
  /// Human i's decision into human_actions_[i], `view` its index among the present (throws what
  /// its policy or the checks throw).
  void DecideHuman(int i, int view);
  void FillRobotObservation();
  /// What `action` does from the robot's current motion (throws for a form the robot refuses).
  ExecutedMove Execute(const Action& action) const;
  /// The robot's heading and frame after a move: its own for a non-holonomic robot, else its
  /// goal's.
  double RobotHeading(const AgentState& robot, double executed_heading) const;
  void Finish(EpisodeStatus status);
  void Record();
  /// The frames before `step` the sensors read (the last history_steps_ of them, or all).
  std::span<const SensedFrame> Past(int step) const;

  const Scenario& scenario_;
  SimConfig sim_;
  EpisodeAgents agents_;
  CollisionWorld world_;
  bool record_;
  // The most earlier steps a sensor reads (-1: all; 0: none, and no frame is kept), the frames
  // kept for them (one a step, from step 0) and the id that names this episode's history.
  int history_steps_ = 0;
  std::vector<SensedFrame> past_;
  std::uint64_t history_id_ = 0;
  PolicyNeeds robot_needs_;
  std::vector<PolicyNeeds> human_needs_;

  double time_ = 0.0;
  int step_index_ = 0;
  AgentState robot_;
  double robot_linear_ = 0.0;   ///< non-holonomic: executed last step, m/s
  double robot_angular_ = 0.0;  ///< non-holonomic: executed last step, rad/s
  std::vector<AgentState> humans_;
  // Presence: all_present_ unless a human appears or leaves; then the present ones' states and
  // scenario indices, refreshed after every move.
  bool all_present_ = true;
  std::vector<char> present_;
  std::vector<AgentState> present_humans_;
  std::vector<int> present_ids_;    // increasing
  std::vector<int> by_appear_;      // every human, in order of appear (then index)
  std::size_t next_to_appear_ = 0;  // by_appear_'s first not yet come
  std::vector<int> left_;           // left at the last presence update: they stop at the next move
  std::vector<std::size_t> human_goal_index_;
  std::vector<bool> human_reached_;
  std::vector<Action> human_actions_;
  std::vector<AgentState> human_view_;  // agents humans see (humans + robot if visible)
  AgentIndex human_index_;
  // Distracted people's view of a visible robot's episode: the humans alone (null: none).
  std::unique_ptr<AgentIndex> unaware_index_;
  Observation robot_obs_;
  bool robot_obs_current_ = false;  ///< robot_obs_ shows the current state (ObserveRobot)
  Observation human_obs_;
  std::unique_ptr<StepLookahead> lookahead_;
  std::uint64_t decision_ticks_ = 0;  ///< the robot's Decide calls, DecisionClock ticks
  EpisodeResult result_;
};

/// What a robot move does, judged as a real step: swept human and obstacle tests, goal, discomfort,
/// timeout.
struct StepJudgement {
  StepEvent event = StepEvent::kNone;
  double reward = 0.0;
  double min_human_distance = kInfinity;
  int human = -1;  ///< kCollisionHuman: index of the human hit (the closest approach)
  int rect = -1;   ///< kCollisionObstacle: index of the rectangle hit (StaticMap::rectangles)
};
StepJudgement JudgeRobotMove(const SimConfig& sim, const CollisionWorld& world,
                             const AgentState& robot, const Vec2& robot_velocity,
                             std::span<const AgentState> humans, double time_after);

}  // namespace crowdsim
