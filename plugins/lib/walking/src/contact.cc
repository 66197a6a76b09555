#include "walking/contact.h"

#include <algorithm>

namespace crowdsim::walking {

Vec2 SlideAlongRectangles(const StaticMap* map, double time_step, const Vec2& position,
                          double radius, Vec2 velocity) {
  if (map == nullptr) return velocity;
  // Whether the step would end closer than `radius` to `rect`, and closer than now.
  const auto touches = [&](const Rect& rect, const Vec2& v) {
    const Vec2 next = position + v * time_step;
    const double gap = (next - NearestPoint(rect, next)).squaredNorm();
    return gap < radius * radius && gap < (position - NearestPoint(rect, position)).squaredNorm();
  };
  for (const Rect& rect : map->rectangles) {
    if (!touches(rect, velocity)) continue;
    const Vec2 out = position - NearestPoint(rect, position);
    const double d = out.norm();
    if (d > 0.0) velocity -= std::min(0.0, velocity.dot(out / d)) * (out / d);  // slide
  }
  // A corner, or two rectangles at once: stop rather than touch.
  for (const Rect& rect : map->rectangles) {
    if (touches(rect, velocity)) return Vec2::Zero();
  }
  return velocity;
}

}  // namespace crowdsim::walking
