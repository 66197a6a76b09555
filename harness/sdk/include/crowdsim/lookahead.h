// One-step lookahead for value-based robot policies (CrowdNav's onestep_lookahead); the episode
// itself does not move.
#pragma once

#include <span>
#include <vector>

#include "crowdsim/action.h"
#include "crowdsim/agent_state.h"
#include "crowdsim/export.h"
#include "crowdsim/observation.h"

namespace crowdsim {

/// How a step ends (or does not).
enum class StepEvent { kNone, kDanger, kSuccess, kCollisionHuman, kCollisionObstacle, kTimeout };

/// The outcome of one hypothetical robot action.
struct CROWDSIM_SDK_API LookaheadOutcome {
  AgentState robot;                     ///< robot after the action (world frame)
  Frame frame;                          ///< its sensor frame
  std::vector<SensorReading> readings;  ///< sensors re-evaluated at the propagated state
  double reward = 0.0;
  StepEvent event = StepEvent::kNone;
};

class CROWDSIM_SDK_API Lookahead {
 public:
  virtual ~Lookahead();
  /// Humans' next states: their own policies' actions from the current snapshot, applied.
  virtual std::span<const AgentState> NextHumans() const = 0;
  /// Evaluates each action; `out` is resized to actions.size().
  virtual void Evaluate(std::span<const Action> actions,
                        std::vector<LookaheadOutcome>* out) const = 0;
};

}  // namespace crowdsim
