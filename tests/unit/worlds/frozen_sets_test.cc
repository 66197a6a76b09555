// The committed random-room sets are exactly what the generator makes from their seeds.
#include "frozen_sets.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <fstream>
#include <set>
#include <sstream>

#include "test_paths.h"

namespace crowdsim::random_rect {
namespace {

namespace fs = std::filesystem;

std::string ReadBytes(const fs::path& path) {
  std::ifstream f(path, std::ios::binary);
  std::ostringstream os;
  os << f.rdbuf();
  return os.str();
}

fs::path CommittedFile(const SetSpec& spec) {
  return crowdsim::testing::SourceDir() / "worlds" / "random_rect" / spec.FileName();
}

TEST(FrozenSets, FourSetsWithDistinctSeeds) {
  const auto sets = CommittedSets();
  ASSERT_EQ(sets.size(), 4u);
  std::set<std::uint64_t> seeds;
  std::set<std::string> files;
  for (const SetSpec& s : sets) {
    EXPECT_EQ(s.count, 100);
    seeds.insert(s.seed);
    files.insert(s.FileName());
  }
  EXPECT_EQ(seeds.size(), 4u);
  EXPECT_EQ(files, (std::set<std::string>{"obstacles_1_test.yaml", "obstacles_1_train.yaml",
                                          "obstacles_3_test.yaml", "obstacles_3_train.yaml"}));
  EXPECT_EQ(LayoutName(sets[3], 17), "rect3_test_017");
}

TEST(FrozenSets, RegeneratingGivesTheCommittedFilesByteForByte) {
  const fs::path dir =
      fs::temp_directory_path() / ("crowdsim_frozen_sets_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  for (const SetSpec& spec : CommittedSets()) {
    const fs::path committed = CommittedFile(spec);
    ASSERT_TRUE(fs::exists(committed)) << committed;
    const fs::path fresh = dir / spec.FileName();
    WriteSet(spec, RectLayoutConfig{}, kCommittedSetsCommand, fresh);
    EXPECT_EQ(ReadBytes(fresh), ReadBytes(committed))
        << committed
        << " differs from what the generator makes now; if the change is "
           "intended, rerun "
        << kCommittedSetsCommand;
  }
  fs::remove_all(dir);
}

TEST(FrozenSets, CommittedFilesReadBackWithTheirNames) {
  for (const SetSpec& spec : CommittedSets()) {
    const auto worlds = ReadWorldSet(CommittedFile(spec));
    ASSERT_EQ(static_cast<int>(worlds.size()), spec.count);
    for (int k = 0; k < spec.count; ++k) {
      EXPECT_EQ(worlds[k].name, LayoutName(spec, k));
      EXPECT_EQ(static_cast<int>(worlds[k].rectangles.size()), kWallCount + spec.obstacles);
    }
  }
}

}  // namespace
}  // namespace crowdsim::random_rect
