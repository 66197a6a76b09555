#include "module_output.h"

#include <ATen/core/Tensor.h>

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace crowdsim::torchscript {

namespace {

std::string Expected(Output output) {
  if (output == Output::kVelocity) {
    return "output: velocity expects 2 floating-point numbers (vx, vy in m/s, world frame), "
           "e.g. a float tensor of shape (2,)";
  }
  return "output: action expects one integer index in [0, " + std::to_string(kActionCount) +
         ") or " + std::to_string(kActionCount) +
         " floating-point scores, one per CrowdNav holonomic action (crowdsim_bench."
         "holonomic_actions())";
}

[[noreturn]] void Refuse(const std::string& file, const std::string& returned, Output output) {
  throw std::runtime_error("torchscript: the module of '" + file + "' returned " + returned +
                           "; " + Expected(output) + " (or set `output` to the other mode)");
}

std::string Describe(const at::Tensor& t) {
  std::ostringstream os;
  os << "a tensor of shape " << t.sizes() << " and dtype " << t.scalar_type();
  return os.str();
}

const at::Tensor& TensorOf(const c10::IValue& out, Output output, const std::string& file) {
  if (!out.isTensor()) Refuse(file, "a " + out.tagKind() + ", not a Tensor", output);
  const at::Tensor& t = out.toTensor();
  const bool floating = t.is_floating_point();
  const bool integral = at::isIntegralType(t.scalar_type(), /*includeBool=*/false);
  const bool fits = output == Output::kVelocity
                        ? floating && t.numel() == 2
                        : (integral && t.numel() == 1) || (floating && t.numel() == kActionCount);
  if (!fits) Refuse(file, Describe(t), output);
  return t;
}

size_t BestScore(const at::Tensor& scores, const std::string& file) {
  const at::Tensor s = scores.to(at::kDouble).contiguous().view({-1});
  const double* v = s.data_ptr<double>();
  size_t best = 0;
  for (size_t i = 0; i < static_cast<size_t>(s.numel()); ++i) {
    if (std::isnan(v[i])) {
      throw std::runtime_error("torchscript: the module of '" + file + "' returned NaN as the "
                               "score of action " + std::to_string(i));
    }
    if (v[i] > v[best]) best = i;
  }
  return best;
}

}  // namespace

void CheckOutput(const c10::IValue& out, Output output, const std::string& file) {
  TensorOf(out, output, file);
}

Action ActionFromOutput(const c10::IValue& out, Output output, std::span<const Action> actions,
                        const std::string& file) {
  const at::Tensor& t = TensorOf(out, output, file);
  if (output == Output::kVelocity) {
    const at::Tensor v = t.to(at::kDouble).contiguous().view({-1});
    return Action{Vec2(v.data_ptr<double>()[0], v.data_ptr<double>()[1])};
  }
  if (t.is_floating_point()) return actions[BestScore(t, file)];
  const int64_t index = t.item<int64_t>();
  if (index < 0 || index >= static_cast<int64_t>(actions.size())) {
    throw std::runtime_error("torchscript: the module of '" + file + "' returned action index " +
                             std::to_string(index) + "; valid: 0 to " +
                             std::to_string(actions.size() - 1) + " (" + Expected(output) + ")");
  }
  return actions[static_cast<size_t>(index)];
}

}  // namespace crowdsim::torchscript
