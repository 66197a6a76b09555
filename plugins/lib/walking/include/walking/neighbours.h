// The people a force-model person reacts to, world frame: ground truth for a human, the person
// sensor's people for the robot.
#pragma once

#include <vector>

#include "crowdsim/observation.h"

namespace crowdsim::walking {

/// One person nearby: centre, velocity and radius.
struct Neighbour {
  Vec2 position = Vec2::Zero();
  Vec2 velocity = Vec2::Zero();
  double radius = 0.3;
};

/// Fills `out` with the people whose centre is closer than `range` to obs.self: a human's
/// `max_neighbors` nearest (obs.agents; `ids` is scratch), or every person the robot's `person`
/// sensor reports within range.
void GatherNeighbours(const Observation& obs, double range, int max_neighbors,
                      std::vector<int>* ids, std::vector<Neighbour>* out);

}  // namespace crowdsim::walking
