#include "route_sensor.h"

#include <algorithm>

#include "crowdsim/collision_world.h"

namespace crowdsim::route {

ParamSchema Schema() {
  return {
      {"resolution", ParamType::kDouble, 0.1, 0.01, 1.0, {}, "m; cell size of the route grid"},
      {"margin",
       ParamType::kDouble,
       0.05,
       0.0,
       2.0,
       {},
       "m; kept from walls on top of the robot's radius where the passages allow it (a robot "
       "behind a narrower one gets the route its radius alone allows)"},
      {"lookahead",
       ParamType::kDouble,
       1.0,
       0.1,
       50.0,
       {},
       "m; how far along the route the reported waypoint lies"},
  };
}

RouteSensor::RouteSensor(const Params& params)
    : resolution_(params.GetDouble("resolution")),
      margin_(params.GetDouble("margin")),
      lookahead_(params.GetDouble("lookahead")) {}

std::shared_ptr<const RouteField> RouteSensor::Field(const SenseInput& in, double clearance) const {
  const std::uint64_t world = in.world.serial();
  const Vec2& goal = in.robot.goal;
  {
    std::lock_guard lock(mutex_);
    for (size_t i = 0; i < cache_.size(); ++i) {
      const Entry& e = cache_[i];
      if (e.world == world && e.goal == goal && e.clearance == clearance) {
        std::rotate(cache_.begin() + i, cache_.begin() + i + 1, cache_.end());
        return cache_.back().field;
      }
    }
  }
  // Built outside the lock: another thread's episode need not wait for this one's field.
  auto field = std::make_shared<const RouteField>(in.world.map(), goal, clearance, resolution_);
  std::lock_guard lock(mutex_);
  if (cache_.size() == kCacheEntries) cache_.erase(cache_.begin());
  cache_.push_back(Entry{world, goal, clearance, field});
  return field;
}

void RouteSensor::Sense(const SenseInput& in, SensorReading* out) const {
  const Vec2& p = in.robot.position;
  const Vec2& goal = in.robot.goal;
  RouteField::Reading route = Field(in, in.robot.radius + margin_)->At(p, lookahead_);
  if (route.distance == kInfinity && margin_ > 0.0) {
    // Behind a passage narrower than the margin asks for (the robot may stand in one, or in a
    // room whose door is): the route the robot's own radius allows.
    route = Field(in, in.robot.radius)->At(p, lookahead_);
  }
  if (route.distance == kInfinity) {
    // No free route (outside the map, or every passage narrower than the robot): the
    // straight line, as a robot without this sensor would take.
    route.distance = (goal - p).norm();
    route.waypoint =
        route.distance <= lookahead_ ? goal : p + (goal - p) * (lookahead_ / route.distance);
  }
  const Vec2 local = in.frame.PointToLocal(route.waypoint);
  out->values.assign({route.distance, local.x(), local.y()});
}

}  // namespace crowdsim::route
