// Sensor plugin interface: turns the world state into a robot observation.
#pragma once

#include <span>

#include "crowdsim/agent_state.h"
#include "crowdsim/export.h"
#include "crowdsim/observation.h"

namespace crowdsim {

class CollisionWorld;

/// A read-only snapshot a sensor reads (the real state, or a lookahead's propagated state).
struct CROWDSIM_SDK_API SenseInput {
  const AgentState& robot;
  const Frame& frame;  ///< the robot's sensor frame
  std::span<const AgentState> humans;
  const CollisionWorld& world;  ///< static rectangles (Bullet) and ray casts
};

class CROWDSIM_SDK_API Sensor {
 public:
  virtual ~Sensor();
  /// Fills `out` (its `sensor` name is set by the harness). Must be thread-compatible:
  /// const, no hidden mutable state, so lookahead can call it freely. A cache of data that is
  /// a pure function of the input (e.g. keyed on CollisionWorld::serial and the goal) is
  /// allowed when it is locked and changes no result.
  virtual void Sense(const SenseInput& in, SensorReading* out) const = 0;
};

}  // namespace crowdsim
