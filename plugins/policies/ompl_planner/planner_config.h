// The `ompl_planner` policy's settings: the parameter schema, and the checked values the
// policy runs with (OMPL-free, so tests and tools can include it).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "crowdsim/params.h"

namespace crowdsim::ompl_planner {

/// How the robot avoids people between path points.
enum class LocalMode { kOrca, kActions };

/// One OMPL planner the plugin offers.
struct PlannerInfo {
  const char* name;        ///< the value of the `planner` parameter
  const char* ompl_class;  ///< the OMPL class behind it
  bool optimizing;         ///< uses the whole sample budget to shorten the path
  bool deterministic;      ///< same seed and budget give the same path in any thread (README)
};

/// Every planner name, in the order error messages list them.
const std::vector<PlannerInfo>& Planners();
/// The entry for `name`, or null.
const PlannerInfo* FindPlanner(const std::string& name);
/// "a, b, c": the valid planner names for messages.
std::string PlannerNameList();

/// Global-planning settings (everything GlobalPlanner needs).
struct PlanSettings {
  std::string planner = "rrtstar";
  std::int64_t plan_samples = 1500;  ///< state samples per attempt (deterministic budget)
  double plan_time_s = 0.0;          ///< > 0: wall-time budget instead (not deterministic)
  int plan_attempts = 3;             ///< attempts per plan; attempt k gets 2^k times the budget
  double margin = 0.1;               ///< m added to the robot radius when planning
  bool simplify = true;              ///< shortcut and prune the planner's path
};

/// All settings of the policy.
struct PolicyConfig {
  PlanSettings plan;                   ///< the global planner's
  int replan_stall_steps = 8;          ///< decisions without 5 cm of progress before replanning
  LocalMode local = LocalMode::kOrca;  ///< people avoidance between path points
  // local: orca
  double time_horizon = 5.0;       ///< s; people avoided this far ahead
  double time_horizon_obst = 2.0;  ///< s; rectangles avoided this far ahead
  double safety_space = 0.05;      ///< m added to every person's radius in the ORCA solve
  int max_neighbors = 10;
  double neighbor_dist = 10.0;  ///< m
  // local: actions
  double action_horizon_s = 1.0;  ///< s of constant-velocity prediction
  double action_clearance = 0.1;  ///< m of surface distance kept from every prediction
};

/// The plugin's parameters, with defaults and ranges (documented in README.md).
ParamSchema Schema();

/// Reads and checks `params`; throws std::invalid_argument naming the key, the bad value
/// and the valid ones (also for values the host did not validate, e.g. in tests).
PolicyConfig ConfigFromParams(const Params& params);

}  // namespace crowdsim::ompl_planner
