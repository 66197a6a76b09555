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
  /// Episodes whose isolated worker process died (policy_crash) or was killed at the suite's
  /// episode_timeout_s (policy_timeout): no result, so they count as failures in every rate's
  /// denominator, never as successes, collisions or timeouts (docs/metrics.md).
  double policy_crash_rate = 0.0;
  double policy_timeout_rate = 0.0;
  double nav_time = 0.0;  ///< mean time of successful episodes (time_limit if none, CrowdNav)
  double danger_frequency = 0.0;  ///< danger steps / all steps
  // Row means of episode columns (kEpisodeColumns says which mean each is).
  double path_length = 0.0;         ///< mean over successful episodes (0 if none)
  double min_human_distance = 0.0;  ///< mean over episodes with humans of the episode minimum
  double discounted_return = 0.0;   ///< mean
  double decision_time_us = 0.0;    ///< mean of per-episode means
  int successes = 0;                ///< counts behind the rates (for their intervals)
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

/// Wilson score interval of a binomial proportion k / n at the two-sided 95% level (z = 1.96):
/// well-behaved at rates near 0 and 1 and for small n, unlike the normal approximation.
/// n = 0 gives [0, 1].
Interval WilsonInterval95(int k, int n);

/// The row's numbers over its episodes: the rates and nav. time from the statuses and times,
/// danger_frequency from the steps, and each row mean that kEpisodeColumns names
/// (episode_columns.h).
RowMetrics Aggregate(std::span<const EpisodeOutcome> episodes, double time_limit);

/// A summary row over several rows (e.g. Table 2's average of easy, medium and hard): every
/// metric is the unweighted mean of the rows' values, as the paper averages; the counts and
/// episodes are summed (so the rates' intervals use the pooled episodes), and nav_time_se is
/// the standard error of the mean of the rows' independent nav times.
RowMetrics SummarizeRows(std::span<const RowMetrics> rows);

}  // namespace crowdsim
