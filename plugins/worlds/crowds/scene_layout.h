// What the crowds world derives once from a scene's tracks: its area and walls, its main flow,
// its frozen train/test time windows, and where the robot crosses the flow.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "crowd_tracks/tracks.h"
#include "crowdsim/rng.h"
#include "crowdsim/scenario.h"
#include "crowdsim/world_file.h"

namespace crowdsim::crowds {

/// Seconds per time window: CrowdNav's time_limit, the episode's length in every suite here.
inline constexpr double kWindowSeconds = 25.0;
/// The share of a scene's windows, the last ones, kept for tests (the first 70% train).
inline constexpr double kTestShare = 0.3;
/// m of free floor between the tracks' bounding box and the walls.
inline constexpr double kMargin = 1.0;
/// m; the walls' thickness.
inline constexpr double kWallThickness = 0.5;
/// m; the robot's start and goal lie this far inside the tracks' bounding box.
inline constexpr double kRobotInset = 0.5;
/// The robot crosses within this share of the box's length along the flow, around its centre.
inline constexpr double kCrossingSpread = 0.5;

/// The tracks' bounding box.
Rect TracksBox(const crowd_tracks::Tracks& tracks);
/// The scene's map: the box plus kMargin, walled by four rectangles outside it.
std::shared_ptr<const StaticMap> SceneMap(const crowd_tracks::Tracks& tracks,
                                          const std::string& name);
/// The unit axis of the scene's main flow: the mean of the people's directions from first to last
/// position, as axes (angles doubled, weighted by distance), so opposite flows add up.
Vec2 MainFlowAxis(const crowd_tracks::Tracks& tracks);
/// The start times (s from the recording's first frame) of the split's windows: the recording's
/// whole kWindowSeconds windows, the first (1 - kTestShare) for "train", the rest for "test".
std::vector<double> SplitWindows(const crowd_tracks::Tracks& tracks, const std::string& split);

/// A robot start and goal across the flow: on the line perpendicular to `axis` through a point
/// drawn within kCrossingSpread of `box` along it, from edge to edge of `box` less kRobotInset,
/// in a drawn direction.
StartGoal CrossingPair(const Rect& box, const Vec2& axis, Rng& rng);

}  // namespace crowdsim::crowds
