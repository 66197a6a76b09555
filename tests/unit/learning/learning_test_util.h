// Training files and trainings for the learning tests.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "crowdsim/bench/training/trainer.h"
#include "crowdsim/trainable.h"
#include "temp_dir.h"

namespace crowdsim::testing {

/// The parts of a training file that the tests vary.
struct TrainFile {
  std::string policy = "cadrl";
  std::string sensors_param = "person";
  std::string sensors = "[person]";
  std::string world = "{source: random_rect, obstacles: 0}";
  std::string humans = "{count: 1}";
  std::string training;  ///< the `training:` map
  std::string sim;       ///< the `sim:` map (empty: defaults)
  int seed = 5;
};

/// Writes the training file into `dir` and returns its path.
std::filesystem::path WriteTrainFile(const TempDir& dir, const TrainFile& f,
                                     const std::string& name = "train.yaml");

/// Loads (ASSERT-free: throws std::runtime_error with the errors) and runs a training.
training::TrainSummary Train(const std::filesystem::path& file, const std::filesystem::path& out,
                             bool resume = false, int stop_after_episodes = -1);

/// The values the weights in `file` give to a fixed set of states of `f`'s configuration.
std::vector<float> ValuesOfWeights(const TrainFile& f, const std::filesystem::path& file);

}  // namespace crowdsim::testing
