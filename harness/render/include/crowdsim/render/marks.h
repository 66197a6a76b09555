// The shapes that mark points in an episode figure and in its key (canvas px).
#pragma once

#include <vector>

#include "crowdsim/geometry.h"

namespace crowdsim::render {

/// A five-pointed star of outer radius `outer` around `c` (the robot's goal).
std::vector<Vec2> Star(const Vec2& c, double outer);
/// An axis-aligned square of half side `half` (the robot's start).
std::vector<Vec2> Square(const Vec2& c, double half);
/// A square standing on a corner, half diagonal `half` (a human's goal).
std::vector<Vec2> Diamond(const Vec2& c, double half);

}  // namespace crowdsim::render
