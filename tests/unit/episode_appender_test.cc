// episodes.csv's appender: lines reach the file within the delay without another append, at
// Finish, at once without a delay, and from a signal handler (Ctrl-C keeps them); a full disk
// is named with its file and reason.
#include "run/episode_appender.h"

#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <functional>
#include <thread>

#include "temp_dir.h"

namespace crowdsim {
namespace {

using std::chrono::milliseconds;

// Two lines appended with an hour's delay: nothing is written until `flush` runs.
void PendingLinesAreWrittenBy(const std::function<void(EpisodeAppender&)>& flush) {
  testing::TempDir dir;
  const auto file = dir.path() / "episodes.csv";
  EpisodeAppender out(file, std::chrono::hours(1));
  std::string why;
  ASSERT_TRUE(out.Append("a,1", &why)) << why;
  ASSERT_TRUE(out.Append("b,2", &why)) << why;
  EXPECT_EQ(testing::ReadText(file), "");
  flush(out);
  EXPECT_EQ(testing::ReadText(file), "a,1\nb,2\n");
  out.Finish(&why);
  EXPECT_EQ(testing::ReadText(file), "a,1\nb,2\n");  // written once
}

TEST(EpisodeAppender, LinesWaitForTheDelayOrFinish) {
  PendingLinesAreWrittenBy([](EpisodeAppender& out) {
    std::string why;
    EXPECT_TRUE(out.Finish(&why)) << why;
  });
}

TEST(EpisodeAppender, TheSignalHandlerFlushWritesThePendingLinesOnce) {
  PendingLinesAreWrittenBy([](EpisodeAppender&) { EpisodeAppender::FlushForSignal(); });
}

TEST(EpisodeAppender, TheBackgroundThreadWritesWithoutAnotherAppend) {
  testing::TempDir dir;
  const auto file = dir.path() / "episodes.csv";
  EpisodeAppender out(file, milliseconds(20));
  std::string why;
  ASSERT_TRUE(out.Append("only,1", &why)) << why;
  // Not a timing claim: the line must come without Finish; a loaded machine gets 30 s.
  for (int i = 0; i < 3000 && testing::ReadText(file).empty(); ++i) {
    std::this_thread::sleep_for(milliseconds(10));
  }
  EXPECT_EQ(testing::ReadText(file), "only,1\n");
  ASSERT_TRUE(out.Finish(&why)) << why;
  EXPECT_EQ(testing::ReadText(file), "only,1\n");
}

TEST(EpisodeAppender, WithoutADelayEachLineIsWrittenAtOnce) {
  testing::TempDir dir;
  const auto file = dir.path() / "episodes.csv";
  std::ofstream(file) << "header\n";
  EpisodeAppender out(file, milliseconds(0));
  std::string why;
  ASSERT_TRUE(out.Append("x,1", &why)) << why;
  EXPECT_EQ(testing::ReadText(file), "header\nx,1\n");  // appended, not truncated
  const std::string longer(100000, 'y');                // longer than the buffer
  ASSERT_TRUE(out.Append(longer, &why)) << why;
  EXPECT_EQ(testing::ReadText(file), "header\nx,1\n" + longer + "\n");
  ASSERT_TRUE(out.Finish(&why)) << why;
}

TEST(EpisodeAppender, AFullDiskIsNamedWithItsReason) {
  if (!std::filesystem::exists("/dev/full")) GTEST_SKIP() << "no /dev/full here";
  EpisodeAppender out("/dev/full", milliseconds(0));
  std::string why;
  EXPECT_FALSE(out.Append("a,1", &why));
  EXPECT_NE(why.find("/dev/full"), std::string::npos) << why;
  EXPECT_NE(why.find("No space left on device"), std::string::npos) << why;
  EXPECT_FALSE(out.Append("b,2", &why));  // stays failed
  EXPECT_FALSE(out.Finish(&why));
}

TEST(EpisodeAppender, AnUnwritableFileIsNamed) {
  try {
    EpisodeAppender out("/nonexistent-folder/episodes.csv", milliseconds(0));
    ADD_FAILURE() << "opened a file in a missing folder";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent-folder/episodes.csv"), std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace crowdsim
