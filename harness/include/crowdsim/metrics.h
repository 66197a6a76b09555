// Per-row aggregation of episode results into the paper's columns.
#pragma once

#include <span>

#include "crowdsim/episode.h"

namespace crowdsim {

/// One table row's numbers. Rates are fractions of all episodes.
struct RowMetrics {
  int episodes = 0;
  double success_rate = 0.0;
  double collision_rate = 0.0;           ///< human + obstacle
  double collision_human_rate = 0.0;
  double collision_obstacle_rate = 0.0;
  double timeout_rate = 0.0;
  double policy_error_rate = 0.0;
  double nav_time = 0.0;        ///< mean time of successful episodes (time_limit if none, CrowdNav)
  double danger_frequency = 0.0;  ///< danger steps / all steps
  double path_length = 0.0;     ///< mean over successful episodes (0 if none)
  double min_human_distance = 0.0;  ///< mean over episodes with humans of the episode minimum
  double discounted_return = 0.0;   ///< mean
  double decision_time_us = 0.0;    ///< mean of per-episode means
};

/// Compact record of an episode as stored in episodes.csv (what the table needs).
struct EpisodeRecord {
  EpisodeStatus status = EpisodeStatus::kRunning;
  double time = 0.0;
  int steps = 0;
  int danger_steps = 0;
  double path_length = 0.0;
  double min_human_distance = kInfinity;
  double discounted_return = 0.0;
  double decision_time_us = 0.0;
};

EpisodeRecord ToRecord(const EpisodeResult& r);

RowMetrics Aggregate(std::span<const EpisodeRecord> episodes, double time_limit);

}  // namespace crowdsim
