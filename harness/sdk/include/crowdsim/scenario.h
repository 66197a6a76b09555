// One episode's initial conditions, produced by a world plugin.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "crowdsim/export.h"
#include "crowdsim/static_map.h"

namespace crowdsim {

/// One recorded position of a person (replayed crowds): time in s from the episode start.
struct CROWDSIM_SDK_API TrackPoint {
  double time = 0.0;
  Vec2 position = Vec2::Zero();
};

/// Tolerance (s) of presence times against step times: n * dt and a recorded time may differ in
/// their last bits.
inline constexpr double kPresenceTolerance = 1e-9;

/// A human's start and its goals, visited in order (one goal: it stays there, CrowdNav).
struct CROWDSIM_SDK_API HumanSpec {
  Vec2 start = Vec2::Zero();
  std::vector<Vec2> goals;  ///< at least one
  double radius = 0.3;
  double v_pref = 1.0;
  bool ignores_robot = false;  ///< a distracted person: the robot is never in its view
  int group = -1;              ///< walking group, -1 alone; a group's members are consecutive
  /// Present from `appear` to `leave` (s, both included): an absent person stands still and is
  /// nobody's neighbour, unseen by the sensors and unhit by the robot (docs/crowds.md).
  double appear = 0.0;
  double leave = kInfinity;
  /// A recorded person's track, times ascending (the replay policy follows it); empty: none.
  std::vector<TrackPoint> track;
};

/// Whether `h` is present at `time` (s).
inline bool PresentAt(const HumanSpec& h, double time) {
  return time >= h.appear - kPresenceTolerance && time <= h.leave + kPresenceTolerance;
}
/// Whether `h` is present throughout every episode (every world but recorded crowds).
inline bool AlwaysPresent(const HumanSpec& h) { return h.appear <= 0.0 && h.leave == kInfinity; }

/// Everything needed to replay an episode exactly (with the policies).
struct CROWDSIM_SDK_API Scenario {
  std::shared_ptr<const StaticMap> map;
  Vec2 robot_start = Vec2::Zero();
  Vec2 robot_goal = Vec2::Zero();
  /// rad; a non-holonomic robot's start heading. Unset: facing its goal (CrowdNav's pi/2).
  std::optional<double> robot_heading;
  std::vector<HumanSpec> humans;
  std::uint64_t seed = 0;  ///< the episode seed it is made from
  std::string layout;      ///< layout identity (e.g. "rect3_test_017")
};

}  // namespace crowdsim
