#include "learning_test_util.h"

#include <fstream>
#include <stdexcept>

#include "crowdsim/bench/plugin_registry.h"
#include "crowdsim/bench/training/train_spec.h"
#include "value_rl/state_encoding.h"
#include "value_rl/value_policy.h"

namespace crowdsim::testing {

std::filesystem::path WriteTrainFile(const TempDir& dir, const TrainFile& f,
                                     const std::string& name) {
  std::string text = "name: test_training\nseed: " + std::to_string(f.seed) +
                     "\npolicy: " + f.policy + "\nparams: {sensors: " + f.sensors_param +
                     ", lidar_beams: 15}\nsensors: " + f.sensors + "\nworld: " + f.world +
                     "\nhumans: " + f.humans + "\n";
  if (!f.training.empty()) text += "training: " + f.training + "\n";
  if (!f.sim.empty()) text += "sim: " + f.sim + "\n";
  return dir.Write(name, text);
}

training::TrainSummary Train(const std::filesystem::path& file, const std::filesystem::path& out,
                             bool resume, int stop_after_episodes) {
  PluginRegistry registry;
  training::TrainSpecLoadResult loaded = training::LoadTrainSpec(file, registry);
  if (!loaded.spec) {
    std::string all;
    for (const auto& e : loaded.errors) all += e.Format() + "\n";
    throw std::runtime_error(all);
  }
  training::TrainOptions options;
  options.out_dir = out;
  options.resume = resume;
  options.progress = false;
  options.stop_after_episodes = stop_after_episodes;
  return training::RunTraining(*loaded.spec, registry, options);
}

std::vector<float> ValuesOfWeights(const TrainFile& f, const std::filesystem::path& file) {
  value_rl::ValueRlConfig c;
  c.model = f.policy == "sarl" ? value_rl::Model::kSarl : value_rl::Model::kCadrl;
  c.sensors = f.sensors_param == "person"  ? value_rl::SensorSet::kPerson
              : f.sensors_param == "lidar" ? value_rl::SensorSet::kLidar
                                           : value_rl::SensorSet::kLidarPerson;
  c.lidar_beams = 15;
  c.weights = file.string();
  value_rl::ValuePolicy policy(c);
  std::vector<EncodedState> states;
  for (int k = 0; k < 8; ++k) {
    EncodedState s;
    s.values = {1.0f + k, 1.0f, 0.0f, 0.3f, 0.1f * k, 0.05f * k};
    for (int b = 0; b < c.LidarInputs(); ++b) s.values.push_back(0.07f * ((b * 3 + k) % 14));
    if (value_rl::UsesPerson(c.sensors)) {
      s.values.insert(s.values.end(), {1.5f - 0.2f * k, 0.4f, -0.5f, 0.1f, 0.3f, 1.6f, 0.6f});
    }
    states.push_back(std::move(s));
  }
  std::vector<const EncodedState*> ptrs;
  for (const auto& s : states) ptrs.push_back(&s);
  return policy.Values(ptrs);
}

}  // namespace crowdsim::testing
