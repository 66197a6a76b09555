#include "crowd_tracks/track_position.h"

#include <algorithm>

namespace crowdsim::crowd_tracks {

Vec2 TrackPosition(std::span<const TrackPoint> track, double time) {
  if (time <= track.front().time) return track.front().position;
  if (time >= track.back().time) return track.back().position;
  // The first point after `time`: the segment ends there.
  const auto after = std::upper_bound(track.begin(), track.end(), time,
                                      [](double t, const TrackPoint& p) { return t < p.time; });
  const TrackPoint& b = *after;
  const TrackPoint& a = *(after - 1);
  const double f = (time - a.time) / (b.time - a.time);
  return a.position + f * (b.position - a.position);
}

}  // namespace crowdsim::crowd_tracks
