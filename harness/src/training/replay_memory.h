// CrowdNav's replay memory: a ring buffer of (state, value target) pairs that overwrites the
// oldest entry once full.
#pragma once

#include <cstddef>
#include <filesystem>
#include <vector>

#include "crowdsim/trainable.h"

namespace crowdsim::training {

class ReplayMemory {
 public:
  explicit ReplayMemory(std::size_t capacity) : capacity_(capacity) {}

  /// Stores a pair, overwriting the oldest one when full.
  void Push(EncodedState state, float value);
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
};

}  // namespace crowdsim::training
