// Reading recorded tracks: scene files, the derived files, every bad input named by file and line,
// and the interpolation the replay follows.
#include "crowd_tracks/tracks.h"

#include <gtest/gtest.h>

#include <sstream>
#include <string>

#include "crowd_tracks/track_position.h"
#include "temp_dir.h"

namespace crowdsim::crowd_tracks {
namespace {

using crowdsim::testing::TempDir;

// The message ReadTracks throws for `text`, or "" when it reads.
std::string ErrorOf(const TempDir& dir, const std::string& text) {
  const auto file = dir.Write("scene.txt", text);
  try {
    ReadTracks(file);
  } catch (const TrackFileError& e) {
    return e.what();
  }
  return "";
}

TEST(CrowdTracks, ReadsAnEthUcyFileWithItsFrameStep) {
  TempDir dir;
  // ETH numbers frames by 6; person 2 starts a frame later; velocities columns ignored.
  const auto file = dir.Write("scene.txt",
                              "780\t1\t8.0\t3.0\t1.0\t0.0\n786\t1\t8.5\t3.0\t1.0\t0.0\n"
                              "786\t2\t1.0\t1.0\t0.0\t0.0\n792\t1\t9.0\t3.5\t1.0\t0.0\n"
                              "792\t2\t1.0\t2.0\t0.0\t0.0\n");
  const Tracks t = ReadTracks(file);
  ASSERT_EQ(t.people.size(), 2u);
  EXPECT_EQ(t.frames, 3);
  EXPECT_EQ(t.people[0].id, 1);
  EXPECT_EQ(t.people[0].first_frame, 0);
  EXPECT_EQ(t.people[0].positions.size(), 3u);
  EXPECT_EQ(t.people[1].first_frame, 1);
  EXPECT_DOUBLE_EQ(t.people[1].first_time(), 0.4);
  EXPECT_EQ(t.people[1].positions[1], Vec2(1.0, 2.0));
  EXPECT_DOUBLE_EQ(t.duration(), 0.8);
}

TEST(CrowdTracks, ADerivedFileReadsBackAsWrittenWithItsCitation) {
  TempDir dir;
  Tracks t = ReadTracks(dir.Write("s.txt",
                                  "0.0 1.0 1.2344 2.0\n10.0 1.0 1.5 2.25\n"
                                  "10.0 2.0 -3.0 4.0\n"));
  t.scene = "test";
  t.source = "s.txt, a synthetic scene";
  t.cite = "nobody, 2026";
  std::ostringstream text;
  WriteTracks(t, text);
  const Tracks back = ReadTracks(dir.Write("s.tracks", text.str()));
  EXPECT_EQ(back.scene, "test");
  EXPECT_EQ(back.source, "s.txt, a synthetic scene");
  EXPECT_EQ(back.cite, "nobody, 2026");
  ASSERT_EQ(back.people.size(), 2u);
  EXPECT_EQ(back.people[0].positions[0], Vec2(1.234, 2.0));  // millimetres
  EXPECT_EQ(back.people[1].first_frame, 1);
  EXPECT_EQ(back.frames, 2);
}

TEST(CrowdTracks, BadInputIsNamedByFileAndLine) {
  TempDir dir;
  const std::string file = (dir.path() / "scene.txt").string();
  EXPECT_EQ(ErrorOf(dir, ""),
            file + ": holds no tracks (an empty file: expected frame person x y lines)");
  EXPECT_EQ(ErrorOf(dir, "0 1 1 1\n10 1 2 2 3\n"),
            file + ":2: 5 columns, expected 4 (frame person x y) or 6 (frame person x y vx vy)");
  EXPECT_EQ(
      ErrorOf(dir, "0 1 1 1\n\n10 1 2 abc\n"),
      file + ":3: column 4 is 'abc', not a finite number (columns: frame person x y [vx vy])");
  EXPECT_EQ(
      ErrorOf(dir, "0 1 1 nan\n"),
      file + ":1: column 4 is 'nan', not a finite number (columns: frame person x y [vx vy])");
  EXPECT_EQ(ErrorOf(dir, "0 1 1 1\n10 1 2 2\n10 2 0 0\n30 1 3 3\n"),
            file +
                ":4: person 1 jumps from frame 10 to 30 (frames advance by 10): a person's "
                "frames must be contiguous");
  EXPECT_EQ(ErrorOf(dir, "0 1.5 1 1\n"), file + ":1: person id 1.500000 is not a whole number");
  const auto missing = dir.path() / "none.txt";
  try {
    ReadTracks(missing);
    FAIL() << "a missing file read";
  } catch (const TrackFileError& e) {
    EXPECT_EQ(std::string(e.what()), missing.string() + ": not found (no such file)");
  }
}

TEST(CrowdTracks, TrackPositionInterpolatesAndHoldsItsEnds) {
  const std::vector<TrackPoint> track{{0.4, Vec2(0, 0)}, {0.8, Vec2(1, 0)}, {1.2, Vec2(1, 2)}};
  EXPECT_EQ(TrackPosition(track, 0.0), Vec2(0, 0));
  EXPECT_EQ(TrackPosition(track, 0.4), Vec2(0, 0));
  EXPECT_NEAR((TrackPosition(track, 0.5) - Vec2(0.25, 0)).norm(), 0.0, 1e-12);
  EXPECT_EQ(TrackPosition(track, 0.8), Vec2(1, 0));
  EXPECT_NEAR((TrackPosition(track, 1.1) - Vec2(1, 1.5)).norm(), 0.0, 1e-12);
  EXPECT_EQ(TrackPosition(track, 5.0), Vec2(1, 2));
}

}  // namespace
}  // namespace crowdsim::crowd_tracks
