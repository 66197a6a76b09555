#include "plan_validity.h"

#include <ompl/base/SpaceInformation.h>
#include <ompl/base/spaces/RealVectorStateSpace.h>

#include <algorithm>

namespace crowdsim::ompl_planner {

namespace ob = ::ompl::base;

namespace {

Vec2 Get(const ob::State* s) {
  const auto* v = s->as<ob::RealVectorStateSpace::StateType>();
  return Vec2(v->values[0], v->values[1]);
}

}  // namespace

DiscValidityChecker::DiscValidityChecker(const ob::SpaceInformationPtr& si,
                                         std::shared_ptr<const CollisionWorld> world, double radius)
    : StateValidityChecker(si), world_(std::move(world)), radius_(radius) {
  specs_.clearanceComputationType = ob::StateValidityCheckerSpecs::EXACT;
}

bool DiscValidityChecker::isValid(const ob::State* state) const {
  if (!si_->satisfiesBounds(state)) return false;
  return !world_->DiscOverlaps(Get(state), radius_);
}

double DiscValidityChecker::clearance(const ob::State* state) const {
  constexpr double kCap = 10.0;
  const double d = world_->ClearanceAt(Get(state), kCap + radius_);
  return std::min(kCap, d - radius_);
}

SweptMotionValidator::SweptMotionValidator(const ob::SpaceInformationPtr& si,
                                           std::shared_ptr<const CollisionWorld> world,
                                           double radius)
    : MotionValidator(si), world_(std::move(world)), radius_(radius) {}

bool SweptMotionValidator::checkMotion(const ob::State* s1, const ob::State* s2) const {
  // OMPL's contract: s1 is known valid; the end state must be checked too (bounds).
  const bool ok =
      si_->isValid(s2) && world_->SweepDisc(Get(s1), Get(s2), radius_).fraction == kInfinity;
  if (ok) {
    ++valid_;
  } else {
    ++invalid_;
  }
  return ok;
}

bool SweptMotionValidator::checkMotion(const ob::State* s1, const ob::State* s2,
                                       std::pair<ob::State*, double>& last_valid) const {
  const SweepHit hit = world_->SweepDisc(Get(s1), Get(s2), radius_);
  if (hit.fraction == kInfinity && si_->isValid(s2)) {
    ++valid_;
    return true;
  }
  // Stop just short of the contact (or of the end, when only the end is out of bounds).
  const double fraction = hit.fraction == kInfinity ? 1.0 : hit.fraction;
  last_valid.second = std::max(0.0, fraction - 1e-6);
  if (last_valid.first != nullptr) {
    si_->getStateSpace()->interpolate(s1, s2, last_valid.second, last_valid.first);
  }
  ++invalid_;
  return false;
}

}  // namespace crowdsim::ompl_planner
