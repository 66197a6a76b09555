// What a TorchScript policy's forward returned, as the robot's velocity: in `velocity` mode 2
// numbers (vx, vy), in `action` mode an index into, or one score per action of, the action
// set (CrowdNav's 81 holonomic actions by default) (argmax, ties to the earliest), in `values` mode
// one value per lookahead candidate (the policy adds rewards and discount). Anything else is an
// error naming the file, the returned shape and dtype, and what the mode expects. Includes
// libtorch.
#pragma once

#include <ATen/core/ivalue.h>

#include <span>
#include <string>
#include <vector>

#include "crowdsim/action.h"
#include "torchscript_config.h"

namespace crowdsim::torchscript {

/// The action `out` stands for. `actions` is the action set at the robot's v_pref (used in
/// `action` mode). Throws std::runtime_error when `out` does not fit `output`.
Action ActionFromOutput(const c10::IValue& out, Output output, std::span<const Action> actions,
                        const std::string& file);

/// The values of a `values` module (one per lookahead candidate). Throws like ActionFromOutput
/// when `out` does not fit, or on a NaN value.
std::vector<double> ValuesFromOutput(const c10::IValue& out, int actions, const std::string& file);

/// Throws like ActionFromOutput when `out` does not fit `output` (the load-time check).
void CheckOutput(const c10::IValue& out, Output output, int actions, const std::string& file);

}  // namespace crowdsim::torchscript
