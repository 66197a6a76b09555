// The `torchscript` plugin: a policy exported from PyTorch (torch.jit.save) as a drop-in.
#include "crowdsim/plugin_abi.h"
#include "torchscript_policy.h"

namespace crowdsim::torchscript {

extern "C++" const PluginDescriptor kDescriptor = PolicyPlugin<TorchScriptPolicy>(
    "torchscript",
    "a TorchScript module from PyTorch: forward(obs: Dict[str, Tensor]) -> velocity or action",
    &Schema);

}  // namespace crowdsim::torchscript

CROWDSIM_EXPORT_PLUGIN(crowdsim::torchscript::kDescriptor)
