// The `ompl_planner` policy: a global path planned with OMPL on the known map, followed
// towards its farthest visible point, with people avoided locally (ORCA or an action set).
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "crowdsim/collision_world.h"
#include "crowdsim/params.h"
#include "crowdsim/policy.h"
#include "crowdsim/rng.h"
#include "global_planner.h"
#include "orca/obstacles.h"
#include "orca/solver.h"
#include "path_follower.h"
#include "planner_config.h"

namespace crowdsim::ompl_planner {

/// Counters of one episode (tests, benchmarks).
struct PlannerStats {
  int plans = 0;             ///< Plan() calls
  int failed_plans = 0;      ///< calls that found no path
  std::int64_t samples = 0;  ///< state samples drawn
};

/// The robot policy (one instance per worker thread; not thread-safe itself).
class OmplPlannerPolicy final : public Policy {
 public:
  /// From validated plugin parameters; throws std::invalid_argument on bad values.
  explicit OmplPlannerPolicy(const Params& params);
  /// From settings already read (tests, tools).
  explicit OmplPlannerPolicy(PolicyConfig config);

  PolicyNeeds Needs() const override;
  void Reset(const EpisodeContext& ctx) override;
  Action Decide(const Observation& obs) override;

  /// The path being followed (world frame; empty before the first decision).
  const std::vector<Vec2>& path() const { return follower_.path(); }
  /// This episode's planning counters.
  const PlannerStats& stats() const { return stats_; }
  /// The settings in use.
  const PolicyConfig& config() const { return config_; }

 private:
  /// Builds the collision world, ORCA obstacles and planner when the map changed.
  void UseMap(const StaticMap* map);
  void Replan(const AgentState& self);
  void GatherPeople(const Observation& obs);

  PolicyConfig config_;

  // Per map (kept across episodes while the map is the same).
  const StaticMap* ctx_map_ = nullptr;  // the episode's (Reset)
  const StaticMap* map_ = nullptr;
  std::vector<Rect> map_rects_;  // copies: the old map may be gone when the next one comes
  Rect map_bounds_;
  std::shared_ptr<const CollisionWorld> world_;
  std::unique_ptr<GlobalPlanner> planner_;
  orca::OrcaObstacles obstacles_;

  // Per episode.
  Rng rng_{0};
  double time_step_ = SimConfig{}.time_step;
  double robot_radius_ = SimConfig{}.robot_radius;
  PathFollower follower_;
  Vec2 planned_goal_ = Vec2::Zero();
  double path_margin_ = 0.0;  // m, the margin the current path keeps
  int steps_since_failed_plan_ = 0;
  bool plan_failed_ = false;
  PlannerStats stats_;
  std::vector<orca::OrcaAgent> people_;
};

}  // namespace crowdsim::ompl_planner
