#include "orca/geometry.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace crowdsim::orca {

double SegmentDistanceSq(const Vec2& a, const Vec2& b, const Vec2& p) {
  const Vec2 ab = b - a;
  const double len_sq = ab.squaredNorm();
  if (len_sq <= 0.0) return (p - a).squaredNorm();
  const double t = std::clamp((p - a).dot(ab) / len_sq, 0.0, 1.0);
  return (a + t * ab - p).squaredNorm();
}

double RectDistanceSq(const Rect& r, const Vec2& p) {
  const double dx = std::max({r.min.x() - p.x(), 0.0, p.x() - r.max.x()});
  const double dy = std::max({r.min.y() - p.y(), 0.0, p.y() - r.max.y()});
  return dx * dx + dy * dy;
}

bool SegmentHitsRect(const Vec2& a, const Vec2& b, const Rect& r) {
  // Liang-Barsky clipping: the segment hits the box iff the clipped interval is non-empty.
  double t0 = 0.0;
  double t1 = 1.0;
  const Vec2 d = b - a;
  for (int axis = 0; axis < 2; ++axis) {
    if (d[axis] == 0.0) {
      if (a[axis] < r.min[axis] || a[axis] > r.max[axis]) return false;
      continue;
    }
    double lo = (r.min[axis] - a[axis]) / d[axis];
    double hi = (r.max[axis] - a[axis]) / d[axis];
    if (lo > hi) std::swap(lo, hi);
    t0 = std::max(t0, lo);
    t1 = std::min(t1, hi);
    if (t0 > t1) return false;
  }
  return true;
}

double SegmentRectDistance(const Vec2& a, const Vec2& b, const Rect& r) {
  if (SegmentHitsRect(a, b, r)) return 0.0;
  // Two disjoint convex sets are closest at a vertex of one of them.
  double d_sq = std::min(RectDistanceSq(r, a), RectDistanceSq(r, b));
  const std::array<Vec2, 4> corners = {r.min, Vec2(r.max.x(), r.min.y()), r.max,
                                       Vec2(r.min.x(), r.max.y())};
  for (const Vec2& c : corners) d_sq = std::min(d_sq, SegmentDistanceSq(a, b, c));
  return std::sqrt(d_sq);
}

double DistanceToRects(std::span<const Rect> rects, const Vec2& p) {
  double best_sq = kInfinity;
  for (const Rect& r : rects) best_sq = std::min(best_sq, RectDistanceSq(r, p));
  return std::sqrt(best_sq);
}

namespace {

// True if rectangle r keeps `clearance` from the segment whose box grown by it is [lo, hi].
bool RectClear(const Vec2& a, const Vec2& b, double clearance, const Vec2& lo, const Vec2& hi,
               const Rect& r) {
  // Bounding-box cull first: most rectangles are nowhere near the segment.
  if (r.min.x() > hi.x() || r.max.x() < lo.x() || r.min.y() > hi.y() || r.max.y() < lo.y()) {
    return true;
  }
  const double d = SegmentRectDistance(a, b, r);
  return !(d < clearance || d == 0.0);
}

}  // namespace

bool SegmentClear(std::span<const Rect> rects, const Vec2& a, const Vec2& b, double clearance) {
  int no_hint = -1;
  return SegmentClear(rects, a, b, clearance, &no_hint);
}

bool SegmentClear(std::span<const Rect> rects, const Vec2& a, const Vec2& b, double clearance,
                  int* blocker) {
  const Vec2 lo = a.cwiseMin(b).array() - clearance;
  const Vec2 hi = a.cwiseMax(b).array() + clearance;
  const int hint = *blocker;
  const int n = static_cast<int>(rects.size());
  if (hint >= 0 && hint < n && !RectClear(a, b, clearance, lo, hi, rects[hint])) return false;
  for (int i = 0; i < n; ++i) {
    if (i == hint || RectClear(a, b, clearance, lo, hi, rects[i])) continue;
    *blocker = i;
    return false;
  }
  return true;
}

}  // namespace crowdsim::orca
