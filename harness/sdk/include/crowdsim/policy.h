// Policy plugin interface: decides a velocity for the robot or a human.
#pragma once

#include <cstdint>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "crowdsim/action.h"
#include "crowdsim/export.h"
#include "crowdsim/kinematics.h"
#include "crowdsim/observation.h"
#include "crowdsim/scenario.h"
#include "crowdsim/sim_config.h"
#include "crowdsim/static_map.h"

namespace crowdsim {

enum class AgentRole { kRobot, kHuman };

/// How a robot policy drives a non-holonomic robot (RobotKinematics).
enum class NonHolonomicDrive {
  kNone,           ///< world velocities only: refused unless the row sets track_velocity
  kTrackVelocity,  ///< world velocities, which the harness's TrackVelocity turns into commands
  kCommands,       ///< Action::Command when EpisodeContext::kinematics is not holonomic
};

/// What a policy needs from the harness (checked before the first episode).
struct CROWDSIM_SDK_API PolicyNeeds {
  bool map = false;  ///< gets EpisodeContext::map (privileged knowledge of the layout)
  /// Robot only: gets Observation::lookahead. A humans' policy that sets it, or names sensors, is
  /// refused before the first episode.
  bool lookahead = false;
  std::vector<std::string> sensors;  ///< robot only: sensor names that must be configured
  /// Humans only: Observation::frame turned towards the goal (costs an atan2 and sincos); false:
  /// world-aligned (ORCA). The robot's frame always turns.
  bool heading_frame = true;
  /// Robot only: how it drives a non-holonomic robot; a holonomic robot always takes velocities.
  NonHolonomicDrive non_holonomic = NonHolonomicDrive::kNone;
};

/// Per-episode context for Reset: the episode's constants (time step, sim settings, map);
/// Observation carries what changes each step.
struct CROWDSIM_SDK_API EpisodeContext {
  /// The static map, given only to policies whose Needs().map is set (ORCA, planners); null
  /// for the others.
  const StaticMap* map = nullptr;
  SimConfig sim;  ///< sim.time_step: s between decisions
  AgentRole role = AgentRole::kRobot;
  std::uint64_t seed = 0;      ///< this agent's own stream for the episode
  int agent_id = 0;            ///< 0 = robot, 1.. = humans
  RobotKinematics kinematics;  ///< robot only: its motion model and limits
  /// Human only: its recorded track (HumanSpec::track), valid until the next Reset; empty: none.
  std::span<const TrackPoint> track = {};
};

class CROWDSIM_SDK_API Policy {
 public:
  virtual ~Policy();
  /// What the harness must provide; called once after construction.
  virtual PolicyNeeds Needs() const { return {}; }
  /// Called at the start of every episode (reset internal state, keep the episode's constants).
  virtual void Reset(const EpisodeContext& ctx);
  /// The action for this step. Throwing ends the episode with status policy_error.
  virtual Action Decide(const Observation& obs) = 0;
};

/// Thrown by a plugin to stop the whole run (Ctrl-C, a lost resource): the episode writes no line,
/// finished ones stay for resume. Bad decisions throw ordinary exceptions.
class CROWDSIM_SDK_API AbortRun : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
  ~AbortRun() override;
};

}  // namespace crowdsim
