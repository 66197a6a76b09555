#include "module_file.h"

#include <torch/csrc/jit/serialization/import.h>

#include <filesystem>
#include <stdexcept>

#include "crowdsim/input_file.h"
#include "value_rl/zip_crc_check.h"

namespace crowdsim::torchscript {
namespace fs = std::filesystem;

namespace {

constexpr const char* kExport = "torch.jit.script(model).save(path)";

std::string Where(const std::string& file) { return "torchscript: weights file '" + file + "'"; }

void CheckForward(const torch::jit::Module& module, const std::string& file) {
  const auto forward = module.find_method("forward");
  if (!forward) {
    throw std::runtime_error(Where(file) +
                             " has no forward method; the policy calls "
                             "forward(obs: Dict[str, Tensor]) -> Tensor (define it, then " +
                             kExport + ")");
  }
  const c10::FunctionSchema& schema = forward->function().getSchema();
  const auto& args = schema.arguments();  // args[0] is self
  const bool one_dict = args.size() == 2 && args[1].type()->str() == "Dict(str, Tensor)";
  if (!one_dict) {
    throw std::runtime_error(Where(file) + " has " + c10::toString(schema) +
                             "; expected forward(self, obs: Dict[str, Tensor]) -> Tensor "
                             "(annotate the argument: `obs: Dict[str, torch.Tensor]`)");
  }
}

}  // namespace

torch::jit::Module LoadPolicyModule(const std::string& file) {
  if (const std::string why = NotARegularFile(file); !why.empty()) {
    throw std::runtime_error(Where(file) + " " + why + "; export the policy with " + kExport +
                             " and name that file in `weights`");
  }
  if (const auto damage = value_rl::FindZipDamage(file)) {
    throw std::runtime_error(
        Where(file) +
        " is damaged: " + (damage->entry.empty() ? "" : "entry '" + damage->entry + "': ") +
        damage->problem + "; export it again with " + kExport + " or copy it again");
  }
  torch::jit::Module module;
  try {
    module = torch::jit::load(file);
  } catch (const c10::Error& e) {
    throw std::runtime_error(Where(file) + " is not a TorchScript module (" +
                             e.what_without_backtrace() + "); write it with " + kExport +
                             ", not torch.save(model.state_dict())");
  } catch (const std::exception& e) {
    throw std::runtime_error(Where(file) + " is not a TorchScript module (" + e.what() +
                             "); write it with " + kExport + ", not torch.save(...)");
  }
  CheckForward(module, file);
  module.eval();
  return module;
}

}  // namespace crowdsim::torchscript
