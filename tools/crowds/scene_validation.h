// Validation against recorded people (docs/crowds.md): in each window of a recorded scene,
// each recorded person walks by a human model from its first observed state towards its last
// observed position while everybody else is replayed as recorded, through the harness's own
// episode loop; its path is compared with its track over a fixed horizon.
#pragma once

#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "crowdsim/bench/plugin_registry.h"
#include "crowdsim/policy.h"
#include "crowdsim/scenario.h"
#include "crowdsim/sim_config.h"
#include "crowdsim/world_source.h"
#include "track_comparison.h"

namespace crowdsim::crowds {

/// Every constant of the validation, with its origin.
struct ValidationSettings {
  /// s: the trajectory-prediction benchmark's 12 frames at 2.5 Hz (Alahi et al., Social LSTM,
  /// CVPR 2016; Gupta et al., Social GAN, CVPR 2018).
  double horizon = 4.8;
  /// The suites' defaults: 0.25 s steps, 25 s windows, people of radius 0.3 m.
  SimConfig sim;
  /// People a window may hold: 120 holds every window of the six scenes (docs/crowds.md).
  int crowd = 120;
  /// Seeds the world's episode seeds (the robot's crossing, which no person sees).
  std::uint64_t seed = 2026;
  /// The world's splits whose windows are walked: both, since no model is fitted to either.
  std::vector<std::string> splits = {"test", "train"};
};

/// One recorded person walked by a model.
struct PersonValidation {
  std::string split;  ///< the world's split of the window
  int window = 0;     ///< the window (the world's layout index in its split)
  int person = 0;     ///< the person's index in the window's scenario
  TrackComparison comparison;
  bool collided = false;  ///< its disc overlapped another present person's at a step
};

/// A scene's windows, their people and the replaying policies, made once.
class SceneValidation {
 public:
  /// Loads the `crowds` world on `tracks` (each of the settings' splits) and the `replay`
  /// policies. Throws what the world throws for a missing or bad track file.
  SceneValidation(PluginRegistry& registry, const std::filesystem::path& tracks,
                  const ValidationSettings& settings);
  ~SceneValidation();
  const std::string& scene() const { return scene_; }
  /// Every validated person of the windows walked by `model` (a humans' policy), in order of
  /// split, window and person.
  std::vector<PersonValidation> Run(Policy& model) const;

 private:
  void RunWorld(const WorldSource& world, const std::string& split, Policy& model,
                std::vector<PersonValidation>* out) const;
  /// Person `self` of `scenario` walked by `model` from `start` (s) over the horizon, the rest
  /// replayed: its comparison and overlaps into `v`.
  void Walk(const Scenario& scenario, int self, double start, Policy& model,
            PersonValidation* v) const;
  ValidationSettings settings_;
  /// One world per split.
  std::vector<std::shared_ptr<WorldSource>> worlds_;
  std::vector<std::shared_ptr<Policy>> replay_;
  std::string scene_;
};

}  // namespace crowdsim::crowds
