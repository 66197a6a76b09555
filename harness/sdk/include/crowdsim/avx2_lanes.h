// Lane-wise helpers for the AVX2 paths of the hot loops (crowdsim/vector_units.h): each is one
// IEEE operation per lane, as the scalar code does it. A product and a sum stay two roundings,
// as in the scalar code, only while the compiler fuses nothing: build the file that uses them
// (and its scalar twin) with -ffp-contract=off. GCC's default, -ffp-contract=fast, fuses them
// wherever the build enables FMA (-march=native, -march=haswell): "avx2" adds to the build's
// instruction set, it does not replace it.
// Defines CROWDSIM_AVX2_LANES where the compiler can build them (x86-64, GCC or Clang); a
// caller runs them only when UseAvx2().
#pragma once

#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#define CROWDSIM_AVX2_LANES 1
#include <immintrin.h>

namespace crowdsim::avx2 {

using V = __m256d;
[[gnu::target("avx2")]] inline V Add(V a, V b) { return _mm256_add_pd(a, b); }
[[gnu::target("avx2")]] inline V Sub(V a, V b) { return _mm256_sub_pd(a, b); }
[[gnu::target("avx2")]] inline V Mul(V a, V b) { return _mm256_mul_pd(a, b); }
[[gnu::target("avx2")]] inline V Div(V a, V b) { return _mm256_div_pd(a, b); }
[[gnu::target("avx2")]] inline V Neg(V a) { return _mm256_xor_pd(a, _mm256_set1_pd(-0.0)); }
// (a < b ? a : b) and (a > b ? a : b): std::min(x, y) = (y < x ? y : x) is Min(y, x), and
// std::max(x, y) = (x < y ? y : x) is Max(y, x); in that order equal values, signed zeros and
// NaNs come out as the scalar code's.
[[gnu::target("avx2")]] inline V Min(V a, V b) { return _mm256_min_pd(a, b); }
[[gnu::target("avx2")]] inline V Max(V a, V b) { return _mm256_max_pd(a, b); }
[[gnu::target("avx2")]] inline V And(V a, V b) { return _mm256_and_pd(a, b); }
[[gnu::target("avx2")]] inline V Or(V a, V b) { return _mm256_or_pd(a, b); }
// a > b, false where either is NaN (as the scalar comparison).
[[gnu::target("avx2")]] inline V Greater(V a, V b) { return _mm256_cmp_pd(a, b, _CMP_GT_OQ); }
// a == b, false where either is NaN.
[[gnu::target("avx2")]] inline V Equal(V a, V b) { return _mm256_cmp_pd(a, b, _CMP_EQ_OQ); }
// mask ? yes : no, lane by lane.
[[gnu::target("avx2")]] inline V Select(V mask, V yes, V no) {
  return _mm256_blendv_pd(no, yes, mask);
}
[[gnu::target("avx2")]] inline V Splat(double x) { return _mm256_set1_pd(x); }

}  // namespace crowdsim::avx2

#endif
