// train: imitation + reinforcement learning of a learned policy from a training file.
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>

#include "crowdsim/render/learning_curve.h"
#include "crowdsim/training/train_spec.h"
#include "crowdsim/training/trainer.h"
#include "cli_args.h"
#include "commands.h"

namespace crowdsim::cli {

int TrainCommand(const std::vector<std::string>& args) {
  const Args a = Args::Parse(args, {"--out", "--seed", "--set"}, {"--resume", "--quiet"});
  if (a.positional.size() != 1) throw UsageError("train needs exactly one training file");
  PluginRegistry registry;
  training::TrainSpecLoadResult loaded = training::LoadTrainSpec(a.positional[0], registry, a.All("--set"));
  if (!loaded.spec) {
    for (const auto& e : loaded.errors) std::cerr << "error: " << e.Format() << "\n";
    std::cerr << loaded.errors.size() << " error" << (loaded.errors.size() == 1 ? "" : "s")
              << " in " << a.positional[0] << "\n";
    return 2;
  }
  training::TrainOptions options;
  if (auto seed = a.Get("--seed")) {
    // Another training seed of the same file: its own default folder <name>_seed<N>.
    char* end = nullptr;
    const unsigned long long v = std::strtoull(seed->c_str(), &end, 10);
    if (seed->empty() || *end != '\0' || (*seed)[0] == '-') {
      throw UsageError("--seed needs a non-negative integer, got '" + *seed + "'");
    }
    training::OverrideSeed(*loaded.spec, v);
    options.out_dir = std::filesystem::path("results") / "train" / (loaded.spec->name + "_seed" + *seed);
  }
  if (auto out = a.Get("--out")) options.out_dir = *out;
  for (const auto& w : training::TrainSpecWarnings(*loaded.spec)) {
    std::cerr << "warning: " << a.positional[0] << ": " << w << "\n";
  }
  options.resume = a.Has("--resume");
  options.progress = !a.Has("--quiet");
  options.on_files_flushed = [](const std::filesystem::path& dir, const std::string& name) {
    try {
      render::WriteLearningCurve(dir, name);
    } catch (const std::exception& e) {
      throw std::runtime_error(std::string("learning curve not drawn: ") + e.what());
    }
  };
  try {
    const training::TrainSummary s = training::RunTraining(*loaded.spec, registry, options);
    std::cout << "trained " << loaded.spec->name << " in " << s.wall_seconds << " s: "
              << s.weights.string();
    if (!s.best_weights.empty()) std::cout << " (best validation: " << s.best_weights.string() << ")";
    std::cout << "\n";
    if (!s.validations.empty()) {
      const auto& v = s.validations.back();
      std::cout << "last validation: success " << v.success << ", collision " << v.collision
                << ", timeout " << v.timeout << ", nav time " << v.nav_time << "\n";
    }
  } catch (const training::TrainingInterrupted& e) {
    std::cerr << "\n" << e.what() << "\n";
    return 130;
  } catch (const training::TrainError& e) {
    std::cerr << "error: " << e.what() << "\n";
    return 1;
  }
  return 0;
}

}  // namespace crowdsim::cli
