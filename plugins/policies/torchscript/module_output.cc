#include "module_output.h"

#include <ATen/core/Tensor.h>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace crowdsim::torchscript {

namespace {

std::string Expected(Output output, int actions) {
  if (output == Output::kVelocity) {
    return "output: velocity expects 2 floating-point numbers (vx, vy in m/s, world frame), "
           "e.g. a float tensor of shape (2,)";
  }
  if (output == Output::kCommand) {
    return "output: command expects 2 floating-point numbers (linear m/s along the heading, "
           "angular rad/s), e.g. a float tensor of shape (2,)";
  }
  if (output == Output::kValues) {
    return "output: values expects " + std::to_string(actions) +
           " floating-point values, one per row of the stacked lookahead observation (one per "
           "action of the action set), e.g. a float tensor of shape (" +
           std::to_string(actions) + ",)";
  }
  return "output: action expects one integer index in [0, " + std::to_string(actions) + ") or " +
         std::to_string(actions) +
         " floating-point scores, one per action of the action set (CrowdNav's holonomic "
         "actions by default: crowdsim_bench.holonomic_actions())";
}

[[noreturn]] void Refuse(const std::string& file, const std::string& returned, Output output,
                         int actions) {
  throw std::runtime_error("torchscript: the module of '" + file + "' returned " + returned + "; " +
                           Expected(output, actions) + " (or set `output` to another mode)");
}

std::string Describe(const at::Tensor& t) {
  std::ostringstream os;
  os << "a tensor of shape " << t.sizes() << " and dtype " << t.scalar_type();
  return os.str();
}

const at::Tensor& TensorOf(const c10::IValue& out, Output output, int actions,
                           const std::string& file) {
  if (!out.isTensor()) Refuse(file, "a " + out.tagKind() + ", not a Tensor", output, actions);
  const at::Tensor& t = out.toTensor();
  const bool floating = t.is_floating_point();
  const bool integral = at::isIntegralType(t.scalar_type(), /*includeBool=*/false);
  bool fits = false;
  switch (output) {
    case Output::kVelocity:
    case Output::kCommand:
      fits = floating && t.numel() == 2;
      break;
    case Output::kAction:
      fits = (integral && t.numel() == 1) || (floating && t.numel() == actions);
      break;
    case Output::kValues:
      fits = floating && t.numel() == actions;
      break;
  }
  if (!fits) Refuse(file, Describe(t), output, actions);
  return t;
}

/// The scores as doubles; a NaN is an error naming the action.
std::vector<double> Scores(const at::Tensor& scores, const std::string& file, const char* what) {
  const at::Tensor s = scores.to(at::kDouble).contiguous().view({-1});
  const double* v = s.data_ptr<double>();
  for (int64_t i = 0; i < s.numel(); ++i) {
    if (std::isnan(v[i])) {
      throw std::runtime_error("torchscript: the module of '" + file + "' returned NaN as the " +
                               what + " of action " + std::to_string(i));
    }
  }
  return std::vector<double>(v, v + s.numel());
}

size_t BestScore(const at::Tensor& scores, const std::string& file) {
  const std::vector<double> v = Scores(scores, file, "score");
  return static_cast<size_t>(std::max_element(v.begin(), v.end()) - v.begin());
}

}  // namespace

std::vector<double> ValuesFromOutput(const c10::IValue& out, int actions, const std::string& file) {
  return Scores(TensorOf(out, Output::kValues, actions, file), file, "value");
}

void CheckOutput(const c10::IValue& out, Output output, int actions, const std::string& file) {
  TensorOf(out, output, actions, file);
}

Action ActionFromOutput(const c10::IValue& out, Output output, std::span<const Action> actions,
                        const std::string& file) {
  const int count = static_cast<int>(actions.size());
  const at::Tensor& t = TensorOf(out, output, count, file);
  if (output == Output::kVelocity || output == Output::kCommand) {
    const at::Tensor v = t.to(at::kDouble).contiguous().view({-1});
    const double a = v.data_ptr<double>()[0], b = v.data_ptr<double>()[1];
    return output == Output::kVelocity ? Action(Vec2(a, b)) : Action::Command(a, b);
  }
  if (t.is_floating_point()) return actions[BestScore(t, file)];
  const int64_t index = t.item<int64_t>();
  if (index < 0 || index >= static_cast<int64_t>(actions.size())) {
    throw std::runtime_error("torchscript: the module of '" + file + "' returned action index " +
                             std::to_string(index) + "; valid: 0 to " +
                             std::to_string(actions.size() - 1) + " (" + Expected(output, count) +
                             ")");
  }
  return actions[static_cast<size_t>(index)];
}

}  // namespace crowdsim::torchscript
