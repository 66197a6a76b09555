// Shortest-path distances to one goal over a world's static rectangles: a grid (Dijkstra over
// 16 move directions between free cells) whose free cells are those a disc of the given clearance
// fits at (route_field.cc: how much of it a move keeps). Built once per (map, goal, clearance);
// queried per reading of the route sensor and once per episode by the path-efficiency metric.
#pragma once

#include <vector>

#include "crowdsim/export.h"
#include "crowdsim/static_map.h"

namespace crowdsim {

class CROWDSIM_SDK_API RouteField {
 public:
  /// Cells of `resolution` metres over `map.bounds`; `clearance` is the robot's radius plus
  /// a margin (m). The goal's neighbourhood seeds the search, so a goal close to a wall is
  /// still reachable.
  RouteField(const StaticMap& map, const Vec2& goal, double clearance, double resolution);

  /// What the route says at `p`: `distance`, the length of the shortest free path to the goal
  /// (m; kInfinity when the goal cannot be reached from p or p is outside the bounds), and
  /// `waypoint`, the point `lookahead` metres from p towards the farthest point of that path
  /// p sees (the goal itself when it is visible and nearer; p when the goal is unreachable).
  /// The grid path is pulled straight through what p sees, so in open space the distance is
  /// the straight one and the waypoint lies on the line to the goal.
  struct Reading {
    double distance = kInfinity;
    Vec2 waypoint = Vec2::Zero();
  };
  Reading At(const Vec2& p, double lookahead) const;

  /// How far along the grid path points are tested for being seen from p (m).
  static constexpr double kPullHorizon = 4.0;

  /// One of the grid's 16 move directions (route_field.cc).
  struct Move;

 private:
  int Index(int row, int col) const { return row * cols_ + col; }
  Vec2 Centre(int row, int col) const;
  bool Free(int row, int col) const;
  /// The reachable cell nearest in path terms to `p` (value + straight distance), searched
  /// within the clearance band around p's cell; -1 if none.
  int EntryCell(const Vec2& p, double* through) const;
  /// The next cell down the path from cell `i` (the move's `length` in m), or -1 when i is
  /// next to the goal.
  int Downhill(int i, double* length) const;
  /// True if the move `m` from (row, col) ends on a free cell.
  bool CanMove(int row, int col, const Move& m) const;
  /// True if the segment p -> q crosses no blocked cells but those of p's and q's clearance
  /// band (a robot or a goal near a wall stands in it): a blocked stretch from p or to q
  /// longer than the band, or any between free cells, is a wall in the way.
  bool Sees(const Vec2& p, const Vec2& q) const;

  Vec2 origin_;
  Vec2 goal_;
  double resolution_;
  double band_;       // how far p or q may stand inside blocked cells: the clearance and a cell
  int search_cells_;  // EntryCell's reach in cells: the clearance and one more
  int rows_ = 0;
  int cols_ = 0;
  std::vector<unsigned char> free_;
  std::vector<double> value_;  // path length to the goal from each cell centre; kInfinity
};

}  // namespace crowdsim
