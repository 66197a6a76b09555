// `crowdsim-bench crowds` end to end: a scene imported, and a bad one refused by file and line
// with nothing written.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "crowd_scene.h"
#include "crowd_tracks/tracks.h"
#include "shell.h"
#include "temp_dir.h"
#include "test_paths.h"

namespace crowdsim {
namespace {

using crowdsim::testing::Shell;
using crowdsim::testing::TempDir;

std::pair<int, std::string> Crowds(const std::string& args) {
  const auto bin = crowdsim::testing::BinaryDir() / "bin" / "crowdsim-bench";
  return Shell(bin.string() + " crowds " + args);
}

TEST(CrowdsCli, ImportsASceneWithItsCitation) {
  TempDir dir;
  const auto scene = dir.Write("scene.txt", testing::SyntheticScene());
  const auto out = dir.path() / "out" / "s.tracks";
  const auto [status, text] =
      Crowds("import " + scene.string() + " --scene s --source 'a test' --cite 'nobody' --out " +
             out.string());
  EXPECT_EQ(status, 0) << text;
  const crowd_tracks::Tracks t = crowd_tracks::ReadTracks(out);
  EXPECT_EQ(t.people.size(), 4u);
  EXPECT_EQ(t.cite, "nobody");
  // Another file than the six known scenes must say what it is.
  EXPECT_EQ(Crowds("import " + scene.string() + " --out " + out.string()).first, 2);
}

TEST(CrowdsCli, ABadSceneIsNamedByFileAndLineAndNothingIsWritten) {
  TempDir dir;
  const auto out = dir.path() / "s.tracks";
  const auto bad = dir.Write("scene.txt", "0 1 1 1\n10 1 2 2\n30 1 3 3\n");
  const auto [status, text] =
      Crowds("import " + bad.string() + " --scene s --source x --cite y --out " + out.string());
  EXPECT_EQ(status, 1);
  EXPECT_NE(text.find(bad.string() + ":3: person 1 jumps from frame 10 to 30"), std::string::npos)
      << text;
  EXPECT_FALSE(std::filesystem::exists(out));
  const auto [missing, why] = Crowds("import " + (dir.path() / "none.txt").string() +
                                     " --scene s --source x --cite y --out " + out.string());
  EXPECT_EQ(missing, 1);
  EXPECT_NE(why.find("none.txt: not found"), std::string::npos) << why;
}

// A suite whose crowds world names a bad track file stops before its first episode, naming the
// file and line, and writes nothing.
TEST(CrowdsCli, ASuiteWithABadTrackFileRunsNothing) {
  TempDir dir;
  dir.Write("bad.tracks", "0 1 1 1\n1 1 2 2\n3 1 3 3\n");
  const auto suite = dir.Write("s.yaml",
                               "name: bad\nepisodes: 2\nseed: 1\n"
                               "world: {source: crowds, file: bad.tracks}\n"
                               "humans: {count: 5, policy: replay}\n"
                               "rows:\n  - {label: linear, policy: linear}\n");
  const auto bin = crowdsim::testing::BinaryDir() / "bin" / "crowdsim-bench";
  const auto out = dir.path() / "out";
  const auto [status, text] = Shell("cd " + dir.path().string() + " && " + bin.string() +
                                    " run s.yaml --out " + out.string());
  EXPECT_EQ(status, 2) << text;
  EXPECT_NE(text.find("bad.tracks:3: person 1 jumps from frame 1 to 3"), std::string::npos) << text;
  EXPECT_FALSE(std::filesystem::exists(out));
}

// `crowds validate` refuses an unknown model and a missing track file by name, running nothing;
// on a good scene it writes the table.
TEST(CrowdsCli, ValidateNamesABadModelOrFileAndRunsNothing) {
  TempDir dir;
  const auto tracks = testing::WriteSyntheticTracks(dir.path());
  const auto out = dir.path() / "out";
  const auto [status, text] =
      Crowds("validate " + tracks.string() + " --models orca,sfm --out " + out.string());
  EXPECT_EQ(status, 2) << text;
  EXPECT_NE(text.find("unknown human model 'sfm'"), std::string::npos) << text;
  const auto none = dir.path() / "none.tracks";
  const auto [missing, why] = Crowds("validate " + none.string() + " --out " + out.string());
  EXPECT_EQ(missing, 2) << why;
  EXPECT_NE(why.find(none.string() + " does not exist"), std::string::npos) << why;
  EXPECT_FALSE(std::filesystem::exists(out));
  const auto [ok, table] =
      Crowds("validate " + tracks.string() + " --models linear,replay --out " + out.string());
  EXPECT_EQ(ok, 0) << table;
  EXPECT_NE(table.find("| synthetic | replay | 2 | 0.000 | 0.000 |"), std::string::npos) << table;
  EXPECT_TRUE(std::filesystem::exists(out / "table.csv"));
}

}  // namespace
}  // namespace crowdsim
