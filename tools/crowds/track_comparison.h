// How a simulated person's path compares with the recorded one: displacement errors (ADE, FDE)
// and mean speeds over points sampled at the same times.
#pragma once

#include <span>

#include "crowdsim/geometry.h"

namespace crowdsim::crowds {

/// One person's comparison.
struct TrackComparison {
  double ade = 0.0;              ///< m: mean distance over the points after the first
  double fde = 0.0;              ///< m: distance at the last point
  double simulated_speed = 0.0;  ///< m/s: the simulated path's length over the horizon
  double recorded_speed = 0.0;   ///< m/s: the recorded path's length over the horizon
};

/// `simulated` and `recorded` hold positions at the same times, the first the shared start, the
/// last at `horizon` s after it (at least two points each, equally many). Throws
/// std::invalid_argument otherwise.
TrackComparison CompareTracks(std::span<const Vec2> simulated, std::span<const Vec2> recorded,
                              double horizon);

}  // namespace crowdsim::crowds
