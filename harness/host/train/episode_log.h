// training_episodes.csv: a line per demonstration, imitation epoch and RL episode. Checkpoints
// record its flushed size; resume truncates to it.
#pragma once

#include <array>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>

#include "train/replay_memory.h"

namespace crowdsim::training {

struct EpisodeLogRow {
  const char* phase = "";  ///< demonstration, imitation (one line per epoch), rl
  int index = 0;           ///< episode (or epoch) within its phase
  double epsilon = 0.0;
  std::string outcome;  ///< success, collision_human, ..., or empty for an epoch
  double discounted_return = 0.0;
  int steps = 0;
  double loss = 0.0;  ///< mean loss of the SGD steps that followed
  std::size_t memory_size = 0;
  std::array<std::size_t, kMemorySources> memory{};  ///< entries by MemorySource
};

class EpisodeLog {
 public:
  static constexpr const char* kHeader =
      "phase,index,epsilon,outcome,return,steps,loss,memory,mem_imitation,mem_success,"
      "mem_collision,mem_timeout";

  /// Opens `file` to append; `keep_bytes` >= 0 (resume) truncates first. New files get the header.
  void Open(const std::filesystem::path& file, std::int64_t keep_bytes);
  void Append(const EpisodeLogRow& row);
  /// Flushes and returns the file size (what a checkpoint records).
  std::int64_t Flush();

 private:
  std::filesystem::path file_;
  std::ofstream out_;
};

}  // namespace crowdsim::training
