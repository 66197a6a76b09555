// A global-route sensor: how far the robot's goal is along the shortest free path around the
// world's static rectangles, and where that path leads (a waypoint a fixed distance ahead), in
// the robot's frame. What a global planner gives a local policy, as a reading.
#pragma once

#include <cstdint>
#include <memory>
#include <mutex>
#include <vector>

#include "crowdsim/params.h"
#include "crowdsim/route_field.h"
#include "crowdsim/sensor.h"

namespace crowdsim::route {

/// Layout of the reading's `values`.
enum RouteValue { kRouteDistance = 0, kWaypointX = 1, kWaypointY = 2, kRouteValues = 3 };

class RouteSensor final : public Sensor {
 public:
  explicit RouteSensor(const Params& params);
  void Sense(const SenseInput& in, SensorReading* out) const override;

 private:
  /// The field for this map, goal and clearance: built on first use, then cached.
  std::shared_ptr<const RouteField> Field(const SenseInput& in, double clearance) const;

  struct Entry {
    std::uint64_t world = 0;
    Vec2 goal = Vec2::Zero();
    double clearance = 0.0;
    std::shared_ptr<const RouteField> field;
  };
  static constexpr size_t kCacheEntries = 8;

  double resolution_;
  double margin_;
  double lookahead_;
  mutable std::mutex mutex_;
  mutable std::vector<Entry> cache_;  // most recently used last
};

/// The parameters route declares (resolution, margin, lookahead).
ParamSchema Schema();

}  // namespace crowdsim::route
