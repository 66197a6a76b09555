#include "crowdsim/bench/metrics.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "crowdsim/bench/episode_columns.h"

namespace crowdsim {

namespace {

/// A column's row mean (kEpisodeColumns) over the episodes, in episode order; its standard error
/// into `se` (NaN with fewer than two episodes counted).
double RowMeanOf(const EpisodeColumn& c, std::span<const EpisodeOutcome> episodes, double* se) {
  const bool social = Social(c);
  const auto social_member = social ? std::get<double SocialMetrics::*>(c.field) : nullptr;
  const auto member = social ? nullptr : std::get<double EpisodeOutcome::*>(c.field);
  double sum = 0.0, sum_sq = 0.0;
  int count = 0;
  for (const EpisodeOutcome& e : episodes) {
    const double x = social ? e.social.*social_member : e.*member;
    const bool counted = c.mean == RowMean::kAll ||
                         (c.mean == RowMean::kSuccesses && e.status == EpisodeStatus::kSuccess) ||
                         (c.mean == RowMean::kFinite && std::isfinite(x));
    if (!counted) continue;
    sum += x;
    sum_sq += x * x;
    ++count;
  }
  *se = std::numeric_limits<double>::quiet_NaN();
  if (count == 0) return c.empty_is_nan ? std::numeric_limits<double>::quiet_NaN() : 0.0;
  const double mean = sum / count;
  if (count >= 2)
    *se = std::sqrt(std::max(0.0, (sum_sq - count * mean * mean) / (count - 1)) / count);
  return mean;
}

}  // namespace

double& RowMeanField(RowMetrics& m, const EpisodeColumn& c) {
  return Social(c) ? m.social.*std::get<double SocialMetrics::*>(c.field) : m.*c.row_mean;
}

double RowMeanField(const RowMetrics& m, const EpisodeColumn& c) {
  return Social(c) ? m.social.*std::get<double SocialMetrics::*>(c.field) : m.*c.row_mean;
}

double& SocialSeField(RowMetrics& m, const EpisodeColumn& c) {
  return m.social_se.*std::get<double SocialMetrics::*>(c.field);
}

double SocialSeField(const RowMetrics& m, const EpisodeColumn& c) {
  return m.social_se.*std::get<double SocialMetrics::*>(c.field);
}

RowMetrics Aggregate(std::span<const EpisodeOutcome> episodes, double time_limit) {
  RowMetrics m;
  m.episodes = static_cast<int>(episodes.size());
  if (episodes.empty()) return m;
  int success = 0, coll_h = 0, coll_o = 0, timeout = 0, error = 0, crash = 0, hang = 0;
  long long steps = 0, danger = 0;
  double nav_time = 0.0, nav_time_sq = 0.0;
  for (const auto& e : episodes) {
    switch (e.status) {
      case EpisodeStatus::kSuccess:
        ++success;
        nav_time += e.time;
        nav_time_sq += e.time * e.time;
        break;
      case EpisodeStatus::kCollisionHuman:
        ++coll_h;
        break;
      case EpisodeStatus::kCollisionObstacle:
        ++coll_o;
        break;
      case EpisodeStatus::kTimeout:
        ++timeout;
        break;
      case EpisodeStatus::kPolicyCrash:
        ++crash;
        break;
      case EpisodeStatus::kPolicyTimeout:
        ++hang;
        break;
      default:
        ++error;
        break;
    }
    steps += e.steps;
    danger += e.danger_steps;
  }
  const double n = static_cast<double>(episodes.size());
  m.success_rate = success / n;
  m.collision_human_rate = coll_h / n;
  m.collision_obstacle_rate = coll_o / n;
  m.collision_rate = (coll_h + coll_o) / n;
  m.timeout_rate = timeout / n;
  m.policy_error_rate = error / n;
  m.policy_crash_rate = crash / n;
  m.policy_timeout_rate = hang / n;
  m.nav_time = success > 0 ? nav_time / success : time_limit;
  m.danger_frequency = steps > 0 ? static_cast<double>(danger) / static_cast<double>(steps) : 0.0;
  for (const EpisodeColumn& c : kEpisodeColumns) {
    if (c.mean == RowMean::kNone) continue;
    double se = 0.0;
    RowMeanField(m, c) = RowMeanOf(c, episodes, &se);
    if (Social(c)) SocialSeField(m, c) = se;
  }
  m.successes = success;
  m.collisions = coll_h + coll_o;
  m.timeouts = timeout;
  if (success >= 2) {
    const double mean = nav_time / success;
    const double variance = std::max(0.0, (nav_time_sq - success * mean * mean) / (success - 1));
    m.nav_time_se = std::sqrt(variance / success);
  }
  return m;
}

Interval WilsonInterval95(int k, int n) {
  if (n <= 0) return {0.0, 1.0};
  constexpr double z = 1.959963984540054;
  const double p = static_cast<double>(k) / n;
  const double z2n = z * z / n;
  const double center = (p + z2n / 2.0) / (1.0 + z2n);
  const double half = z / (1.0 + z2n) * std::sqrt(p * (1.0 - p) / n + z2n / (4.0 * n));
  // Exact ends where the formula's rounding would leave a hair off 0 or 1.
  return {k == 0 ? 0.0 : std::max(0.0, center - half), k == n ? 1.0 : std::min(1.0, center + half)};
}

RowMetrics SummarizeRows(std::span<const RowMetrics> rows) {
  RowMetrics m;
  if (rows.empty()) return m;
  const double k = static_cast<double>(rows.size());
  for (const EpisodeColumn& c : kEpisodeColumns) {
    if (c.mean != RowMean::kNone) RowMeanField(m, c) = 0.0;
  }
  double se_sq = 0.0;
  bool se_known = true;
  for (const RowMetrics& r : rows) {
    m.episodes += r.episodes;
    m.successes += r.successes;
    m.collisions += r.collisions;
    m.timeouts += r.timeouts;
    for (auto field :
         {&RowMetrics::success_rate, &RowMetrics::collision_rate, &RowMetrics::collision_human_rate,
          &RowMetrics::collision_obstacle_rate, &RowMetrics::timeout_rate,
          &RowMetrics::policy_error_rate, &RowMetrics::policy_crash_rate,
          &RowMetrics::policy_timeout_rate, &RowMetrics::nav_time, &RowMetrics::danger_frequency}) {
      m.*field += r.*field / k;
    }
    for (const EpisodeColumn& c : kEpisodeColumns) {
      if (c.mean != RowMean::kNone) RowMeanField(m, c) += RowMeanField(r, c) / k;
    }
    se_known = se_known && std::isfinite(r.nav_time_se);
    se_sq += r.nav_time_se * r.nav_time_se;
  }
  if (se_known) m.nav_time_se = std::sqrt(se_sq) / k;
  // A mean of independent rows: its standard error is sqrt(sum se^2) / k (NaN if any is).
  for (const EpisodeColumn& c : kEpisodeColumns) {
    if (c.mean == RowMean::kNone || !Social(c)) continue;
    double sum_sq = 0.0;
    for (const RowMetrics& r : rows) sum_sq += SocialSeField(r, c) * SocialSeField(r, c);
    SocialSeField(m, c) = std::sqrt(sum_sq) / k;
  }
  return m;
}

}  // namespace crowdsim
