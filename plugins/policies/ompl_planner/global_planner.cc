#include "global_planner.h"

#include <ompl/base/ProblemDefinition.h>
#include <ompl/base/ScopedState.h>
#include <ompl/base/SpaceInformation.h>
#include <ompl/base/spaces/RealVectorStateSpace.h>
#include <ompl/geometric/PathGeometric.h>
#include <ompl/geometric/PathSimplifier.h>
#include <ompl/geometric/SimpleSetup.h>
#include <ompl/util/Console.h>

#include <algorithm>
#include <stdexcept>

#include "plan_sampler.h"
#include "plan_validity.h"
#include "planner_factory.h"

namespace crowdsim::ompl_planner {

namespace ob = ::ompl::base;
namespace og = ::ompl::geometric;

namespace {

// OMPL's PathSimplifier draws from a protected RNG; seed it like the planners.
class SeededSimplifier final : public og::PathSimplifier {
 public:
  SeededSimplifier(const ob::SpaceInformationPtr& si, std::uint32_t seed) : PathSimplifier(si) {
    rng_.setLocalSeed(seed);
  }
};

std::uint32_t Seed32(std::uint64_t seed) {
  return static_cast<std::uint32_t>(SplitMix64(seed) >> 32);
}

bool DiscFree(const CollisionWorld& world, const Vec2& p, double radius) {
  return world.map().bounds.Contains(p) && !world.DiscOverlaps(p, radius);
}

}  // namespace

bool SegmentClear(const CollisionWorld& world, const Vec2& a, const Vec2& b, double radius) {
  return world.SweepDisc(a, b, radius).fraction == kInfinity;
}

double PathLength(const std::vector<Vec2>& path) {
  double length = 0.0;
  for (std::size_t i = 1; i < path.size(); ++i) length += (path[i] - path[i - 1]).norm();
  return length;
}

GlobalPlanner::GlobalPlanner(std::shared_ptr<const CollisionWorld> world, PlanSettings settings)
    : world_(std::move(world)), settings_(std::move(settings)) {
  if (FindPlanner(settings_.planner) == nullptr) {
    throw std::invalid_argument("ompl_planner: planner: '" + settings_.planner +
                                "' is not valid; valid planners: " + PlannerNameList());
  }
  if (settings_.plan_samples < 1 || settings_.plan_time_s < 0.0 || settings_.plan_attempts < 1) {
    throw std::invalid_argument(
        "ompl_planner: plan_samples must be >= 1, plan_time_s >= 0 and plan_attempts >= 1");
  }
  // OMPL reports every solve at INFO level on stderr; a suite plans thousands of times.
  static const bool quiet = [] {
    ::ompl::msg::setLogLevel(::ompl::msg::LOG_ERROR);
    return true;
  }();
  (void)quiet;
}

PlanResult GlobalPlanner::Plan(const Vec2& start, const Vec2& goal, double radius,
                               std::uint64_t seed) const {
  PlanResult result;
  std::vector<double> margins = {settings_.margin};
  if (settings_.margin > 0.0) {
    margins.push_back(0.5 * settings_.margin);
    margins.push_back(0.0);
  }
  for (double margin : margins) {
    const double r = radius + margin;
    // A start or goal closer to a wall than the margin would make every path invalid.
    if (!DiscFree(*world_, start, r) || !DiscFree(*world_, goal, r)) continue;
    result.margin = margin;
    if (SegmentClear(*world_, start, goal, r)) {
      result.solved = true;
      result.path = {start, goal};
      result.length = PathLength(result.path);
      return result;
    }
    Rng seeds(seed);
    for (int k = 0; k < settings_.plan_attempts; ++k) {
      const std::int64_t budget = settings_.plan_samples << k;
      if (Attempt(start, goal, r, budget, seeds.NextU64(), &result)) return result;
    }
  }
  result.solved = false;
  result.path.clear();
  return result;
}

bool GlobalPlanner::Attempt(const Vec2& start, const Vec2& goal, double radius, std::int64_t budget,
                            std::uint64_t seed, PlanResult* result) const {
  const Rect& bounds = world_->map().bounds;
  auto space = std::make_shared<ob::RealVectorStateSpace>(2);
  ob::RealVectorBounds box(2);
  box.setLow(0, bounds.min.x());
  box.setLow(1, bounds.min.y());
  box.setHigh(0, bounds.max.x());
  box.setHigh(1, bounds.max.y());
  space->setBounds(box);

  auto counter = std::make_shared<SampleBudget>();
  auto source = std::make_shared<SampleSource>(bounds, SplitMix64(seed ^ 0x5A17ull), counter);
  space->setStateSamplerAllocator([source](const ob::StateSpace* s) -> ob::StateSamplerPtr {
    return std::make_shared<SeededStateSampler>(s, source);
  });

  // Made by libompl, not here: a planner's setup (tools::SelfConfig) files `si` in a static map
  // of OMPL's through a weak_ptr, dropped only by a later setup or at exit. Dropping it frees
  // the shared_ptr's control block through its vtable, which must not be this plugin's: the
  // harness unloads the plugin before exit (libompl stays), and with std::make_shared here the
  // vtable was the plugin's, so the process crashed on exit (SIGSEGV, exit code 139) after
  // every run or validate with `local: actions` (with `local: orca` a thread-local of the ORCA
  // code happened to keep the plugin mapped).
  const ob::SpaceInformationPtr si = og::SimpleSetup(space).getSpaceInformation();
  si->setStateValidityChecker(std::make_shared<DiscValidityChecker>(si, world_, radius));
  si->setMotionValidator(std::make_shared<SweptMotionValidator>(si, world_, radius));
  si->setup();

  auto problem = std::make_shared<ob::ProblemDefinition>(si);
  ob::ScopedState<ob::RealVectorStateSpace> s(space), g(space);
  s[0] = start.x();
  s[1] = start.y();
  g[0] = goal.x();
  g[1] = goal.y();
  problem->setStartAndGoalStates(s, g, 1e-3);
  auto objective = std::make_shared<PlanObjective>(si, source);
  // Optimising planners stop early only on the straight line (never, in practice): the
  // sample budget, not luck, decides how long they improve the path.
  objective->setCostThreshold(ob::Cost((goal - start).norm() * (1.0 + 1e-9)));
  problem->setOptimizationObjective(objective);

  ob::PlannerPtr planner = MakePlanner(settings_.planner, si, Seed32(seed));
  planner->setProblemDefinition(problem);
  planner->setup();

  ob::PlannerStatus status;
  if (settings_.plan_time_s > 0.0) {
    status = planner->solve(ob::timedPlannerTerminationCondition(settings_.plan_time_s));
  } else {
    // Samples, not seconds: the same budget stops at the same place on any machine. The
    // evaluation cap only guards against a planner that stops sampling.
    const std::int64_t max_evaluations = 100 * budget + 10000;
    status = planner->solve(ob::PlannerTerminationCondition([counter, budget, max_evaluations] {
      return counter->drawn.load(std::memory_order_relaxed) >= budget ||
             counter->evaluations.fetch_add(1, std::memory_order_relaxed) >= max_evaluations;
    }));
  }
  ++result->attempts;
  result->samples += counter->drawn.load();
  if (status != ob::PlannerStatus::EXACT_SOLUTION || !problem->hasExactSolution()) return false;

  og::PathGeometric path = *problem->getSolutionPath()->as<og::PathGeometric>();
  if (settings_.simplify) {
    SeededSimplifier simplifier(si, Seed32(seed ^ 0x51ull));
    og::PathGeometric simplified = path;
    simplifier.reduceVertices(simplified);
    simplifier.collapseCloseVertices(simplified);
    simplifier.shortcutPath(simplified);
    simplifier.reduceVertices(simplified);
    if (simplified.check()) path = simplified;
  }
  std::vector<Vec2> points;
  points.reserve(path.getStateCount() + 1);
  for (std::size_t i = 0; i < path.getStateCount(); ++i) {
    const auto* v = path.getState(i)->as<ob::RealVectorStateSpace::StateType>();
    points.emplace_back(v->values[0], v->values[1]);
  }
  // The goal is reached within 1e-3 m; end exactly on it when that keeps the path clear.
  if (points.empty()) return false;
  if (points.back() != goal) {
    if (points.size() >= 2 && SegmentClear(*world_, points[points.size() - 2], goal, radius)) {
      points.back() = goal;
    } else {
      points.push_back(goal);
    }
  }
  points.front() = start;
  result->solved = true;
  result->path = std::move(points);
  result->length = PathLength(result->path);
  return true;
}

}  // namespace crowdsim::ompl_planner
