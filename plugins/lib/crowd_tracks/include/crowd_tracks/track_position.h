// Where a recorded person is at any time: its track linearly interpolated, held at its ends.
#pragma once

#include <span>

#include "crowdsim/scenario.h"

namespace crowdsim::crowd_tracks {

/// The position at `time` (s) on `track` (times ascending, at least one point): linear between
/// the recorded points around it, the first point before them, the last after them.
Vec2 TrackPosition(std::span<const TrackPoint> track, double time);

}  // namespace crowdsim::crowd_tracks
