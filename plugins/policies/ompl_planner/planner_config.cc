#include "planner_config.h"

#include <cmath>
#include <stdexcept>

namespace crowdsim::ompl_planner {

const std::vector<PlannerInfo>& Planners() {
  // Determinism is by construction for the first five (every random draw comes from a seeded
  // generator, single thread, exact nearest neighbours); see README.md for the others.
  static const std::vector<PlannerInfo> kPlanners = {
      {"rrtstar", "ompl::geometric::RRTstar", true, true},
      {"informed_rrtstar", "ompl::geometric::InformedRRTstar", true, true},
      {"rrtconnect", "ompl::geometric::RRTConnect", false, true},
      {"rrt", "ompl::geometric::RRT", false, true},
      {"lazyprmstar", "ompl::geometric::LazyPRMstar", true, true},
      {"bitstar", "ompl::geometric::BITstar", true, false},
      {"prmstar", "ompl::geometric::PRMstar", true, false},
  };
  return kPlanners;
}

const PlannerInfo* FindPlanner(const std::string& name) {
  for (const PlannerInfo& p : Planners()) {
    if (name == p.name) return &p;
  }
  return nullptr;
}

std::string PlannerNameList() {
  std::string out;
  for (const PlannerInfo& p : Planners()) {
    if (!out.empty()) out += ", ";
    out += p.name;
  }
  return out;
}

ParamSchema Schema() {
  std::vector<std::string> names;
  for (const PlannerInfo& p : Planners()) names.emplace_back(p.name);
  return {
      {"planner", ParamType::kString, std::string("rrtstar"), 0, 0, names,
       "OMPL planner for the global path (see README for which are deterministic)"},
      {"plan_samples",
       ParamType::kInt,
       std::int64_t{1500},
       1,
       10000000,
       {},
       "state samples per planning attempt (the deterministic budget)"},
      {"plan_time_s",
       ParamType::kDouble,
       0.0,
       0.0,
       60.0,
       {},
       "s; > 0 replaces the sample budget by wall time: NOT deterministic"},
      {"plan_attempts",
       ParamType::kInt,
       std::int64_t{3},
       1,
       10,
       {},
       "attempts per plan, attempt k with 2^k times the budget"},
      {"margin",
       ParamType::kDouble,
       0.1,
       0.0,
       2.0,
       {},
       "m; the planned path keeps robot radius + margin from every rectangle"},
      {"simplify",
       ParamType::kBool,
       true,
       0,
       1,
       {},
       "shortcut and prune the planner's path (OMPL PathSimplifier, seeded)"},
      {"replan_stall_steps",
       ParamType::kInt,
       std::int64_t{8},
       1,
       1000,
       {},
       "decisions without 5 cm of progress along the path before replanning"},
      {"local",
       ParamType::kString,
       std::string("orca"),
       0,
       0,
       {"orca", "actions"},
       "people avoidance: orca (the ORCA solver) or actions (16-action set vs predictions)"},
      {"time_horizon",
       ParamType::kDouble,
       5.0,
       0.1,
       60.0,
       {},
       "s; orca: collisions with people are avoided this far ahead"},
      {"time_horizon_obst",
       ParamType::kDouble,
       2.0,
       0.1,
       60.0,
       {},
       "s; orca: collisions with rectangles are avoided this far ahead"},
      {"safety_space",
       ParamType::kDouble,
       0.05,
       0.0,
       1.0,
       {},
       "m; orca: added to every person's radius in the solve"},
      {"max_neighbors",
       ParamType::kInt,
       std::int64_t{10},
       0,
       100,
       {},
       "orca: nearest people avoided"},
      {"neighbor_dist",
       ParamType::kDouble,
       10.0,
       0.0,
       100.0,
       {},
       "m; orca: people whose centre is closer are avoided"},
      {"action_horizon_s",
       ParamType::kDouble,
       1.0,
       0.0,
       10.0,
       {},
       "s; actions: how far the constant-velocity predictions are checked"},
      {"action_clearance",
       ParamType::kDouble,
       0.1,
       0.0,
       2.0,
       {},
       "m; actions: surface distance kept from every predicted person"},
  };
}

namespace {

[[noreturn]] void Bad(const std::string& key, const std::string& value, const std::string& valid) {
  throw std::invalid_argument("ompl_planner: " + key + ": " + value + " is not valid; " + valid);
}

double Range(const Params& p, const std::string& key, double lo, double hi) {
  const double v = p.GetDouble(key);
  if (!(v >= lo && v <= hi)) {
    Bad(key, FormatParamValue(v),
        "give a value in [" + FormatParamValue(lo) + ", " + FormatParamValue(hi) + "]");
  }
  return v;
}

std::int64_t IntRange(const Params& p, const std::string& key, std::int64_t lo, std::int64_t hi) {
  const std::int64_t v = p.GetInt(key);
  if (v < lo || v > hi) {
    Bad(key, std::to_string(v),
        "give an integer in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]");
  }
  return v;
}

}  // namespace

PolicyConfig ConfigFromParams(const Params& params) {
  // The host checks ranges and choices against Schema() before the factory runs; this
  // repeats the checks so a policy made directly (tests, tools) fails just as clearly.
  PolicyConfig c;
  c.plan.planner = params.GetString("planner");
  if (FindPlanner(c.plan.planner) == nullptr) {
    Bad("planner", "'" + c.plan.planner + "'", "valid planners: " + PlannerNameList());
  }
  c.plan.plan_samples = IntRange(params, "plan_samples", 1, 10000000);
  c.plan.plan_time_s = Range(params, "plan_time_s", 0.0, 60.0);
  c.plan.plan_attempts = static_cast<int>(IntRange(params, "plan_attempts", 1, 10));
  c.plan.margin = Range(params, "margin", 0.0, 2.0);
  c.plan.simplify = params.GetBool("simplify");
  c.replan_stall_steps = static_cast<int>(IntRange(params, "replan_stall_steps", 1, 1000));
  const std::string& local = params.GetString("local");
  if (local == "orca") {
    c.local = LocalMode::kOrca;
  } else if (local == "actions") {
    c.local = LocalMode::kActions;
  } else {
    Bad("local", "'" + local + "'", "valid: orca, actions");
  }
  c.time_horizon = Range(params, "time_horizon", 0.1, 60.0);
  c.time_horizon_obst = Range(params, "time_horizon_obst", 0.1, 60.0);
  c.safety_space = Range(params, "safety_space", 0.0, 1.0);
  c.max_neighbors = static_cast<int>(IntRange(params, "max_neighbors", 0, 100));
  c.neighbor_dist = Range(params, "neighbor_dist", 0.0, 100.0);
  c.action_horizon_s = Range(params, "action_horizon_s", 0.0, 10.0);
  c.action_clearance = Range(params, "action_clearance", 0.0, 2.0);
  return c;
}

}  // namespace crowdsim::ompl_planner
