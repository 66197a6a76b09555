#include "beam_scan.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <type_traits>

#include "crowdsim/avx2_lanes.h"
#include "crowdsim/vector_units.h"

namespace crowdsim {
namespace {

// Slab test of ray t * (dx, dy) against an origin-relative rectangle; (ix, iy) = (1/dx, 1/dy).
// Axis-parallel beams avoid 0 * inf.
inline double RelRectHit(const RelRect& r, double dx, double dy, double ix, double iy) {
  double t_near = -kInfinity;
  double t_far = kInfinity;
  if (dx != 0.0) {
    const double t0 = r.x0 * ix;
    const double t1 = r.x1 * ix;
    t_near = std::min(t0, t1);
    t_far = std::max(t0, t1);
  } else if (r.x0 > 0.0 || r.x1 < 0.0) {
    return kInfinity;
  }
  if (dy != 0.0) {
    const double t0 = r.y0 * iy;
    const double t1 = r.y1 * iy;
    t_near = std::max(t_near, std::min(t0, t1));
    t_far = std::min(t_far, std::max(t0, t1));
  } else if (r.y0 > 0.0 || r.y1 < 0.0) {
    return kInfinity;
  }
  if (t_near > t_far || t_far < 0.0) return kInfinity;
  return std::max(t_near, 0.0);
}

// Ray t * (dx, dy) from the origin against a disc relative to it (0 when inside).
inline double RelDiscHit(const RelDisc& d, double dx, double dy) {
  if (d.c <= 0.0) return 0.0;
  const double b = d.cx * dx + d.cy * dy;  // projection of the centre on the beam
  if (b < 0.0) return kInfinity;
  const double disc = b * b - d.c;
  if (disc < 0.0) return kInfinity;
  return b - std::sqrt(disc);
}

}  // namespace

void ScanBeamsScalar(std::span<const Vec2> directions, double max_range,
                     std::span<const RelRect> rects, std::span<const RelDisc> discs,
                     double* ranges) {
  for (std::size_t k = 0; k < directions.size(); ++k) {
    const double dx = directions[k].x();
    const double dy = directions[k].y();
    const double ix = 1.0 / dx;
    const double iy = 1.0 / dy;
    double best = max_range;
    for (const RelRect& r : rects) best = std::min(best, RelRectHit(r, dx, dy, ix, iy));
    for (const RelDisc& d : discs) best = std::min(best, RelDiscHit(d, dx, dy));
    ranges[k] = best;
  }
}

#ifdef CROWDSIM_AVX2_LANES

[[gnu::target("avx2")]] void ScanBeamsAvx2(std::span<const Vec2> directions, double max_range,
                                           std::span<const RelRect> rects,
                                           std::span<const RelDisc> discs, double* ranges) {
  using namespace avx2;  // NOLINT(google-build-using-namespace): the lanes' arithmetic
  const V zero = _mm256_setzero_pd();
  const V one = Splat(1.0);
  const V inf = Splat(kInfinity);
  const V minus_inf = Splat(-kInfinity);
  const std::size_t n = directions.size();
  for (std::size_t first = 0; first < n; first += 4) {
    const int count = static_cast<int>(std::min<std::size_t>(4, n - first));
    const auto beam = [&](int k) -> const Vec2& {
      return directions[first + static_cast<std::size_t>(std::min(k, count - 1))];
    };
    // x of the four beams in one register, y in another.
    const V b02 = _mm256_set_m128d(_mm_loadu_pd(beam(2).data()), _mm_loadu_pd(beam(0).data()));
    const V b13 = _mm256_set_m128d(_mm_loadu_pd(beam(3).data()), _mm_loadu_pd(beam(1).data()));
    const V dx = _mm256_unpacklo_pd(b02, b13);
    const V dy = _mm256_unpackhi_pd(b02, b13);
    const V ix = Div(one, dx);
    const V iy = Div(one, dy);
    // The scalar code's dx != 0.0 is false exactly where dx == 0.0 (a NaN is "not zero").
    const V x_parallel = Equal(dx, zero);
    const V y_parallel = Equal(dy, zero);
    V best = Splat(max_range);

    for (const RelRect& r : rects) {
      const V x0 = Splat(r.x0), x1 = Splat(r.x1), y0 = Splat(r.y0), y1 = Splat(r.y1);
      // A parallel lane's products may be 0 * inf; its selects never take them.
      const V tx0 = Mul(x0, ix), tx1 = Mul(x1, ix);
      V t_near = Select(x_parallel, minus_inf, Min(tx1, tx0));
      V t_far = Select(x_parallel, inf, Max(tx1, tx0));
      const V ty0 = Mul(y0, iy), ty1 = Mul(y1, iy);
      t_near = Select(y_parallel, t_near, Max(Min(ty1, ty0), t_near));
      t_far = Select(y_parallel, t_far, Min(Max(ty1, ty0), t_far));
      // A parallel beam misses when the origin lies outside the slab along it.
      const V x_miss = And(x_parallel, Or(Greater(x0, zero), Greater(zero, x1)));
      const V y_miss = And(y_parallel, Or(Greater(y0, zero), Greater(zero, y1)));
      const V miss = Or(Or(x_miss, y_miss), Or(Greater(t_near, t_far), Greater(zero, t_far)));
      best = Min(Select(miss, inf, Max(zero, t_near)), best);
    }
    for (const RelDisc& d : discs) {
      if (d.c <= 0.0) {  // the origin inside the disc: 0 on every beam
        best = Min(zero, best);
        continue;
      }
      const V b = Add(Mul(Splat(d.cx), dx), Mul(Splat(d.cy), dy));
      const V disc = Sub(Mul(b, b), Splat(d.c));
      // A missing lane's root may be of a negative number; its select never takes it.
      const V miss = Or(Greater(zero, b), Greater(zero, disc));
      best = Min(Select(miss, inf, Sub(b, _mm256_sqrt_pd(disc))), best);
    }

    alignas(32) double lanes[4];
    _mm256_store_pd(lanes, best);
    std::copy(lanes, lanes + count, ranges + first);
  }
  // GCC may leave upper halves dirty, slowing the scalar code that follows (see agent_lines.cc).
  _mm256_zeroupper();
}

#else  // no AVX2 path on this target

void ScanBeamsAvx2(std::span<const Vec2> directions, double max_range,
                   std::span<const RelRect> rects, std::span<const RelDisc> discs, double* ranges) {
  ScanBeamsScalar(directions, max_range, rects, discs, ranges);
}

#endif

namespace {

// The culls' one loop, writing rectangles (Out = RelRect) or their indices (Out = int): each is
// written at slot `kept`, which the next one overwrites unless it touches `box` (no branch).
template <class Out>
std::size_t CullScalar(std::span<const RelRect> rects, const RelRect& box, Out* out) {
  std::size_t kept = 0;
  for (const RelRect& r : rects) {
    if constexpr (std::is_same_v<Out, RelRect>) {
      out[kept] = r;
    } else {
      out[kept] = static_cast<int>(&r - rects.data());
    }
    kept += static_cast<std::size_t>((r.x0 <= box.x1) & (box.x0 <= r.x1) & (r.y0 <= box.y1) &
                                     (box.y0 <= r.y1));
  }
  return kept;
}

#ifdef CROWDSIM_AVX2_LANES
template <class Out>
[[gnu::target("avx2")]] std::size_t CullAvx2(std::span<const RelRect> rects, const RelRect& box,
                                             Out* out) {
  // One rectangle a register: (x0, y0, -x1, -y1) <= (box x1, y1, -x0, -y0) in all four lanes.
  const __m256d sign = _mm256_set_pd(-1.0, -1.0, 1.0, 1.0);
  const __m256d limit = _mm256_set_pd(-box.y0, -box.x0, box.y1, box.x1);
  std::size_t kept = 0;
  for (const RelRect& r : rects) {
    const __m256d v = _mm256_loadu_pd(&r.x0);
    if constexpr (std::is_same_v<Out, RelRect>) {
      _mm256_storeu_pd(&out[kept].x0, v);
    } else {
      out[kept] = static_cast<int>(&r - rects.data());
    }
    const int lanes = _mm256_movemask_pd(_mm256_cmp_pd(_mm256_mul_pd(v, sign), limit, _CMP_LE_OQ));
    kept += static_cast<std::size_t>(lanes == 0xF);
  }
  _mm256_zeroupper();
  return kept;
}
#endif

}  // namespace

std::size_t RectsTouchingScalar(std::span<const RelRect> rects, const RelRect& box, RelRect* out) {
  return CullScalar(rects, box, out);
}

std::size_t RectIdsTouchingScalar(std::span<const RelRect> rects, const RelRect& box, int* ids) {
  return CullScalar(rects, box, ids);
}

#ifdef CROWDSIM_AVX2_LANES
std::size_t RectsTouchingAvx2(std::span<const RelRect> rects, const RelRect& box, RelRect* out) {
  return CullAvx2(rects, box, out);
}

std::size_t RectIdsTouchingAvx2(std::span<const RelRect> rects, const RelRect& box, int* ids) {
  return CullAvx2(rects, box, ids);
}
#else
std::size_t RectsTouchingAvx2(std::span<const RelRect> rects, const RelRect& box, RelRect* out) {
  return CullScalar(rects, box, out);
}

std::size_t RectIdsTouchingAvx2(std::span<const RelRect> rects, const RelRect& box, int* ids) {
  return CullScalar(rects, box, ids);
}
#endif

std::size_t RectsTouching(std::span<const RelRect> rects, const RelRect& box, RelRect* out) {
  using CullFn = std::size_t(std::span<const RelRect>, const RelRect&, RelRect*);
  static CullFn* const fastest = UseAvx2() ? &RectsTouchingAvx2 : &RectsTouchingScalar;
  return fastest(rects, box, out);
}

std::size_t RectIdsTouching(std::span<const RelRect> rects, const RelRect& box, int* ids) {
  using CullFn = std::size_t(std::span<const RelRect>, const RelRect&, int*);
  static CullFn* const fastest = UseAvx2() ? &RectIdsTouchingAvx2 : &RectIdsTouchingScalar;
  return fastest(rects, box, ids);
}

void ScanBeams(std::span<const Vec2> directions, double max_range, std::span<const RelRect> rects,
               std::span<const RelDisc> discs, double* ranges) {
  // Chosen at the first call, then called through.
  using ScanFn = void(std::span<const Vec2>, double, std::span<const RelRect>,
                      std::span<const RelDisc>, double*);
  static ScanFn* const fastest = UseAvx2() ? &ScanBeamsAvx2 : &ScanBeamsScalar;
  fastest(directions, max_range, rects, discs, ranges);
}

namespace {

// Sight lines are culled in fours by their box from this many rectangles; fewer are scanned
// against every line, up to 64 lines a scan.
constexpr std::size_t kSightCullFrom = 8;

using CullFn = std::size_t(std::span<const RelRect>, const RelRect&, RelRect*);
using ScanFn = void(std::span<const Vec2>, double, std::span<const RelRect>,
                    std::span<const RelDisc>, double*);

// The lines' box relative to the origin (which it holds), padded, and their longest.
RelRect SightBox(std::span<const Vec2> offsets, const double* lengths, double* farthest) {
  Vec2 lo = Vec2::Zero(), hi = Vec2::Zero();
  *farthest = 0.0;
  for (std::size_t k = 0; k < offsets.size(); ++k) {
    lo = lo.cwiseMin(offsets[k]);
    hi = hi.cwiseMax(offsets[k]);
    *farthest = std::max(*farthest, lengths[k]);
  }
  return {lo.x() - kSightPad, lo.y() - kSightPad, hi.x() + kSightPad, hi.y() + kSightPad};
}

// The sight lines' group loop over one pair of kernels, called directly: only rectangles
// touching a group's box can meet its lines before their ends.
template <CullFn* Cull, ScanFn* Scan>
void SightLinesWith(std::span<const Vec2> offsets, std::span<const Vec2> directions,
                    const double* lengths, std::span<const RelRect> rects, RelRect* near,
                    std::uint8_t* blocked) {
  const bool cull = rects.size() > kSightCullFrom;
  constexpr std::size_t kMaxGroup = 64;
  const std::size_t group_size = cull ? 4 : kMaxGroup;
  const std::size_t n = directions.size();
  for (std::size_t first = 0; first < n; first += group_size) {
    const std::size_t count = std::min(group_size, n - first);
    double farthest = 0.0;
    const RelRect box = SightBox(offsets.subspan(first, count), lengths + first, &farthest);
    std::span<const RelRect> near_rects = rects;
    if (cull) near_rects = {near, Cull(rects, box, near)};
    double ranges[kMaxGroup];
    if (near_rects.empty()) {
      std::fill(ranges, ranges + count, kInfinity);
    } else {
      Scan(directions.subspan(first, count), farthest + 1.0, near_rects, {}, ranges);
    }
    for (std::size_t k = 0; k < count; ++k)
      blocked[first + k] = ranges[k] < lengths[first + k] ? 1 : 0;
  }
}

}  // namespace

void ScanSightLinesScalar(std::span<const Vec2> offsets, std::span<const Vec2> directions,
                          const double* lengths, std::span<const RelRect> rects, RelRect* near,
                          std::uint8_t* blocked) {
  SightLinesWith<&RectsTouchingScalar, &ScanBeamsScalar>(offsets, directions, lengths, rects, near,
                                                         blocked);
}

void ScanSightLinesAvx2(std::span<const Vec2> offsets, std::span<const Vec2> directions,
                        const double* lengths, std::span<const RelRect> rects, RelRect* near,
                        std::uint8_t* blocked) {
  SightLinesWith<&RectsTouchingAvx2, &ScanBeamsAvx2>(offsets, directions, lengths, rects, near,
                                                     blocked);
}

void ScanSightLines(std::span<const Vec2> offsets, std::span<const Vec2> directions,
                    const double* lengths, std::span<const RelRect> rects, RelRect* near,
                    std::uint8_t* blocked) {
  using SightFn = void(std::span<const Vec2>, std::span<const Vec2>, const double*,
                       std::span<const RelRect>, RelRect*, std::uint8_t*);
  static SightFn* const fastest = UseAvx2() ? &ScanSightLinesAvx2 : &ScanSightLinesScalar;
  fastest(offsets, directions, lengths, rects, near, blocked);
}

}  // namespace crowdsim
