// Plane-geometry helpers of the ORCA solver and its roadmap. Kept local to the solver so it
// depends only on the core's types, not on the collision code.
#pragma once

#include <algorithm>
#include <cmath>
#include <span>

#include "crowdsim/geometry.h"

namespace crowdsim::orca {

/// RVO2's tolerance for parallel lines and "already covered" tests.
inline constexpr double kEpsilon = 1e-5;

/// Determinant of the 2x2 matrix [a b] (z of the cross product).
inline double Det(const Vec2& a, const Vec2& b) { return a.x() * b.y() - a.y() * b.x(); }

/// Positive iff c lies left of the directed line a -> b (twice the signed triangle area).
inline double LeftOf(const Vec2& a, const Vec2& b, const Vec2& c) { return Det(a - c, b - a); }

/// Unit vector along w (of norm `length`), or a fixed direction when w vanishes (two agents on
/// the same spot with the same velocity), so that no NaN ever reaches the linear program.
inline Vec2 UnitOr(const Vec2& w, double length) {
  return length > 0.0 ? Vec2(w / length) : Vec2::UnitX();
}

/// Left / right tangent directions from the origin to the disc of `radius` around `p`
/// (|p| > radius): the legs of a velocity obstacle.
inline Vec2 LeftTangent(const Vec2& p, double radius) {
  const double dist_sq = p.squaredNorm();
  const double leg = std::sqrt(std::max(0.0, dist_sq - radius * radius));
  return Vec2(p.x() * leg - p.y() * radius, p.x() * radius + p.y() * leg) / dist_sq;
}
inline Vec2 RightTangent(const Vec2& p, double radius) {
  const double dist_sq = p.squaredNorm();
  const double leg = std::sqrt(std::max(0.0, dist_sq - radius * radius));
  return Vec2(p.x() * leg + p.y() * radius, -p.x() * radius + p.y() * leg) / dist_sq;
}

/// Squared distance from p to the segment a-b (a point when a == b).
double SegmentDistanceSq(const Vec2& a, const Vec2& b, const Vec2& p);

/// Squared distance from p to rectangle r; 0 inside.
double RectDistanceSq(const Rect& r, const Vec2& p);

/// True if the segment a-b touches or crosses rectangle r.
bool SegmentHitsRect(const Vec2& a, const Vec2& b, const Rect& r);

/// Distance between the segment a-b and rectangle r; 0 when they touch.
double SegmentRectDistance(const Vec2& a, const Vec2& b, const Rect& r);

/// Distance from p to the nearest rectangle; kInfinity when there is none.
double DistanceToRects(std::span<const Rect> rects, const Vec2& p);

/// True if the segment a-b stays at least `clearance` (m, >= 0) away from every rectangle.
bool SegmentClear(std::span<const Rect> rects, const Vec2& a, const Vec2& b, double clearance);
/// The same, testing rects[*blocker] first (-1: none) and setting *blocker to a rectangle
/// that blocks: segments tested one after another from one point are mostly blocked by the
/// same rectangle. The answer never depends on the hint.
bool SegmentClear(std::span<const Rect> rects, const Vec2& a, const Vec2& b, double clearance,
                  int* blocker);

}  // namespace crowdsim::orca
