// How a robot move ends, shared by steps and lookahead: policies plan with the rules that judge.
#include <cmath>

#include "crowdsim/bench/episode.h"

namespace crowdsim {

StepJudgement JudgeRobotMove(const SimConfig& sim, const CollisionWorld& world,
                             const AgentState& robot, const Vec2& robot_velocity,
                             std::span<const AgentState> humans, double time_after) {
  StepJudgement j;
  const double dt = sim.time_step;
  // CrowdNav's swept test: humans keep their velocity, the robot takes its action; closest approach
  // decides.
  const Vec2 origin = Vec2::Zero();
  int closest = -1;
  for (size_t i = 0; i < humans.size(); ++i) {
    const AgentState& h = humans[i];
    const Vec2 p = h.position - robot.position;
    const Vec2 e = p + (h.velocity - robot_velocity) * dt;
    const double d = PointToSegmentDistanceInline(p, e, origin) - h.radius - robot.radius;
    if (d < j.min_human_distance) {
      j.min_human_distance = d;
      closest = static_cast<int>(i);
    }
  }
  const bool hit_human = j.min_human_distance < 0.0;
  if (hit_human) j.human = closest;
  const Vec2 end = robot.position + robot_velocity * dt;
  bool hit_obstacle = false;
  if (!hit_human) {
    const SweepHit hit = world.SweepDisc(robot.position, end, robot.radius);
    hit_obstacle = hit.fraction <= 1.0;
    if (hit_obstacle) j.rect = hit.rect;
  }
  const bool reached = NormBelow(end - robot.goal, sim.goal_radius);

  if (hit_human) {
    j.event = StepEvent::kCollisionHuman;
    j.reward = sim.collision_penalty;
  } else if (hit_obstacle) {
    j.event = StepEvent::kCollisionObstacle;
    j.reward = sim.collision_penalty;
  } else if (reached) {
    j.event = StepEvent::kSuccess;
    j.reward = sim.success_reward;
  } else if (time_after >= sim.time_limit - 1e-9) {
    j.event = StepEvent::kTimeout;
    j.reward = 0.0;
  } else if (j.min_human_distance < sim.discomfort_dist) {
    j.event = StepEvent::kDanger;
    j.reward = (j.min_human_distance - sim.discomfort_dist) * sim.discomfort_penalty_factor * dt;
  }
  return j;
}

}  // namespace crowdsim
