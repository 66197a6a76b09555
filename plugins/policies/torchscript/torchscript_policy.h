// The `torchscript` robot policy: a TorchScript module exported from Python decides the
// velocity from the observation the Python package's Env gives (observation_tensors.h). The
// module is loaded and its output checked once, at construction, so a wrong file is an error
// before the first episode. No libtorch in this header.
#pragma once

#include <memory>

#include "crowdsim/params.h"
#include "crowdsim/policy.h"
#include "torchscript_config.h"

namespace crowdsim::torchscript {

class TorchScriptPolicy final : public Policy {
 public:
  explicit TorchScriptPolicy(const Params& params);
  explicit TorchScriptPolicy(const TorchScriptConfig& config);
  ~TorchScriptPolicy() override;

  PolicyNeeds Needs() const override;
  void Reset(const EpisodeContext& ctx) override;
  Action Decide(const Observation& obs) override;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace crowdsim::torchscript
