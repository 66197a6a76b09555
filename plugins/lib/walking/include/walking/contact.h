// Contact with the map's rectangles: their nearest points, and the slide along an edge that
// keeps a force-model person out of them at a coarse time step.
#pragma once

#include "crowdsim/geometry.h"
#include "crowdsim/static_map.h"

namespace crowdsim::walking {

/// The point of `rect` nearest to `p` (p itself inside it).
inline Vec2 NearestPoint(const Rect& rect, const Vec2& p) {
  return p.cwiseMax(rect.min).cwiseMin(rect.max);
}

/// `velocity` less its part into any rectangle of `map` (null: none) it would touch within
/// `time_step` from `position` (it slides along the edge); zero when sliding still touches one
/// (a corner, two rectangles). Touching: ending closer than `radius`, and closer than now.
Vec2 SlideAlongRectangles(const StaticMap* map, double time_step, const Vec2& position,
                          double radius, Vec2 velocity);

}  // namespace crowdsim::walking
