#include "plan_sampler.h"

#include <ompl/base/ProblemDefinition.h>
#include <ompl/base/goals/GoalState.h>
#include <ompl/base/spaces/RealVectorStateSpace.h>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace crowdsim::ompl_planner {

namespace ob = ::ompl::base;

namespace {

Vec2 Get(const ob::State* s) {
  const auto* v = s->as<ob::RealVectorStateSpace::StateType>();
  return Vec2(v->values[0], v->values[1]);
}

Vec2 Clamp(const Rect& box, const Vec2& p) {
  return Vec2(std::clamp(p.x(), box.min.x(), box.max.x()),
              std::clamp(p.y(), box.min.y(), box.max.y()));
}

// Draws that give up after this many misses of the box, whatever OMPL asks for (BIT* asks
// for UINT_MAX), so that a call always returns.
constexpr unsigned int kMaxDraws = 1000;

}  // namespace

SeededStateSampler::SeededStateSampler(const ob::StateSpace* space,
                                       std::shared_ptr<SampleSource> source)
    : StateSampler(space), source_(std::move(source)), rng_(source_->NextStream()) {}

void SeededStateSampler::Set(ob::State* state, Vec2 p) const {
  auto* v = state->as<ob::RealVectorStateSpace::StateType>();
  v->values[0] = p.x();
  v->values[1] = p.y();
  source_->budget().drawn.fetch_add(1, std::memory_order_relaxed);
}

void SeededStateSampler::sampleUniform(ob::State* state) {
  const Rect& box = source_->box();
  const double x = rng_.Uniform(box.min.x(), box.max.x());
  const double y = rng_.Uniform(box.min.y(), box.max.y());
  Set(state, Vec2(x, y));
}

void SeededStateSampler::sampleUniformNear(ob::State* state, const ob::State* near,
                                           double distance) {
  const Vec2 c = Get(near);
  const double x = rng_.Uniform(c.x() - distance, c.x() + distance);
  const double y = rng_.Uniform(c.y() - distance, c.y() + distance);
  Set(state, Clamp(source_->box(), Vec2(x, y)));
}

void SeededStateSampler::sampleGaussian(ob::State* state, const ob::State* mean, double std_dev) {
  const Vec2 c = Get(mean);
  const double x = c.x() + std_dev * rng_.Normal();
  const double y = c.y() + std_dev * rng_.Normal();
  Set(state, Clamp(source_->box(), Vec2(x, y)));
}

SeededInformedSampler::SeededInformedSampler(const ob::ProblemDefinitionPtr& problem,
                                             unsigned int max_calls,
                                             std::shared_ptr<SampleSource> source)
    : InformedSampler(problem, max_calls), source_(std::move(source)), rng_(source_->NextStream()) {
  // One start and one goal state: the only problems GlobalPlanner poses.
  start_ = Get(problem->getStartState(0));
  goal_ = Get(problem->getGoal()->as<ob::GoalState>()->getState());
}

bool SeededInformedSampler::Draw(double cost, Vec2* p) {
  const Rect& box = source_->box();
  source_->budget().drawn.fetch_add(1, std::memory_order_relaxed);
  if (!std::isfinite(cost)) {
    *p = Vec2(rng_.Uniform(box.min.x(), box.max.x()), rng_.Uniform(box.min.y(), box.max.y()));
    return true;
  }
  const Vec2 axis = goal_ - start_;
  const double focal = axis.norm();
  const double a = 0.5 * cost;
  const double b = 0.5 * std::sqrt(std::max(0.0, cost * cost - focal * focal));
  // Uniform in the unit disc, stretched to the ellipse and turned onto the start-goal axis.
  const double r = std::sqrt(rng_.Uniform());
  const double t = rng_.Uniform(0.0, 2.0 * std::numbers::pi);
  const Vec2 u = focal > 0.0 ? Vec2(axis / focal) : Vec2(1.0, 0.0);
  const Vec2 local(a * r * std::cos(t), b * r * std::sin(t));
  *p = 0.5 * (start_ + goal_) + local.x() * u + local.y() * Vec2(-u.y(), u.x());
  return box.Contains(*p);
}

bool SeededInformedSampler::sampleUniform(ob::State* state, const ob::Cost& max_cost) {
  return sampleUniform(state, ob::Cost(0.0), max_cost);
}

bool SeededInformedSampler::sampleUniform(ob::State* state, const ob::Cost& min_cost,
                                          const ob::Cost& max_cost) {
  const unsigned int draws = std::min(numIters_, kMaxDraws);
  for (unsigned int i = 0; i < draws; ++i) {
    Vec2 p;
    if (!Draw(max_cost.value(), &p)) continue;
    if ((p - start_).norm() + (p - goal_).norm() < min_cost.value()) continue;
    auto* v = state->as<ob::RealVectorStateSpace::StateType>();
    v->values[0] = p.x();
    v->values[1] = p.y();
    return true;
  }
  return false;
}

double SeededInformedSampler::getInformedMeasure(const ob::Cost& current_cost) const {
  const Vec2 size = source_->box().Size();
  const double box_area = size.x() * size.y();
  const double c = current_cost.value();
  if (!std::isfinite(c)) return box_area;
  const double focal = (goal_ - start_).norm();
  const double b = 0.5 * std::sqrt(std::max(0.0, c * c - focal * focal));
  return std::min(box_area, std::numbers::pi * 0.5 * c * b);
}

ob::InformedSamplerPtr PlanObjective::allocInformedStateSampler(
    const ob::ProblemDefinitionPtr& problem, unsigned int max_calls) const {
  return std::make_shared<SeededInformedSampler>(problem, max_calls, source_);
}

}  // namespace crowdsim::ompl_planner
