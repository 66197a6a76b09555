#include "train/training_checkpoint.h"

#include <cmath>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>

namespace crowdsim::training {

void WriteCheckpointState(const std::filesystem::path& file, const CheckpointState& s) {
  std::ofstream out(file, std::ios::trunc);
  out.precision(17);
  out << "crowdsim_training_checkpoint 4\n"
      << "config_hash " << s.config_hash << "\n"
      << "phase " << static_cast<int>(s.phase) << "\n"
      << "counter " << s.counter << "\n"
      << "best " << s.best_success << " " << s.best_episode << "\n"
      << "episode_log_bytes " << s.episode_log_bytes << "\n"
      << "rl_episodes " << s.rl_episodes << "\n"
      << "validations " << s.validations.size() << "\n";
  for (const auto& v : s.validations) {
    out << v.episode << " " << v.success << " " << v.collision << " " << v.timeout << " "
        << v.nav_time << " " << v.probe_value << "\n";
  }
  if (!out) throw TrainError("cannot write the checkpoint state " + file.string());
}

CheckpointState ReadCheckpointState(const std::filesystem::path& file) {
  std::ifstream in(file);
  std::string word;
  int version = 0, phase = 0;
  std::size_t count = 0;
  CheckpointState s;
  in >> word >> version;
  if (word != "crowdsim_training_checkpoint" || version < 1 || version > 4) {
    throw TrainError("'" + file.string() + "' is not a training checkpoint of this version");
  }
  in >> word >> s.config_hash >> word >> phase >> word >> s.counter >> word >> s.best_success >>
      s.best_episode;
  if (version >= 2) in >> word >> s.episode_log_bytes;
  if (version >= 4) in >> word >> s.rl_episodes;
  in >> word >> count;
  s.phase = static_cast<TrainPhase>(phase);
  for (std::size_t i = 0; i < count && in; ++i) {
    ValidationResult v;
    in >> v.episode >> v.success >> v.collision >> v.timeout >> v.nav_time;
    if (version >= 3) {
      std::string probe;  // "nan" does not read as a double
      in >> probe;
      v.probe_value = probe == "nan" || probe == "-nan" ? std::numeric_limits<double>::quiet_NaN()
                                                        : std::stod(probe);
    }
    s.validations.push_back(v);
  }
  if (!in || phase < 0 || phase > static_cast<int>(TrainPhase::kDone)) {
    throw TrainError("the checkpoint state '" + file.string() + "' is damaged");
  }
  return s;
}

std::string ValidationCsv(const std::vector<ValidationResult>& validations) {
  std::ostringstream os;
  os << "rl_episode,success_rate,collision_rate,timeout_rate,nav_time,probe_value\n";
  for (const auto& v : validations) {
    os << v.episode << "," << v.success << "," << v.collision << "," << v.timeout << ","
       << v.nav_time << ",";
    if (!std::isnan(v.probe_value)) os << v.probe_value;
    os << "\n";
  }
  return os.str();
}

}  // namespace crowdsim::training
