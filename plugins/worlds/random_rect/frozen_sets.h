// The committed test and training sets of random rooms: which seeds made them, and how to
// make them again byte for byte (the generator and the frozen-file test share this code).
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "crowdsim/world_file.h"
#include "rect_layout.h"

namespace crowdsim::random_rect {

/// One world-set file: its obstacle count, split, seed and size.
struct SetSpec {
  int obstacles = 1;
  std::string split = "test";  ///< "train" or "test"
  std::uint64_t seed = 0;      ///< layout k uses Rng(DeriveSeed(seed, SetPrefix(), k))
  int count = 100;             ///< layouts in the file

  /// Name prefix of the layouts, e.g. "rect3_test".
  std::string SetPrefix() const;
  /// File name, e.g. "obstacles_3_test.yaml".
  std::string FileName() const;
};

/// The four committed sets: 1 and 3 obstacles, train and test, 100 layouts each.
std::vector<SetSpec> CommittedSets();

/// Layout k's name, e.g. "rect3_test_017".
std::string LayoutName(const SetSpec& spec, int k);

/// All layouts of a set, generated with `config` (its `obstacles` is replaced by the spec's).
std::vector<crowdsim::WorldFile> GenerateSet(const SetSpec& spec, RectLayoutConfig config,
                                             RectLayoutStats* stats = nullptr);

/// The command, run from the project root, that remakes the committed sets.
inline constexpr const char* kCommittedSetsCommand =
    "build/bin/crowdsim-make-rect-worlds --out worlds/random_rect";

/// The file's comment header: how the set was made and `command`, which remakes it.
std::string SetComment(const SetSpec& spec, const RectLayoutConfig& config,
                       const RectLayoutStats& stats, const std::string& command);

/// Generates a set and writes it with WriteWorldSet; returns the generation statistics.
RectLayoutStats WriteSet(const SetSpec& spec, const RectLayoutConfig& config,
                         const std::string& command, const std::filesystem::path& path);

}  // namespace crowdsim::random_rect
