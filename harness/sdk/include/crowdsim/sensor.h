// Sensor plugin interface: turns the world state into a robot observation.
#pragma once

#include <cstdint>
#include <span>

#include "crowdsim/agent_state.h"
#include "crowdsim/export.h"
#include "crowdsim/observation.h"
#include "crowdsim/rng.h"

namespace crowdsim {

class CollisionWorld;

/// A read-only snapshot a sensor reads (the real state, or a lookahead's propagated state).
struct CROWDSIM_SDK_API SenseInput {
  const AgentState& robot;
  const Frame& frame;  ///< the robot's sensor frame
  std::span<const AgentState> humans;
  const CollisionWorld& world;  ///< static rectangles (Bullet) and ray casts
  /// The episode's stream for sensor noise: draw from (noise_seed, step, what) with no state, so
  /// a reading is the same on any thread and in a lookahead of the same step. 0: no episode.
  std::uint64_t noise_seed = 0;
  int step = 0;  ///< the step sensed (a lookahead senses the next one)
};

/// The noise of `item` (a person, a beam) at this reading's step: stateless, so the same draws on
/// any thread and in a lookahead of that step. `stream` keeps sensors' draws apart (person: 0).
inline Rng NoiseRng(const SenseInput& in, std::uint64_t item, std::uint64_t stream = 0) {
  return Rng(SplitMix64(in.noise_seed ^ SplitMix64((static_cast<std::uint64_t>(in.step) << 24) ^
                                                   item ^ (stream << 56))));
}

class CROWDSIM_SDK_API Sensor {
 public:
  virtual ~Sensor();
  /// Fills `out` (the harness names it). Const, no hidden mutable state: lookahead calls it from
  /// any thread. Locked caches of pure results are fine.
  virtual void Sense(const SenseInput& in, SensorReading* out) const = 0;
};

}  // namespace crowdsim
