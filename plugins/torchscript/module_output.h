// What a TorchScript policy's forward returned, as the robot's velocity: in `velocity` mode 2
// numbers (vx, vy), in `action` mode an index into, or one score per action of, CrowdNav's 81
// holonomic actions (argmax, ties to the earliest). Anything else is an error naming the file,
// the returned shape and dtype, and what the mode expects. Includes libtorch.
#pragma once

#include <ATen/core/ivalue.h>

#include <span>
#include <string>

#include "crowdsim/action.h"
#include "torchscript_config.h"

namespace crowdsim::torchscript {

/// The action `out` stands for. `actions` is the action set at the robot's v_pref (used in
/// `action` mode). Throws std::runtime_error when `out` does not fit `output`.
Action ActionFromOutput(const c10::IValue& out, Output output, std::span<const Action> actions,
                        const std::string& file);

/// Throws like ActionFromOutput when `out` does not fit `output` (the load-time check).
void CheckOutput(const c10::IValue& out, Output output, const std::string& file);

}  // namespace crowdsim::torchscript
