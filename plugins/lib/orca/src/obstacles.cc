#include "orca/obstacles.h"

#include <algorithm>
#include <array>
#include <stdexcept>

#include "orca/geometry.h"

namespace crowdsim::orca {

OrcaObstacles OrcaObstacles::FromRects(std::span<const Rect> rects) {
  OrcaObstacles obstacles;
  for (const Rect& r : rects) {
    const double w = r.max.x() - r.min.x();
    const double h = r.max.y() - r.min.y();
    if (w < 0.0 || h < 0.0 || (w == 0.0 && h == 0.0)) continue;  // empty: blocks nothing
    if (w == 0.0 || h == 0.0) {
      const std::array<Vec2, 2> wall = {r.min, r.max};
      obstacles.AddPolygon(wall);
      continue;
    }
    const std::array<Vec2, 4> ccw = {r.min, Vec2(r.max.x(), r.min.y()), r.max,
                                     Vec2(r.min.x(), r.max.y())};
    obstacles.AddPolygon(ccw);
  }
  return obstacles;
}

void OrcaObstacles::AddPolygon(std::span<const Vec2> vertices) {
  const int n = static_cast<int>(vertices.size());
  if (n < 2) throw std::invalid_argument("ORCA obstacle polygon needs at least 2 vertices");
  const int begin = static_cast<int>(vertices_.size());
  Polygon polygon{begin, n, vertices[0], vertices[0]};
  for (int i = 0; i < n; ++i) {
    const Vec2& p = vertices[i];
    const Vec2& next = vertices[(i + 1) % n];
    if ((next - p).squaredNorm() == 0.0) {
      throw std::invalid_argument("ORCA obstacle polygon has two equal consecutive vertices");
    }
    ObstacleVertex v;
    v.point = p;
    v.direction = (next - p).normalized();
    v.next = begin + (i + 1) % n;
    v.prev = begin + (i + n - 1) % n;
    // A segment's two ends are both convex; otherwise a left turn (or straight) is convex.
    v.convex = n == 2 || LeftOf(vertices[(i + n - 1) % n], p, next) >= 0.0;
    vertices_.push_back(v);
    polygon.lo = polygon.lo.cwiseMin(p);
    polygon.hi = polygon.hi.cwiseMax(p);
  }
  polygons_.push_back(polygon);
}

void OrcaObstacles::Query(const Vec2& p, double range, std::vector<ObstacleNeighbor>* out) const {
  out->clear();
  const double range_sq = range * range;
  for (const Polygon& polygon : polygons_) {
    const double dx = std::max({polygon.lo.x() - p.x(), 0.0, p.x() - polygon.hi.x()});
    const double dy = std::max({polygon.lo.y() - p.y(), 0.0, p.y() - polygon.hi.y()});
    if (dx * dx + dy * dy >= range_sq) continue;
    for (int i = polygon.begin; i < polygon.begin + polygon.count; ++i) {
      const ObstacleVertex& v1 = vertices_[i];
      const ObstacleVertex& v2 = vertices_[v1.next];
      // Only edges seen from outside: an agent never needs the back of an edge.
      if (LeftOf(v1.point, v2.point, p) >= 0.0) continue;
      const double dist_sq = SegmentDistanceSq(v1.point, v2.point, p);
      if (dist_sq >= range_sq) continue;
      out->push_back({dist_sq, i});
    }
  }
  // Nearest first; equal distances in insertion order, which is the order of the first vertex
  // (polygons and their vertices are stored as added, and visited in that order). Among the
  // boxes of a floor plan 26-56 edges come back (orca_bench ObstacleQuery), where one sort
  // beats swapping each into place.
  std::sort(out->begin(), out->end(), [](const ObstacleNeighbor& a, const ObstacleNeighbor& b) {
    return a.dist_sq < b.dist_sq || (a.dist_sq == b.dist_sq && a.vertex < b.vertex);
  });
}

}  // namespace crowdsim::orca
