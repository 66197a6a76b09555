// Static obstacles in RVO2's form: polygons whose vertices are linked in a ring, each vertex
// standing for the edge to its successor, with directions and convexity computed once.
#pragma once

#include <span>
#include <vector>

#include "crowdsim/geometry.h"
#include "crowdsim/static_map.h"

namespace crowdsim::orca {

/// One polygon vertex; it also stands for the edge from itself to `next`.
struct ObstacleVertex {
  Vec2 point = Vec2::Zero();       ///< m, world frame
  Vec2 direction = Vec2::UnitX();  ///< unit vector from this vertex to the next one
  int next = 0;                    ///< index of the next vertex of the same polygon
  int prev = 0;                    ///< index of the previous vertex of the same polygon
  bool convex = true;              ///< false at reflex corners (e.g. of an enclosing boundary)
};

/// An obstacle edge near an agent, with its squared distance (m^2).
struct ObstacleNeighbor {
  double dist_sq = 0.0;
  int vertex = 0;  ///< first vertex of the edge
};

/// The static obstacles of a world, processed once; immutable afterwards and safe to share.
class OrcaObstacles {
 public:
  OrcaObstacles() = default;

  /// Each rectangle as a counter-clockwise 4-vertex polygon (a segment if it is flat).
  static OrcaObstacles FromRects(std::span<const Rect> rects);
  /// The rectangles of `map` (its bounds are not an obstacle: walls are rectangles).
  static OrcaObstacles FromMap(const StaticMap& map) { return FromRects(map.rectangles); }

  /// Adds a polygon of >= 2 distinct vertices, counter-clockwise (clockwise for a boundary
  /// that keeps agents inside). Two vertices make a thin wall blocking from both sides.
  void AddPolygon(std::span<const Vec2> vertices);

  std::span<const ObstacleVertex> vertices() const { return vertices_; }
  int num_polygons() const { return static_cast<int>(polygons_.size()); }
  bool empty() const { return vertices_.empty(); }

  /// Edges closer than `range` (m) to `p` whose outer side faces `p`, nearest first (ties
  /// in insertion order, as RVO2).
  void Query(const Vec2& p, double range, std::vector<ObstacleNeighbor>* out) const;

 private:
  struct Polygon {
    int begin = 0;
    int count = 0;
    Vec2 lo = Vec2::Zero();  // bounding box, for a cheap cull
    Vec2 hi = Vec2::Zero();
  };

  std::vector<ObstacleVertex> vertices_;
  std::vector<Polygon> polygons_;
};

}  // namespace crowdsim::orca
