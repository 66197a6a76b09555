// Suite episodes replayed for figures: row and episode arguments checked, the trajectory
// recorded, the sensors re-read at a chosen step, and the figure's title and legend.
#pragma once

#include <optional>
#include <string>

#include "crowdsim/bench/row_instance.h"
#include "crowdsim/bench/suite.h"
#include "crowdsim/render/episode_figure.h"

namespace crowdsim::render {

/// The 0-based row of `text`: a 1-based number as in the table, or a row label. Throws
/// std::invalid_argument naming the value, the valid range and the labels.
size_t ResolveRow(const Suite& suite, const std::string& text);

/// The episode index of `text`, in [0, suite.episodes). Throws std::invalid_argument naming the
/// value and the valid range.
int ResolveEpisode(const Suite& suite, const std::string& text);

/// One row's replay of an episode, with the trajectory.
struct ReplayedEpisode {
  size_t row = 0;  ///< 0-based
  int episode = 0;
  Scenario scenario;
  EpisodeResult result;
  std::optional<SensorSnapshot> sensors;
};

/// Replays (row, episode) exactly as `run` did, recording the trajectory; re-senses at frame
/// `sensors_at` when set. Throws PluginError, std::out_of_range (bad step).
ReplayedEpisode ReplayForFigure(const Suite& suite, size_t row, int episode,
                                PluginRegistry& registry,
                                std::optional<int> sensors_at = std::nullopt);

/// Legend text of a replay: "row 1 linear: success in 11.25 s".
std::string TrackLabel(const Suite& suite, const ReplayedEpisode& replay);

/// The figure of one replay, or of two rows in the same episode (`compare`, second colour).
/// Throws std::invalid_argument when the two replays do not share the scenario.
EpisodeFigure MakeFigure(const Suite& suite, const ReplayedEpisode& replay,
                         const ReplayedEpisode* compare = nullptr);

}  // namespace crowdsim::render
