// Rectangular decomposition of the blocked area of a floor plan.
//
// Choice: an exact greedy instead of adaptive-boxes' randomised search (reference §4). Each
// step takes the largest all-blocked rectangle of the cells not yet covered, found exactly
// with the maximal-rectangle-in-a-histogram scan. Because the remaining cells only shrink,
// the areas come out non-increasing: the first N rectangles ARE the N largest, so the paper's
// "sort by area, keep 30" is a prefix, and no random seed can miss a large block.
#pragma once

#include <vector>

#include "grid.h"

namespace crowdsim::floorplan {

/// Inclusive cell rectangle: rows row0..row1 (row 0 at the top), columns col0..col1.
struct CellRect {
  int row0 = 0;
  int col0 = 0;
  int row1 = 0;
  int col1 = 0;
  /// Number of cells.
  long Area() const { return long(row1 - row0 + 1) * (col1 - col0 + 1); }
  bool operator==(const CellRect& o) const = default;
};

/// Covers every blocked (0) cell of `g` with disjoint rectangles, largest first (ties: the
/// topmost, then leftmost). Stops early once `max_rectangles` (> 0) are found.
std::vector<CellRect> DecomposeBlocked(const Grid& g, long max_rectangles = -1);

/// Smallest number of leading rectangles covering at least `share` (0..1] of `total` cells.
int RectanglesForCoverage(const std::vector<CellRect>& rects, long total, double share);

}  // namespace crowdsim::floorplan
