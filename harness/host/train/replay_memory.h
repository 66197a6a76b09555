// CrowdNav's replay memory: a ring buffer of (state, value target) pairs, each tagged with its
// episode kind for logging.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <vector>

#include "crowdsim/trainable.h"

namespace crowdsim::training {

/// The episode a memory entry is recorded in.
enum class MemorySource : std::uint8_t { kImitation, kSuccess, kCollision, kTimeout };
inline constexpr std::size_t kMemorySources = 4;

class ReplayMemory {
 public:
  explicit ReplayMemory(std::size_t capacity) : capacity_(capacity) {}

  /// Stores a pair, overwriting the oldest one when full.
  void Push(EncodedState state, float value, MemorySource source);
  /// Entries now held from each source (indexed by MemorySource).
  const std::array<std::size_t, kMemorySources>& composition() const { return counts_; }
  std::size_t size() const { return states_.size(); }
  std::size_t capacity() const { return capacity_; }
  const EncodedState& state(std::size_t i) const { return states_[i]; }
  float value(std::size_t i) const { return values_[i]; }

  /// Binary dump (checkpoints); Load replaces the contents. Load throws std::runtime_error
  /// on a damaged or foreign file.
  void Save(const std::filesystem::path& file) const;
  void Load(const std::filesystem::path& file);

 private:
  std::size_t capacity_;
  std::size_t position_ = 0;  // next slot to overwrite once full
  std::vector<EncodedState> states_;
  std::vector<float> values_;
  std::vector<MemorySource> sources_;
  std::array<std::size_t, kMemorySources> counts_{};
};

}  // namespace crowdsim::training
