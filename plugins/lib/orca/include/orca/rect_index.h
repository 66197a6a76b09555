// Axis-aligned boxes (a map's rectangles, the bounds of ORCA's obstacle polygons) in a uniform
// grid, so that "which boxes touch this region" does not scan every box of a large map.
#pragma once

#include <span>
#include <utility>
#include <vector>

#include "crowdsim/geometry.h"

namespace crowdsim::orca {

/// Immutable once built; const queries are safe from several threads.
class RectIndex {
 public:
  RectIndex() = default;
  explicit RectIndex(std::span<const Rect> boxes);

  std::span<const Rect> boxes() const { return boxes_; }

  /// Indices of the boxes whose closed extent touches the closed box `query` (exactly the
  /// boxes a plain scan with that test keeps), ascending, each once.
  void Query(const Rect& query, std::vector<int>* out) const;

 private:
  int CellX(double x) const;
  int CellY(double y) const;

  std::vector<Rect> boxes_;
  Vec2 origin_ = Vec2::Zero();
  double cell_ = 1.0;
  int nx_ = 0, ny_ = 0;
  std::vector<int> cell_start_;  // CSR: the boxes of cell c are items_[start[c] .. start[c + 1])
  std::vector<int> items_;
  std::vector<std::pair<int, int>> first_cell_;  // per box: its lowest cell (x, y)
};

}  // namespace crowdsim::orca
