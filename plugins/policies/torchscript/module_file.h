// Loading a TorchScript file with errors that name the file, what is wrong and the fix: a
// missing or damaged file, a file that is no TorchScript module (e.g. torch.save of a
// state_dict), a module without forward(obs: Dict[str, Tensor]). Includes libtorch: only
// torchscript_policy.cc includes this header.
#pragma once

#include <torch/csrc/jit/api/module.h>

#include <string>

namespace crowdsim::torchscript {

/// The module in `file`, in eval mode, its forward checked to take one Dict[str, Tensor].
/// Throws std::runtime_error otherwise.
torch::jit::Module LoadPolicyModule(const std::string& file);

}  // namespace crowdsim::torchscript
