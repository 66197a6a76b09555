// The colours of every figure, in one place so figures, animations and the report agree.
#pragma once

#include "crowdsim/render/drawing.h"

namespace crowdsim::render::palette {

inline constexpr Color kInk{33, 33, 33, 1.0};              ///< text
inline constexpr Color kMutedInk{110, 110, 110, 1.0};      ///< secondary text, bounds
inline constexpr Color kObstacleFill{150, 150, 150, 1.0};  ///< rectangles
inline constexpr Color kObstacleEdge{90, 90, 90, 1.0};     ///< rectangle outlines
inline constexpr Color kBlocked{214, 214, 214, 1.0};       ///< mask cells that are not navigable
inline constexpr Color kRobot{31, 119, 180, 1.0};          ///< first robot (blue)
inline constexpr Color kRobotCompare{230, 110, 20, 1.0};   ///< second robot of --compare (orange)
inline constexpr Color kBeam{220, 40, 40, 1.0};            ///< lidar beams and hits
inline constexpr Color kPersonReading{148, 52, 190, 1.0};  ///< person-sensor detections
inline constexpr Color kUnseen{150, 150, 150, 1.0};        ///< people no detection is near
inline constexpr Color kGroupLink{90, 90, 90, 0.6};        ///< the links of a walking group
inline constexpr Color kSuccess{44, 160, 44, 1.0};         ///< outcome charts: success
inline constexpr Color kCollision{214, 39, 40, 1.0};       ///< collisions, collision marks
inline constexpr Color kTimeout{255, 170, 40, 1.0};        ///< timeouts
inline constexpr Color kOther{127, 127, 127, 1.0};         ///< policy errors, anything else

/// Colour of human `i` (cycles through 8 hues distinct from the robots').
Color Human(int i);

/// Colour of an outcome in charts and titles (success green, collisions red, timeout amber).
Color Outcome(const char* status_name);

}  // namespace crowdsim::render::palette
