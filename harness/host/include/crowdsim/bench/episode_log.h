// The open episode log: one episode's trajectories, map and outcome as gzip-compressed JSON lines
// (docs/episode_log.md, its schema docs/episode_log.schema.json). `run --record` writes them;
// `score` computes the social navigation metrics from them alone, so a log converted from another
// simulator or a real robot is scored by the same code as a run.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "crowdsim/bench/episode.h"

namespace crowdsim {

/// The format version this build writes and the newest it reads.
inline constexpr int kEpisodeLogVersion = 1;

/// One logged episode.
struct EpisodeLog {
  std::string source;  ///< who wrote it ("crowdsim-bench 0.1.0, suite s, row r, episode 3")
  double dt = 0.0;     ///< s between states
  bool holonomic = true;
  double goal_radius = 0.0;
  StaticMap map;
  std::vector<EpisodeFrame> frames;  ///< time 0 first; each agent's radius and goal included
  /// The end as the simulator judged it; absent in a log cut short (never scored as complete).
  std::optional<EpisodeStatus> status;
};

/// Writes `log` to `path` (gzip) atomically: a crash leaves the old file or none.
void WriteEpisodeLog(const std::filesystem::path& path, const EpisodeLog& log);

/// Reads a log. Throws std::runtime_error naming the file, line and field for a missing or
/// mistyped field, a unit other than the format's, time not increasing by dt, a newer version, or
/// no outcome line (a partial log).
EpisodeLog ReadEpisodeLog(const std::filesystem::path& path);

/// The log's social navigation metrics, as a suite run computes them (SocialMetricsAccumulator).
SocialMetrics ScoreEpisodeLog(const EpisodeLog& log);

}  // namespace crowdsim
