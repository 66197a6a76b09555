#include "crowdsim/geometry.h"

#include <algorithm>
#include <cmath>

namespace crowdsim {
namespace {

// Entry/exit parameters of the ray o + t*d in one slab [lo, hi]. A ray parallel to the slab
// is either always inside (-inf, +inf) or never (returns false); handled apart so that a
// zero direction never produces 0 * inf = NaN.
bool Slab(double o, double d, double lo, double hi, double* t_near, double* t_far) {
  if (d == 0.0) {
    if (o < lo || o > hi) return false;
    return true;
  }
  const double inv = 1.0 / d;
  double t0 = (lo - o) * inv;
  double t1 = (hi - o) * inv;
  if (t0 > t1) std::swap(t0, t1);
  *t_near = std::max(*t_near, t0);
  *t_far = std::min(*t_far, t1);
  return *t_near <= *t_far;
}

// How far p lies outside r along each axis (0 inside the rectangle's slab on that axis).
Vec2 OutsideRect(const Vec2& p, const Rect& r) {
  return Vec2(std::max({r.min.x() - p.x(), 0.0, p.x() - r.max.x()}),
              std::max({r.min.y() - p.y(), 0.0, p.y() - r.max.y()}));
}

// hypot(d.x, d.y) for non-negative d, skipping the call (a hot path of human placement) beside
// the rectangle's sides, where hypot would return the other coordinate exactly.
double Length(const Vec2& d) {
  if (d.x() == 0.0) return d.y();
  if (d.y() == 0.0) return d.x();
  return std::hypot(d.x(), d.y());
}

}  // namespace

double PointToSegmentDistance(const Vec2& a, const Vec2& b, const Vec2& p) {
  return PointToSegmentDistanceInline(a, b, p);
}

double PointToRectDistance(const Vec2& p, const Rect& r) { return Length(OutsideRect(p, r)); }

bool DiscOverlapsRect(const Vec2& c, double radius, const Rect& r) {
  const Vec2 d = OutsideRect(c, r);
  // hypot(x, y) >= max(x, y) holds in floating point too (the float x lies at or below the
  // exact value, and rounding is monotonic), so this cut-off gives hypot's answer.
  if (d.x() >= radius || d.y() >= radius) return false;
  return Length(d) < radius;
}

double RayRectDistance(const Vec2& origin, const Vec2& dir, const Rect& r) {
  if (r.Contains(origin)) return 0.0;
  double t_near = -kInfinity;
  double t_far = kInfinity;
  if (!Slab(origin.x(), dir.x(), r.min.x(), r.max.x(), &t_near, &t_far)) return kInfinity;
  if (!Slab(origin.y(), dir.y(), r.min.y(), r.max.y(), &t_near, &t_far)) return kInfinity;
  if (t_far < 0.0) return kInfinity;
  return std::max(t_near, 0.0);
}

double RayCircleDistance(const Vec2& origin, const Vec2& dir, const Vec2& center, double radius) {
  const Vec2 m = origin - center;
  const double c = m.squaredNorm() - radius * radius;
  if (c <= 0.0) return 0.0;
  const double b = m.dot(dir);
  if (b > 0.0) return kInfinity;  // outside and pointing away
  const double disc = b * b - c;
  if (disc < 0.0) return kInfinity;
  return -b - std::sqrt(disc);
}

double SweptDiscRectTime(const Vec2& a, const Vec2& b, double radius, const Rect& r) {
  // Contact means the disc's interior enters r. Touching (centre exactly `radius` away) is
  // not contact, so an agent resting against a wall, sliding along it or leaving it does not
  // collide; the slop keeps exact touches on that side of rounding.
  constexpr double kContactSlop = 1e-9;
  const double reach = radius - kContactSlop;
  const Vec2 d = b - a;
  const double len = d.norm();
  if (len == 0.0) return PointToRectDistance(a, r) < reach ? 0.0 : kInfinity;
  const Vec2 dir = d / len;
  // The set of centres at which the disc reaches r is r grown by `reach` with rounded
  // corners: the union of two crossed rectangles and four corner discs. The first entry of
  // the motion segment into that union is the contact, however thin r or fast the motion.
  const Rect wide{Vec2(r.min.x() - reach, r.min.y()), Vec2(r.max.x() + reach, r.max.y())};
  const Rect tall{Vec2(r.min.x(), r.min.y() - reach), Vec2(r.max.x(), r.max.y() + reach)};
  double t = std::min(RayRectDistance(a, dir, wide), RayRectDistance(a, dir, tall));
  const Vec2 corners[4] = {r.min, r.max, Vec2(r.min.x(), r.max.y()), Vec2(r.max.x(), r.min.y())};
  for (const Vec2& corner : corners) t = std::min(t, RayCircleDistance(a, dir, corner, reach));
  if (t > len) return kInfinity;
  return std::min(t / len, 1.0);
}

}  // namespace crowdsim
