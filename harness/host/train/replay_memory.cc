#include "train/replay_memory.h"

#include <cstdint>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "atomic_file.h"

namespace crowdsim::training {

namespace {

constexpr std::uint64_t kMagic = 0x32594d4552524353ULL;    // "SCRREMY2": entries carry their source
constexpr std::uint64_t kMagicV1 = 0x31594d4552524353ULL;  // before sources

template <typename T>
void Put(std::ostream& out, const T& v) {
  out.write(reinterpret_cast<const char*>(&v), sizeof(T));
}

template <typename T>
T Get(std::ifstream& in) {
  T v{};
  in.read(reinterpret_cast<char*>(&v), sizeof(T));
  return v;
}

}  // namespace

void ReplayMemory::Push(EncodedState state, float value, MemorySource source) {
  ++counts_[static_cast<std::size_t>(source)];
  if (states_.size() < capacity_) {
    states_.push_back(std::move(state));
    values_.push_back(value);
    sources_.push_back(source);
    return;
  }
  --counts_[static_cast<std::size_t>(sources_[position_])];
  states_[position_] = std::move(state);
  values_[position_] = value;
  sources_[position_] = source;
  position_ = (position_ + 1) % capacity_;
}

void ReplayMemory::Save(const std::filesystem::path& file) const {
  std::ostringstream out;  // then written whole: a full disk is said as such
  Put(out, kMagic);
  Put(out, static_cast<std::uint64_t>(capacity_));
  Put(out, static_cast<std::uint64_t>(position_));
  Put(out, static_cast<std::uint64_t>(states_.size()));
  for (std::size_t i = 0; i < states_.size(); ++i) {
    Put(out, values_[i]);
    Put(out, static_cast<std::uint8_t>(sources_[i]));
    Put(out, static_cast<std::uint32_t>(states_[i].values.size()));
    out.write(reinterpret_cast<const char*>(states_[i].values.data()),
              static_cast<std::streamsize>(states_[i].values.size() * sizeof(float)));
  }
  common::WriteFileAtomically(file, out.str());
}

void ReplayMemory::Load(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  const auto magic = Get<std::uint64_t>(in);
  if (in && magic == kMagicV1) {
    throw std::runtime_error("'" + file.string() +
                             "' is a replay memory of an older crowdsim-bench "
                             "(without entry sources); restart that training without --resume");
  }
  if (!in || magic != kMagic) {
    throw std::runtime_error("'" + file.string() + "' is not a replay memory file");
  }
  capacity_ = Get<std::uint64_t>(in);
  position_ = Get<std::uint64_t>(in);
  const auto n = Get<std::uint64_t>(in);
  if (!in || n > capacity_ || position_ >= std::max<std::size_t>(capacity_, 1)) {
    throw std::runtime_error("the replay memory file '" + file.string() + "' is damaged");
  }
  states_.assign(n, EncodedState{});
  values_.assign(n, 0.0f);
  sources_.assign(n, MemorySource::kImitation);
  counts_.fill(0);
  for (std::size_t i = 0; i < n; ++i) {
    values_[i] = Get<float>(in);
    const auto source = Get<std::uint8_t>(in);
    if (source >= kMemorySources) {
      throw std::runtime_error("the replay memory file '" + file.string() + "' is damaged");
    }
    sources_[i] = static_cast<MemorySource>(source);
    ++counts_[source];
    states_[i].values.resize(Get<std::uint32_t>(in));
    in.read(reinterpret_cast<char*>(states_[i].values.data()),
            static_cast<std::streamsize>(states_[i].values.size() * sizeof(float)));
  }
  if (!in) throw std::runtime_error("the replay memory file '" + file.string() + "' is cut short");
}

}  // namespace crowdsim::training
