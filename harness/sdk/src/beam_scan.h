// The exact 2D part of a lidar scan: beams from one origin against nearby shapes, scalar or four
// per AVX2 step, bit-identical.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>

#include "crowdsim/geometry.h"

namespace crowdsim {

/// A candidate rectangle of one scan, relative to the scan's origin.
struct RelRect {
  double x0, y0, x1, y1;
};
static_assert(sizeof(RelRect) == 4 * sizeof(double), "one AVX2 register a rectangle");

/// A candidate disc of one scan, relative to the scan's origin; c = |centre|^2 - radius^2.
struct RelDisc {
  double cx, cy, c;
};

/// ranges[k]: distance along unit directions[k] to the nearest shape, max_range if none, 0 from
/// inside. Dispatches to the fastest kernel.
void ScanBeams(std::span<const Vec2> directions, double max_range, std::span<const RelRect> rects,
               std::span<const RelDisc> discs, double* ranges);

/// One beam at a time: the reference, and what runs without AVX2.
void ScanBeamsScalar(std::span<const Vec2> directions, double max_range,
                     std::span<const RelRect> rects, std::span<const RelDisc> discs,
                     double* ranges);

/// Four beams per AVX2 step (a short last group padded with its last beam). Needs HaveAvx2().
void ScanBeamsAvx2(std::span<const Vec2> directions, double max_range,
                   std::span<const RelRect> rects, std::span<const RelDisc> discs, double* ranges);

/// Copies to `out` the rectangles touching `box` (closed boxes), in order; returns how many.
/// `out` holds rects.size(). Dispatches to the fastest kernel, all alike.
std::size_t RectsTouching(std::span<const RelRect> rects, const RelRect& box, RelRect* out);
std::size_t RectsTouchingScalar(std::span<const RelRect> rects, const RelRect& box, RelRect* out);
/// One rectangle an AVX2 compare. Needs HaveAvx2().
std::size_t RectsTouchingAvx2(std::span<const RelRect> rects, const RelRect& box, RelRect* out);

/// The same cull writing the touching rectangles' indices to `ids` (holds rects.size()).
std::size_t RectIdsTouching(std::span<const RelRect> rects, const RelRect& box, int* ids);
std::size_t RectIdsTouchingScalar(std::span<const RelRect> rects, const RelRect& box, int* ids);
std::size_t RectIdsTouchingAvx2(std::span<const RelRect> rects, const RelRect& box, int* ids);

/// Sight lines' boxes grow by this (m): a rectangle beyond it cannot meet a line before its end,
/// whatever the rounding.
inline constexpr double kSightPad = 1e-6;

/// blocked[k] = 1 when one of `rects` meets the line along unit directions[k] nearer than
/// lengths[k] (as ScanBeams along it finds), else 0; offsets[k] is the line's end relative to the
/// origin. Among more than 8 rectangles, lines are culled four at a time by their box into `near`
/// (holds rects.size()). Dispatches to the fastest kernels, all alike.
void ScanSightLines(std::span<const Vec2> offsets, std::span<const Vec2> directions,
                    const double* lengths, std::span<const RelRect> rects, RelRect* near,
                    std::uint8_t* blocked);
void ScanSightLinesScalar(std::span<const Vec2> offsets, std::span<const Vec2> directions,
                          const double* lengths, std::span<const RelRect> rects, RelRect* near,
                          std::uint8_t* blocked);
/// With the AVX2 cull and scan. Needs HaveAvx2().
void ScanSightLinesAvx2(std::span<const Vec2> offsets, std::span<const Vec2> directions,
                        const double* lengths, std::span<const RelRect> rects, RelRect* near,
                        std::uint8_t* blocked);

}  // namespace crowdsim
