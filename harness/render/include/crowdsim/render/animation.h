// An episode as an animation (GIF or MP4) at real time or faster.
#pragma once

#include <filesystem>
#include <functional>
#include <vector>

#include "crowdsim/render/episode_figure.h"

namespace crowdsim::render {

/// Playback choices.
struct AnimationOptions {
  double speed = 1.0;       ///< playback speed, x real time, in (0, 100]
  double max_side = 560.0;  ///< px, the longer side of the world area
  double hold_end_s = 1.5;  ///< s the last frame stays before the loop restarts
  /// Called after each frame written: (frames done, frames in all); e.g. a progress line.
  std::function<void(size_t done, size_t total)> on_frame;
};

/// One shown frame: the trajectory frame index and how long it stays (centiseconds).
struct TimedFrame {
  size_t frame = 0;
  int delay_cs = 0;
};

/// GIF timing of `frames` frames `time_step` s apart played at `speed`: consecutive trajectory
/// frames are merged until each stays >= 4 cs (browsers slow faster frames), and delays are
/// rounded so the total stays on the real clock.
std::vector<TimedFrame> GifTimeline(size_t frames, double time_step, double speed,
                                    double hold_end_s);

/// Writes the animation to `path` (.gif, or .mp4 when supported). Throws std::invalid_argument
/// for another extension, a bad speed or a .mp4 without MP4 support; std::runtime_error on I/O.
void WriteAnimation(const EpisodeFigure& figure, double time_step,
                    const std::filesystem::path& path, const AnimationOptions& options = {});

}  // namespace crowdsim::render
