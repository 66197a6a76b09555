// Resampling a binary floor plan to the simulation's 0.1 m cells.
#pragma once

#include "grid.h"

namespace crowdsim::floorplan {

/// Resamples `src` (metres per pixel `src_res`) to cells of `dst_res` metres by exact area
/// weighting: a target cell is blocked when the blocked share of its area is at least
/// `blocked_share` (0.5: majority rule; small values keep strokes thinner than a cell, as the
/// outline maps' walls are). The result covers the source: ceil(size * src_res / dst_res)
/// cells, the part beyond the image counting as blocked. Equal resolutions copy the image.
Grid Resample(const Grid& src, double src_res, double dst_res, double blocked_share);

}  // namespace crowdsim::floorplan
