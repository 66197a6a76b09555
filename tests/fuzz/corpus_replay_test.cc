// The committed fuzz corpus as a regression test of every build (no libFuzzer needed): each
// file under tests/fuzz/corpus/<target>/ is fed once to the same function the fuzzer calls,
// and must give a result or clean errors (an escaping exception fails the test, a crash ends
// it). The corpus holds the seeds, what the fuzzer found interesting, and every input that once
// crashed a reader.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "fuzz_targets.h"
#include "test_paths.h"

namespace crowdsim::fuzz {
namespace {

namespace fs = std::filesystem;

std::vector<fs::path> CorpusFiles(const std::string& target) {
  std::vector<fs::path> files;
  for (const auto& entry :
       fs::directory_iterator(testing::SourceDir() / "tests/fuzz/corpus" / target)) {
    if (entry.is_regular_file()) files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end());
  return files;
}

std::string Bytes(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

class FuzzCorpus : public ::testing::TestWithParam<FuzzTarget> {};

}  // namespace

// Test names and messages show the target's name, not its bytes.
void PrintTo(const FuzzTarget& target, std::ostream* os) { *os << target.name; }

namespace {

TEST_P(FuzzCorpus, EveryInputGivesAResultOrCleanErrors) {
  const FuzzTarget& target = GetParam();
  const auto files = CorpusFiles(target.name);
  // A corpus folder that lost its files would pass vacuously.
  ASSERT_GE(files.size(), 10u) << "tests/fuzz/corpus/" << target.name << " holds too few inputs";
  for (const fs::path& file : files) {
    SCOPED_TRACE(file.string());
    std::string problem;
    EXPECT_NO_THROW(problem = target.run(Bytes(file)));
    EXPECT_EQ(problem, "");
  }
}

INSTANTIATE_TEST_SUITE_P(Readers, FuzzCorpus, ::testing::ValuesIn(FuzzTargets()),
                         [](const auto& info) { return std::string(info.param.name); });

}  // namespace
}  // namespace crowdsim::fuzz
