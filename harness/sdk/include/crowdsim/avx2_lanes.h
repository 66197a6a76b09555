// Lane-wise AVX2 helpers, each one IEEE operation per lane as in the scalar code. Build users and
// their scalar twins with -ffp-contract=off, else GCC fuses products into sums under FMA. Defines
// CROWDSIM_AVX2_LANES on x86-64 GCC or Clang; call only when UseAvx2().
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
// (a < b ? a : b) and (a > b ? a : b). std::min(x, y) is Min(y, x), std::max(x, y) is Max(y, x),
// matching ties, signed zeros and NaNs.
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
