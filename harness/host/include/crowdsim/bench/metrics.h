// Per-row aggregation of episode results into the paper's columns.
#pragma once

#include <limits>
#include <span>

#include "crowdsim/bench/episode.h"

namespace crowdsim {

/// One table row's numbers. Rates are fractions of all episodes.
struct RowMetrics {
  int episodes = 0;
  double success_rate = 0.0;
  double collision_rate = 0.0;  ///< human + obstacle
  double collision_human_rate = 0.0;
  double collision_obstacle_rate = 0.0;
  double timeout_rate = 0.0;
  double policy_error_rate = 0.0;
  /// Episodes whose isolated worker died (policy_crash) or hit episode_timeout_s (policy_timeout):
  /// failures in every rate's denominator, never successes, collisions or timeouts
  /// (docs/metrics.md).
  double policy_crash_rate = 0.0;
  double policy_timeout_rate = 0.0;
  double nav_time = 0.0;  ///< mean time of successful episodes (time_limit if none, CrowdNav)
  double danger_frequency = 0.0;  ///< danger steps / all steps
  // Row means of episode columns (kEpisodeColumns says which mean each is).
  double path_length = 0.0;         ///< mean over successful episodes (0 if none)
  double min_human_distance = 0.0;  ///< mean over episodes with humans of the episode minimum
  double discounted_return = 0.0;   ///< mean
  double decision_time_us = 0.0;    ///< mean of per-episode means
  SocialMetrics social;             ///< means of the social columns (kEpisodeColumns says which)
  SocialMetrics social_se;  ///< their standard errors (NaN with fewer than 2 episodes counted)
  int successes = 0;        ///< counts behind the rates (for their intervals)
  int collisions = 0;
  int timeouts = 0;
  double nav_time_se =
      std::numeric_limits<double>::quiet_NaN();  ///< standard error of nav_time (NaN with fewer
                                                 ///< than 2 successes)
};

/// A two-sided interval [low, high].
struct Interval {
  double low = 0.0;
  double high = 0.0;
  bool Contains(double x) const { return low <= x && x <= high; }
};

/// Wilson score interval of k / n at 95% (z = 1.96): sound near 0, 1 and small n. n = 0 gives [0,
/// 1].
Interval WilsonInterval95(int k, int n);

/// A row's numbers from its episodes: rates, nav. time, danger_frequency and kEpisodeColumns'
/// means.
RowMetrics Aggregate(std::span<const EpisodeOutcome> episodes, double time_limit);

/// A summary row (e.g. Table 2's average): unweighted means of the rows' metrics as the paper,
/// summed counts (pooled intervals), nav_time_se over rows.
RowMetrics SummarizeRows(std::span<const RowMetrics> rows);

}  // namespace crowdsim
