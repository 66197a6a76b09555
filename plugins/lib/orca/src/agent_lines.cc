#include "orca/agent_lines.h"

#include <algorithm>
#include <cmath>
#include <cstddef>

#include "crowdsim/avx2_lanes.h"
#include "orca/geometry.h"

namespace crowdsim::orca {

void AddAgentLinesScalar(const OrcaAgent& self, std::span<const OrcaAgent> neighbours,
                         const OrcaParams& params, double time_step, OrcaLine* out) {
  const double inv_tau = 1.0 / params.time_horizon;
  for (const OrcaAgent& other : neighbours) {
    const Vec2 p = other.position - self.position;
    const Vec2 v_rel = self.velocity - other.velocity;
    const double dist_sq = p.squaredNorm();
    const double combined = self.radius + other.radius;
    const double combined_sq = combined * combined;

    Vec2 direction;
    Vec2 u;  // smallest change of v_rel that leaves the velocity obstacle
    if (dist_sq > combined_sq) {
      const Vec2 w = v_rel - inv_tau * p;  // from the cut-off centre to v_rel
      const double w_len_sq = w.squaredNorm();
      const double dot = w.dot(p);
      if (dot < 0.0 && dot * dot > combined_sq * w_len_sq) {
        // Nearest boundary point is on the cut-off circle.
        const double w_len = std::sqrt(w_len_sq);
        const Vec2 unit_w = w / w_len;
        direction = Vec2(unit_w.y(), -unit_w.x());
        u = (combined * inv_tau - w_len) * unit_w;
      } else {
        // Nearest boundary point is on a leg.
        direction = Det(p, w) > 0.0 ? LeftTangent(p, combined) : Vec2(-RightTangent(p, combined));
        u = v_rel.dot(direction) * direction - v_rel;
      }
    } else {
      // Already overlapping: separate within one time step.
      const double inv_dt = 1.0 / time_step;
      const Vec2 w = v_rel - inv_dt * p;
      const double w_len = w.norm();
      const Vec2 unit_w = UnitOr(w, w_len);
      direction = Vec2(unit_w.y(), -unit_w.x());
      u = (combined * inv_dt - w_len) * unit_w;
    }
    *out++ = {self.velocity + 0.5 * u, direction};
  }
}

#ifdef CROWDSIM_AVX2_LANES

namespace {

using namespace avx2;  // NOLINT(google-build-using-namespace): the lanes' arithmetic

// Four (x, y) pairs, one per lane group, from four 16-byte vectors: x of each in one register,
// y in another. a02 holds agents 0 and 2, a13 agents 1 and 3.
[[gnu::target("avx2")]] inline void Transpose(const Vec2& v0, const Vec2& v1, const Vec2& v2,
                                              const Vec2& v3, V* x, V* y) {
  const V a02 = _mm256_set_m128d(_mm_loadu_pd(v2.data()), _mm_loadu_pd(v0.data()));
  const V a13 = _mm256_set_m128d(_mm_loadu_pd(v3.data()), _mm_loadu_pd(v1.data()));
  *x = _mm256_unpacklo_pd(a02, a13);
  *y = _mm256_unpackhi_pd(a02, a13);
}

// The reverse: lane k's (x, y) into dst(k) for the first `count` lanes.
template <typename Dst>
[[gnu::target("avx2")]] inline void StorePairs(V x, V y, int count, Dst dst) {
  const V lo = _mm256_unpacklo_pd(x, y);  // lanes 0 and 2
  const V hi = _mm256_unpackhi_pd(x, y);  // lanes 1 and 3
  _mm_storeu_pd(dst(0), _mm256_castpd256_pd128(lo));
  if (count > 1) _mm_storeu_pd(dst(1), _mm256_castpd256_pd128(hi));
  if (count > 2) _mm_storeu_pd(dst(2), _mm256_extractf128_pd(lo, 1));
  if (count > 3) _mm_storeu_pd(dst(3), _mm256_extractf128_pd(hi, 1));
}

}  // namespace

[[gnu::target("avx2")]] void AddAgentLinesAvx2(const OrcaAgent& self,
                                               std::span<const OrcaAgent> neighbours,
                                               const OrcaParams& params, double time_step,
                                               OrcaLine* out) {
  const double inv_tau_s = 1.0 / params.time_horizon;
  const double inv_dt_s = 1.0 / time_step;
  const V inv_tau = _mm256_set1_pd(inv_tau_s);
  const V inv_dt = _mm256_set1_pd(inv_dt_s);
  const V zero = _mm256_setzero_pd();
  const V one = _mm256_set1_pd(1.0);
  const V half = _mm256_set1_pd(0.5);
  const V all_lanes = _mm256_castsi256_pd(_mm256_set1_epi64x(-1));
  const V self_px = _mm256_set1_pd(self.position.x());
  const V self_py = _mm256_set1_pd(self.position.y());
  const V self_vx = _mm256_set1_pd(self.velocity.x());
  const V self_vy = _mm256_set1_pd(self.velocity.y());
  const V self_r = _mm256_set1_pd(self.radius);
  const std::size_t n = neighbours.size();
  // One or two neighbours left over go one at a time (a group of four costs about as much as
  // two alone); three fill a group whose fourth lane repeats the last neighbour, its line
  // computed and dropped.
  const std::size_t grouped = n % 4 >= 3 ? n : n - n % 4;
  for (std::size_t first = 0; first < grouped; first += 4) {
    const int count = static_cast<int>(std::min<std::size_t>(4, n - first));
    const auto agent = [&](int k) -> const OrcaAgent& {
      return neighbours[first + static_cast<std::size_t>(std::min(k, count - 1))];
    };
    const OrcaAgent &a0 = agent(0), &a1 = agent(1), &a2 = agent(2), &a3 = agent(3);
    V ox, oy, ovx, ovy;
    Transpose(a0.position, a1.position, a2.position, a3.position, &ox, &oy);
    Transpose(a0.velocity, a1.velocity, a2.velocity, a3.velocity, &ovx, &ovy);
    const V orad = _mm256_set_pd(a3.radius, a2.radius, a1.radius, a0.radius);

    const V px = Sub(ox, self_px), py = Sub(oy, self_py);
    const V vx = Sub(self_vx, ovx), vy = Sub(self_vy, ovy);  // v_rel
    const V dist_sq = Add(Mul(px, px), Mul(py, py));
    const V combined = Add(self_r, orad);
    const V combined_sq = Mul(combined, combined);
    const V apart = Greater(dist_sq, combined_sq);

    // w: from the cut-off centre to v_rel while apart (scale 1 / tau), from the centre that
    // separates within one step while overlapping (1 / time_step). Each lane computes the w of
    // its own branch, so the two branches share one square root and one division.
    const V inv = Select(apart, inv_tau, inv_dt);
    const V wx = Sub(vx, Mul(inv, px)), wy = Sub(vy, Mul(inv, py));
    const V w_len_sq = Add(Mul(wx, wx), Mul(wy, wy));
    const V w_len = _mm256_sqrt_pd(w_len_sq);
    const V dot = Add(Mul(wx, px), Mul(wy, py));
    const V on_cutoff =
        _mm256_and_pd(Greater(zero, dot), Greater(Mul(dot, dot), Mul(combined_sq, w_len_sq)));
    // The unit w: on the cut-off circle as it comes; overlapping, +x when w vanishes (UnitOr).
    const V divide = _mm256_or_pd(apart, Greater(w_len, zero));
    const V unit_x = Select(divide, Div(wx, w_len), one);
    const V unit_y = Select(divide, Div(wy, w_len), zero);
    const V scale = Sub(Mul(combined, inv), w_len);
    const V circle_dx = unit_y, circle_dy = Neg(unit_x);
    const V circle_ux = Mul(scale, unit_x), circle_uy = Mul(scale, unit_y);

    // Apart, nearest boundary point on a leg: the left tangent, or the right one reversed.
    // A quotient's sign follows its numerator's exactly, so the right one's numerator is
    // negated before the one division instead of its quotient after.
    const V leg = _mm256_sqrt_pd(_mm256_max_pd(Sub(dist_sq, combined_sq), zero));
    const V left = Greater(Sub(Mul(px, wy), Mul(py, wx)), zero);  // Det(p, w) > 0
    const V px_leg = Mul(px, leg), py_leg = Mul(py, leg);
    const V px_c = Mul(px, combined), py_c = Mul(py, combined);
    const V leg_nx = Select(left, Sub(px_leg, py_c), Neg(Add(px_leg, py_c)));
    const V leg_ny = Select(left, Add(px_c, py_leg), Neg(Add(Neg(px_c), py_leg)));
    const V leg_dx = Div(leg_nx, dist_sq), leg_dy = Div(leg_ny, dist_sq);
    const V along = Add(Mul(vx, leg_dx), Mul(vy, leg_dy));
    const V leg_ux = Sub(Mul(along, leg_dx), vx), leg_uy = Sub(Mul(along, leg_dy), vy);

    // Overlapping lanes take the circle's formulas too (with their own w).
    const V circle = Select(apart, on_cutoff, all_lanes);
    const V dir_x = Select(circle, circle_dx, leg_dx), dir_y = Select(circle, circle_dy, leg_dy);
    const V ux = Select(circle, circle_ux, leg_ux), uy = Select(circle, circle_uy, leg_uy);
    const V point_x = Add(self_vx, Mul(half, ux)), point_y = Add(self_vy, Mul(half, uy));

    OrcaLine* lines = out + first;
    StorePairs(point_x, point_y, count, [lines](int k) { return lines[k].point.data(); });
    StorePairs(dir_x, dir_y, count, [lines](int k) { return lines[k].direction.data(); });
  }
  // Upper halves cleared before the scalar code, whatever the compiler decides: when a
  // variant of this file called a local scalar function, GCC left them dirty, and the scalar
  // code after it (here and in the caller) ran 2.5x slower on this project's Zen 4.
  _mm256_zeroupper();
  AddAgentLinesScalar(self, neighbours.subspan(grouped), params, time_step, out + grouped);
}

#else  // no AVX2 path on this target

void AddAgentLinesAvx2(const OrcaAgent& self, std::span<const OrcaAgent> neighbours,
                       const OrcaParams& params, double time_step, OrcaLine* out) {
  AddAgentLinesScalar(self, neighbours, params, time_step, out);
}

#endif

void AddAgentLines(const OrcaAgent& self, std::span<const OrcaAgent> neighbours,
                   const OrcaParams& params, double time_step, OrcaLine* out) {
  // Chosen at the first call, then called through: a processor test per call (inlining the
  // scalar path beside it) cost more than the call itself.
  using AgentLinesFn =
      void(const OrcaAgent&, std::span<const OrcaAgent>, const OrcaParams&, double, OrcaLine*);
  static AgentLinesFn* const fastest = UseAvx2() ? &AddAgentLinesAvx2 : &AddAgentLinesScalar;
  fastest(self, neighbours, params, time_step, out);
}

}  // namespace crowdsim::orca
