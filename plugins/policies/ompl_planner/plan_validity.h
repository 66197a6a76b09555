// OMPL validity for a disc robot among the map's rectangles, answered by the harness's own
// CollisionWorld (the geometry the episode judges collisions with; no second copy).
#pragma once

#include <ompl/base/MotionValidator.h>
#include <ompl/base/StateValidityChecker.h>

#include <memory>

#include "crowdsim/collision_world.h"

namespace crowdsim::ompl_planner {

/// A state is valid when the disc of `radius` (robot radius + margin) at it is inside the
/// map's bounds and overlaps no rectangle.
class DiscValidityChecker final : public ::ompl::base::StateValidityChecker {
 public:
  DiscValidityChecker(const ::ompl::base::SpaceInformationPtr& si,
                      std::shared_ptr<const CollisionWorld> world, double radius);
  bool isValid(const ::ompl::base::State* state) const override;
  /// Surface distance to the nearest rectangle (m), capped at 10 m.
  double clearance(const ::ompl::base::State* state) const override;

 private:
  std::shared_ptr<const CollisionWorld> world_;
  double radius_;
};

/// A straight motion is valid when the swept disc never enters a rectangle: the exact
/// continuous test (CollisionWorld::SweepDisc), i.e. motion checking at zero resolution, so
/// no thin wall can be jumped over between two checked points.
class SweptMotionValidator final : public ::ompl::base::MotionValidator {
 public:
  SweptMotionValidator(const ::ompl::base::SpaceInformationPtr& si,
                       std::shared_ptr<const CollisionWorld> world, double radius);
  bool checkMotion(const ::ompl::base::State* s1, const ::ompl::base::State* s2) const override;
  bool checkMotion(const ::ompl::base::State* s1, const ::ompl::base::State* s2,
                   std::pair<::ompl::base::State*, double>& last_valid) const override;

 private:
  std::shared_ptr<const CollisionWorld> world_;
  double radius_;
};

}  // namespace crowdsim::ompl_planner
