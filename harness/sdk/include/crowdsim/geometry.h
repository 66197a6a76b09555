// Plane geometry on axis-aligned rectangles and discs: the exact narrow phase after Bullet culls.
#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <limits>

#include "crowdsim/export.h"

namespace crowdsim {

using Vec2 = Eigen::Vector2d;

inline constexpr double kInfinity = std::numeric_limits<double>::infinity();

/// Axis-aligned rectangle given by its min and max corners (metres).
struct CROWDSIM_SDK_API Rect {
  Vec2 min = Vec2::Zero();
  Vec2 max = Vec2::Zero();

  static Rect FromCorners(double x0, double y0, double x1, double y1) {
    return Rect{Vec2(x0, y0), Vec2(x1, y1)};
  }
  Vec2 Center() const { return 0.5 * (min + max); }
  Vec2 Size() const { return max - min; }
  double Area() const { return (max.x() - min.x()) * (max.y() - min.y()); }
  bool Contains(const Vec2& p) const {
    return p.x() >= min.x() && p.x() <= max.x() && p.y() >= min.y() && p.y() <= max.y();
  }
  /// This rectangle grown by `margin` on every side (negative shrinks).
  Rect Inflated(double margin) const {
    return Rect{min - Vec2(margin, margin), max + Vec2(margin, margin)};
  }
  bool Overlaps(const Rect& o) const {
    return min.x() < o.max.x() && o.min.x() < max.x() && min.y() < o.max.y() && o.min.y() < max.y();
  }
  bool operator==(const Rect& o) const { return min == o.min && max == o.max; }
};

/// Disc (agents are discs).
struct CROWDSIM_SDK_API Circle {
  Vec2 center = Vec2::Zero();
  double radius = 0.0;
};

/// z of the 3D cross product of two plane vectors.
inline double Cross(const Vec2& a, const Vec2& b) { return a.x() * b.y() - a.y() * b.x(); }

/// |d| against `limit` (> 0) by squares: -1 below, +1 above, 0 within 2%, where only the root
/// decides.
inline int NormSideBySquares(const Vec2& d, double limit) {
  const double sq = d.squaredNorm();
  const double limit_sq = limit * limit;
  return sq < 0.98 * limit_sq ? -1 : (sq > 1.02 * limit_sq ? 1 : 0);
}

/// Exactly `d.norm() < limit`, the square root only near the limit.
inline bool NormBelow(const Vec2& d, double limit) {
  const int side = limit > 0.0 ? NormSideBySquares(d, limit) : 0;
  return side != 0 ? side < 0 : d.norm() < limit;
}

/// Exactly `d.norm() > limit`, the square root only near the limit.
inline bool NormAbove(const Vec2& d, double limit) {
  const int side = limit > 0.0 ? NormSideBySquares(d, limit) : 0;
  return side != 0 ? side > 0 : d.norm() > limit;
}

/// Distance from point p to segment a-b (CrowdNav's point_to_segment_dist).
CROWDSIM_SDK_API double PointToSegmentDistance(const Vec2& a, const Vec2& b, const Vec2& p);

/// PointToSegmentDistance inline, for the per-step swept robot-human test (the exported function
/// stays for plugins built against older headers).
inline double PointToSegmentDistanceInline(const Vec2& a, const Vec2& b, const Vec2& p) {
  const Vec2 ab = b - a;
  const double len2 = ab.squaredNorm();
  if (len2 == 0.0) return (p - a).norm();
  // u = clamp((p - a).ab / len2, 0, 1), dividing only strictly between the ends. An overflowing or
  // NaN len2 takes the definition.
  const double along = (p - a).dot(ab);
  if (len2 < kInfinity) {
    if (along <= 0.0) return (a - p).norm();  // a + 0 * ab is a (up to the sign of a zero)
    if (along >= len2) return (a + ab - p).norm();
  }
  const double u = std::clamp(along / len2, 0.0, 1.0);
  return (a + u * ab - p).norm();
}

/// Distance from point p to rectangle r (0 inside).
CROWDSIM_SDK_API double PointToRectDistance(const Vec2& p, const Rect& r);

/// True if the disc (c, radius) and the rectangle share interior points.
CROWDSIM_SDK_API bool DiscOverlapsRect(const Vec2& c, double radius, const Rect& r);

/// Distance along the ray origin + t * dir (dir unit) to `r`: kInfinity on a miss, 0 inside.
CROWDSIM_SDK_API double RayRectDistance(const Vec2& origin, const Vec2& dir, const Rect& r);

/// Distance along the ray to the disc: kInfinity on a miss, 0 inside.
CROWDSIM_SDK_API double RayCircleDistance(const Vec2& origin, const Vec2& dir, const Vec2& center,
                                          double radius);

/// First contact of a disc of `radius` moving a to b with r, as a fraction in [0, 1]; 0 if
/// overlapping at a; kInfinity if its interior never enters r (touching within 1e-9 m is no
/// contact).
CROWDSIM_SDK_API double SweptDiscRectTime(const Vec2& a, const Vec2& b, double radius,
                                          const Rect& r);

}  // namespace crowdsim
