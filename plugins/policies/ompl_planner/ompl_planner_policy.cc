#include "ompl_planner_policy.h"

#include <algorithm>
#include <stdexcept>

#include "action_set.h"

namespace crowdsim::ompl_planner {

OmplPlannerPolicy::OmplPlannerPolicy(const Params& params)
    : OmplPlannerPolicy(ConfigFromParams(params)) {}

OmplPlannerPolicy::OmplPlannerPolicy(PolicyConfig config) : config_(std::move(config)) {
  if (FindPlanner(config_.plan.planner) == nullptr) {
    throw std::invalid_argument("ompl_planner: planner: '" + config_.plan.planner +
                                "' is not valid; valid planners: " + PlannerNameList());
  }
}

PolicyNeeds OmplPlannerPolicy::Needs() const {
  PolicyNeeds needs;
  needs.map = true;
  needs.sensors = {"person"};
  needs.non_holonomic = NonHolonomicDrive::kTrackVelocity;  // turn-then-go (docs/kinematics.md)
  return needs;
}

void OmplPlannerPolicy::UseMap(const StaticMap* map) {
  if (map == nullptr) {
    throw std::runtime_error("ompl_planner: no map; the policy plans on the known map");
  }
  // Compare with copies: the map an earlier episode used may be gone, its address reused.
  if (map == map_ && world_ != nullptr && map->rectangles == map_rects_ &&
      map->bounds == map_bounds_) {
    return;
  }
  map_ = map;
  map_rects_ = map->rectangles;
  map_bounds_ = map->bounds;
  // The harness owns the map and keeps it alive for the episode: share it without owning.
  world_ = std::make_shared<const CollisionWorld>(
      std::shared_ptr<const StaticMap>(map, [](const StaticMap*) {}));
  planner_ = std::make_unique<GlobalPlanner>(world_, config_.plan);
  obstacles_ = orca::OrcaObstacles::FromMap(*map);
}

void OmplPlannerPolicy::Reset(const EpisodeContext& ctx) {
  ctx_map_ = ctx.map;
  UseMap(ctx.map);
  rng_ = Rng(ctx.seed);
  time_step_ = ctx.sim.time_step;
  robot_radius_ = ctx.sim.robot_radius;
  follower_.Clear();
  path_margin_ = 0.0;
  planned_goal_ = Vec2::Zero();
  plan_failed_ = false;
  steps_since_failed_plan_ = 0;
  stats_ = PlannerStats{};
}

void OmplPlannerPolicy::Replan(const AgentState& self) {
  // Each plan of the episode takes the next number of the episode's stream: the k-th plan
  // is the same whichever thread runs the episode.
  const PlanResult plan = planner_->Plan(self.position, self.goal, self.radius, rng_.NextU64());
  ++stats_.plans;
  stats_.samples += plan.samples;
  planned_goal_ = self.goal;
  if (plan.solved) {
    follower_.SetPath(plan.path);
    path_margin_ = plan.margin;
    plan_failed_ = false;
  } else {
    ++stats_.failed_plans;
    follower_.Clear();
    plan_failed_ = true;
    steps_since_failed_plan_ = 0;
  }
}

void OmplPlannerPolicy::GatherPeople(const Observation& obs) {
  people_.clear();
  const SensorReading* reading = obs.Reading("person");
  if (reading == nullptr) return;
  const double range_sq = config_.neighbor_dist * config_.neighbor_dist;
  for (const PersonObservation& person : reading->people) {
    const Vec2 position = obs.frame.origin + obs.frame.VectorToWorld(person.position);
    if ((position - obs.self.position).squaredNorm() >= range_sq) continue;
    people_.push_back({position, obs.frame.VectorToWorld(person.velocity), person.radius});
  }
  // Nearest first, as ORCA expects; stable so equal distances keep the sensor's order.
  std::stable_sort(people_.begin(), people_.end(),
                   [&](const orca::OrcaAgent& a, const orca::OrcaAgent& b) {
                     return (a.position - obs.self.position).squaredNorm() <
                            (b.position - obs.self.position).squaredNorm();
                   });
}

Action OmplPlannerPolicy::Decide(const Observation& obs) {
  if (world_ == nullptr || ctx_map_ != map_) UseMap(ctx_map_);
  const AgentState& self = obs.self;
  const double time_step = time_step_;
  // Half the margin the current path was planned with: every path segment stays in sight from
  // the one before it, with room for small deviations. Read after any replanning below: a
  // value taken before it would be the previous path's (at an episode's first step, the
  // previous episode's, which made results depend on which episodes a worker ran before).
  const auto sight_radius = [&] { return self.radius + 0.5 * path_margin_; };

  // Plan when there is no path, the goal moved, the path is out of sight, or no progress.
  // After a failed plan, retry only every replan_stall_steps decisions (planning is costly).
  int target = -1;
  if (plan_failed_) {
    if (++steps_since_failed_plan_ >= config_.replan_stall_steps) Replan(self);
  } else if (!follower_.has_path() || self.goal != planned_goal_) {
    Replan(self);
  } else {
    target = follower_.FarthestVisible(*world_, self.position, sight_radius());
    if (target < 0 ||
        follower_.Stalled(follower_.Remaining(self.position, target), config_.replan_stall_steps)) {
      Replan(self);
      target = -1;
    }
  }
  if (target < 0 && follower_.has_path()) {
    target = follower_.FarthestVisible(*world_, self.position, sight_radius());
    if (target >= 0)
      follower_.Stalled(follower_.Remaining(self.position, target), config_.replan_stall_steps);
  }

  // Without a path in sight, head for the goal: the local planner keeps off the walls.
  const bool to_goal = target < 0 || target + 1 == static_cast<int>(follower_.path().size());
  const Vec2 aim = target < 0 ? self.goal : follower_.path()[target];
  const Vec2 pref = PreferredVelocity(self.position, aim, to_goal, self.v_pref, time_step);

  GatherPeople(obs);
  if (config_.local == LocalMode::kActions) {
    ActionSetParams params;
    params.v_pref = self.v_pref;
    params.radius = self.radius;
    params.time_step = time_step;
    params.horizon = config_.action_horizon_s;
    params.clearance = config_.action_clearance;
    return Action{ChooseAction(self.position, pref, people_, *world_, params)};
  }
  // The safety space goes on the people only: ORCA would apply the robot's radius to the
  // rectangles too, and the floor plans have passages the bare robot just fits through.
  std::vector<orca::OrcaAgent> neighbours;
  const int count = std::min<int>(config_.max_neighbors, static_cast<int>(people_.size()));
  neighbours.reserve(count);
  for (int i = 0; i < count; ++i) {
    orca::OrcaAgent a = people_[i];
    a.radius += config_.safety_space;
    neighbours.push_back(a);
  }
  orca::OrcaParams params;
  params.time_horizon = config_.time_horizon;
  params.time_horizon_obst = config_.time_horizon_obst;
  params.max_speed = self.v_pref;
  const orca::OrcaAgent me{self.position, self.velocity, self.radius};
  return Action{orca::ComputeOrcaVelocity(me, neighbours, obstacles_, params, pref, time_step)};
}

}  // namespace crowdsim::ompl_planner
