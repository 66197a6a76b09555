// Sensor plugin interface: turns the world state into a robot observation.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "crowdsim/agent_state.h"
#include "crowdsim/export.h"
#include "crowdsim/observation.h"
#include "crowdsim/rng.h"

namespace crowdsim {

class CollisionWorld;

/// One earlier step as the robot sensed it: its state (heading as sensed), its sensor frame and
/// the humans.
struct CROWDSIM_SDK_API SensedFrame {
  AgentState robot;
  Frame frame;
  std::vector<AgentState> humans;
  std::vector<int> human_ids;  ///< SenseInput::human_ids of that step
};

/// A read-only snapshot a sensor reads (the real state, or a lookahead's propagated state).
struct CROWDSIM_SDK_API SenseInput {
  const AgentState& robot;
  const Frame& frame;  ///< the robot's sensor frame
  std::span<const AgentState> humans;
  const CollisionWorld& world;  ///< static rectangles (Bullet) and ray casts
  /// The episode's stream for sensor noise: draw from (noise_seed, step, what) with no state, so
  /// a reading is the same on any thread and in a lookahead of the same step. 0: no episode.
  std::uint64_t noise_seed = 0;
  int step = 0;            ///< the step sensed (a lookahead senses the next one)
  double time_step = 0.0;  ///< s between steps; 0: unknown (no episode)
  /// The steps before `step`, oldest first, when a sensor asks for them (Sensor::HistorySteps):
  /// the frames of steps step - past.size() .. step - 1. A lookahead's past ends with the real
  /// current step. Empty when no sensor of the robot asks.
  std::span<const SensedFrame> past = {};
  /// Names the history: readings with the same nonzero id share their past frames (one episode's,
  /// only ever appended to), so a sensor may memoise what it derives from them. 0: no promise.
  std::uint64_t history_id = 0;
  /// A lookahead's reading of a predicted state (which the episode may never reach).
  bool lookahead = false;
  /// The scenario index of each of `humans` when only the present people are handed over
  /// (recorded crowds); empty: humans[i] is human i.
  std::span<const int> human_ids = {};
};

/// The scenario index of in.humans[i]: a person's identity from step to step.
inline int HumanId(const SenseInput& in, std::size_t i) {
  return in.human_ids.empty() ? static_cast<int>(i) : in.human_ids[i];
}

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
  /// How many earlier steps Sense reads from SenseInput::past: 0 (default) none, -1 all of the
  /// episode. The harness keeps the episode's frames only when a sensor asks.
  virtual int HistorySteps() const { return 0; }
};

}  // namespace crowdsim
