// Binary morphology on floor-plan grids (square structuring elements), flood fill and the
// Euclidean distance transform.
#pragma once

#include <vector>

#include "grid.h"

namespace crowdsim::floorplan {

/// Navigable area grown by a (2 radius + 1)^2 square; outside the image stays blocked.
Grid DilateNavigable(const Grid& g, int radius);
/// Navigable area shrunk by a (2 radius + 1)^2 square; outside the image counts as blocked
/// when `outside_blocked` (so the border erodes too).
Grid ErodeNavigable(const Grid& g, int radius, bool outside_blocked = true);
/// Closing of the navigable area (dilate, then erode): fills blocked specks and cracks up to
/// 2 radius cells wide and keeps wider obstacles as they were.
Grid CloseNavigable(const Grid& g, int radius);
/// CloseNavigable that keeps every blocked 8-connected component of more than `min_kept`
/// cells: strokes one cell thin (outline maps' walls) survive, specks and cracks are filled.
Grid CloseNavigableKeepingStrokes(const Grid& g, int radius, long min_kept);
/// Closing of the blocked area: fills navigable gaps (doors) up to 2 radius cells wide.
Grid CloseBlocked(const Grid& g, int radius);

/// Cells of value `value` 4-connected to a seed cell of that value (1 = reached).
Grid FloodFill(const Grid& g, const std::vector<std::pair<int, int>>& seeds, std::uint8_t value);

/// Exact squared Euclidean distance (in cells, centre to centre) from every cell to the
/// nearest cell with value 0 (Felzenszwalb). With `outside_is_zero` the cells just outside
/// the image count as value 0 (obstacles); otherwise a grid without zeros gives huge values.
std::vector<double> SquaredDistanceToZero(const Grid& g, bool outside_is_zero = true);

}  // namespace crowdsim::floorplan
