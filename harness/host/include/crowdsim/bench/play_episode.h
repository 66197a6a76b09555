// Plays an episode to its end as a suite run does, with its social metrics when asked.
#pragma once

#include "crowdsim/bench/episode.h"

namespace crowdsim {

/// Runs `episode` to its end; with `social_metrics`, an accumulator watches every state (time 0
/// first) and the outcome carries its SocialMetrics (docs/metrics.md).
EpisodeOutcome PlayEpisode(Episode& episode, unsigned social_metrics);

}  // namespace crowdsim
