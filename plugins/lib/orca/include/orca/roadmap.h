// Global guidance for ORCA agents: a visibility roadmap over the rectangles of a static map,
// so that agents walk around large obstacles instead of stalling in front of them.
#pragma once

#include <memory>
#include <span>
#include <vector>

#include "crowdsim/geometry.h"
#include "crowdsim/static_map.h"
#include "orca/rect_index.h"

namespace crowdsim::orca {

/// Visibility graph for a disc of one radius: nodes at the corners of the rectangles grown
/// by clearance + margin, edges between nodes whose connecting segment keeps `clearance` from
/// every rectangle. Immutable once built; safe to share between threads.
class Roadmap {
 public:
  /// `clearance` (m, >= 0): the radius to keep clear; `margin` (m, >= 0): extra room at the
  /// corners, so an agent slightly off a node still sees the next one. Nodes outside
  /// `bounds` are dropped (unless bounds is empty).
  Roadmap(std::span<const Rect> rects, const Rect& bounds, double clearance, double margin);

  double clearance() const { return clearance_; }
  double margin() const { return margin_; }
  const std::vector<Rect>& rects() const { return rects_; }
  const Rect& bounds() const { return bounds_; }
  const std::vector<Vec2>& nodes() const { return nodes_; }
  /// Number of undirected edges.
  std::size_t num_edges() const { return edges_.size() / 2; }

  /// True if a disc of radius <= clearance can move straight from a to b. The clearance
  /// asked of the segment is capped by that of its ends, so an agent already squeezed
  /// against a wall still sees along it.
  bool Visible(const Vec2& a, const Vec2& b) const;
  /// The same with the ends' capped clearances given (CappedClearance(a), CappedClearance(b)),
  /// for a caller that tests one point against many or the same point step after step.
  bool Visible(const Vec2& a, double a_clearance, const Vec2& b, double b_clearance) const;
  /// The same, testing rectangle *blocker first and setting it to one that blocks (see
  /// SegmentClear): a caller testing many segments from one place keeps it between calls. The
  /// answer never depends on it.
  bool Visible(const Vec2& a, double a_clearance, const Vec2& b, double b_clearance,
               int* blocker) const;

  /// min(clearance, distance from p to the nearest rectangle): only rectangles within the
  /// clearance can lower it, so only those are looked at.
  double CappedClearance(const Vec2& p) const;

  /// Shortest path from `start` to `goal` over the roadmap: the waypoints after the start,
  /// `goal` last. Empty when the roadmap does not connect them.
  std::vector<Vec2> ShortestPath(const Vec2& start, const Vec2& goal) const;

 private:
  struct Edge {
    int to = 0;
    double length = 0.0;
  };
  std::vector<Rect> rects_;
  RectIndex index_;  // over rects_, for the clearance of points (small queries)
  Rect bounds_;
  double clearance_ = 0.0;
  double margin_ = 0.0;
  std::vector<Vec2> nodes_;
  std::vector<int> edge_start_;  // CSR: edges of node i are edges_[edge_start_[i] .. [i + 1])
  std::vector<Edge> edges_;
};

/// The roadmap of `map` for (clearance, margin), shared by every policy of the process: it
/// is built once per map and radius (maps are immutable), not once per agent and episode.
std::shared_ptr<const Roadmap> SharedRoadmap(const StaticMap& map, double clearance, double margin);

}  // namespace crowdsim::orca
