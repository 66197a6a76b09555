// What an episode figure shows (the scenario, one or two robot runs, an optional sensor
// snapshot) and the drawing of it: the whole episode, or one animation frame.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "crowdsim/bench/episode.h"
#include "crowdsim/render/drawing.h"
#include "crowdsim/render/sensor_snapshot.h"
#include "crowdsim/scenario.h"

namespace crowdsim::render {

/// One robot run drawn in a figure (two of them with --compare, as in the paper's Figure 1).
struct RobotTrack {
  std::string label;                      ///< legend text, e.g. "row 1 linear: success in 11.25 s"
  const EpisodeResult* result = nullptr;  ///< not owned; must have a recorded trajectory
  Color color;
};

/// Everything one figure shows.
struct EpisodeFigure {
  const Scenario* scenario = nullptr;  ///< not owned
  std::string title;                   ///< first header line
  std::vector<RobotTrack> robots;      ///< 1 or 2
  /// The track whose humans are drawn (humans ignore invisible robots, so every row has the
  /// same humans; the longest track shows them the longest).
  size_t humans_from = 0;
  std::optional<SensorSnapshot> sensors;  ///< drawn in full figures only
};

/// Layout choices of a figure.
struct FigureOptions {
  double max_side = 760.0;          ///< px, the longer side of the world area
  double time_mark_interval = 2.0;  ///< s between time dots on every trajectory
  bool time_labels = true;          ///< write the time next to each dot
  bool key = true;                  ///< scale bar and key of the marks under the map
};

/// The whole episode: map, trajectories with time marks, starts and goals, final discs,
/// outcome in the header, and the sensor snapshot when set. Throws std::invalid_argument
/// when a track has no trajectory.
Drawing DrawEpisode(const EpisodeFigure& figure, const FigureOptions& options = {});

/// Animation frame `frame` (index into the trajectories, clamped per track): trails so far and
/// everybody's disc at that time, with a clock in the header.
Drawing DrawEpisodeFrame(const EpisodeFigure& figure, size_t frame,
                         const FigureOptions& options = {});

/// Number of frames an animation of `figure` has (the longest track's trajectory).
size_t FrameCount(const EpisodeFigure& figure);

}  // namespace crowdsim::render
