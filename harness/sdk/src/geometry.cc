#include "crowdsim/geometry.h"

#include <algorithm>
#include <cmath>

namespace crowdsim {
namespace {

// Entry/exit of ray o + t*d in slab [lo, hi]. A parallel ray is handled apart (inside or false) to
// avoid 0 * inf.
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

// hypot(d.x, d.y) for d >= 0, skipping the call where one coordinate is 0 (placement's hot path).
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
  // hypot(x, y) >= max(x, y) holds in floating point too, so this cut-off gives hypot's answer.
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
  // Touching is not contact, so agents may rest on or slide along walls; the slop keeps exact
  // touches so under rounding.
  constexpr double kContactSlop = 1e-9;
  const double reach = radius - kContactSlop;
  const Vec2 d = b - a;
  const double len = d.norm();
  if (len == 0.0) return PointToRectDistance(a, r) < reach ? 0.0 : kInfinity;
  const Vec2 dir = d / len;
  // Centres reaching r form r grown by `reach` with round corners; the motion's first entry into it
  // is the contact.
  const Rect wide{Vec2(r.min.x() - reach, r.min.y()), Vec2(r.max.x() + reach, r.max.y())};
  const Rect tall{Vec2(r.min.x(), r.min.y() - reach), Vec2(r.max.x(), r.max.y() + reach)};
  double t = std::min(RayRectDistance(a, dir, wide), RayRectDistance(a, dir, tall));
  const Vec2 corners[4] = {r.min, r.max, Vec2(r.min.x(), r.max.y()), Vec2(r.max.x(), r.min.y())};
  for (const Vec2& corner : corners) t = std::min(t, RayCircleDistance(a, dir, corner, reach));
  if (t > len) return kInfinity;
  return std::min(t / len, 1.0);
}

}  // namespace crowdsim
