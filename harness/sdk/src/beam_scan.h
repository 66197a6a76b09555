// The exact 2D part of a lidar scan: every beam from one origin against the rectangles and
// discs near it, all given relative to that origin. One beam at a time, or four beams at a time
// in AVX2 lanes; both compute each beam with the same IEEE operations in the same order (no
// fused multiply-add), so they agree to the last bit (crowdsim/vector_units.h).
#pragma once

#include <span>

#include "crowdsim/geometry.h"

namespace crowdsim {

/// A candidate rectangle of one scan, relative to the scan's origin.
struct RelRect {
  double x0, y0, x1, y1;
};

/// A candidate disc of one scan, relative to the scan's origin; c = |centre|^2 - radius^2.
struct RelDisc {
  double cx, cy, c;
};

/// ranges[k] = the distance along directions[k] (unit vectors) to the nearest rectangle or
/// disc it meets, or max_range; a beam starting inside a shape gets 0. The fastest of the two
/// below that this processor runs, or the scalar one when SimdDisabled().
void ScanBeams(std::span<const Vec2> directions, double max_range, std::span<const RelRect> rects,
               std::span<const RelDisc> discs, double* ranges);

/// One beam at a time: the reference, and what runs without AVX2.
void ScanBeamsScalar(std::span<const Vec2> directions, double max_range,
                     std::span<const RelRect> rects, std::span<const RelDisc> discs,
                     double* ranges);

/// Four beams at a time in AVX2 lanes (a last group of fewer padded with copies of its last
/// beam). Call only when HaveAvx2().
void ScanBeamsAvx2(std::span<const Vec2> directions, double max_range,
                   std::span<const RelRect> rects, std::span<const RelDisc> discs, double* ranges);

}  // namespace crowdsim
