// Output files: format by extension (and the errors), PNG/PDF through Cairo, GIF animations
// decoded back with giflib, MP4 when built, the GIF timeline, row and episode arguments.
#include <gif_lib.h>
#include <gtest/gtest.h>

#include <fstream>
#include <numeric>
#include <string>

#include "crowdsim/bench/episode.h"
#include "crowdsim/render/animation.h"
#include "crowdsim/render/episode_replay.h"
#include "crowdsim/render/figure_output.h"
#include "crowdsim/render/gif_writer.h"
#include "crowdsim/render/mp4_writer.h"
#include "crowdsim/render/output_format.h"
#include "crowdsim/render/palette.h"
#include "scripted.h"
#include "temp_dir.h"

namespace crowdsim::render {
namespace {

using crowdsim::testing::GoStraightPolicy;
using crowdsim::testing::MakeRoom;
using crowdsim::testing::MakeScenario;
using crowdsim::testing::TempDir;

std::string Head(const std::filesystem::path& p, size_t n) {
  std::ifstream in(p, std::ios::binary);
  std::string s(n, '\0');
  in.read(s.data(), static_cast<std::streamsize>(n));
  s.resize(static_cast<size_t>(in.gcount()));
  return s;
}

std::string MessageOf(const std::function<void()>& f) {
  try {
    f();
  } catch (const std::exception& e) {
    return e.what();
  }
  return "(no exception)";
}

struct Scripted {
  Scenario scenario =
      MakeScenario(MakeRoom({Rect::FromCorners(-1, 1.5, 1, 2.5)}), Vec2(-4, 0), Vec2(4, 0));
  EpisodeResult result;
  Scripted() {
    GoStraightPolicy robot;
    Episode ep(scenario, SimConfig{}, EpisodeAgents{&robot, {}, {}, {}}, true);
    result = ep.Run();
  }
  EpisodeFigure Figure() const {
    EpisodeFigure fig;
    fig.scenario = &scenario;
    fig.title = "scripted";
    fig.robots.push_back(RobotTrack{"robot", &result, palette::kRobot});
    return fig;
  }
};

TEST(OutputFormat, ByExtensionCaseInsensitive) {
  EXPECT_EQ(FormatFromPath("a/b.svg"), OutputFormat::kSvg);
  EXPECT_EQ(FormatFromPath("x.PNG"), OutputFormat::kPng);
  EXPECT_EQ(FormatFromPath("x.pdf"), OutputFormat::kPdf);
  EXPECT_EQ(FormatFromPath("x.gif"), OutputFormat::kGif);
  EXPECT_EQ(FormatFromPath("x.mp4"), OutputFormat::kMp4);
  EXPECT_TRUE(IsAnimation(OutputFormat::kGif));
  EXPECT_FALSE(IsAnimation(OutputFormat::kPdf));
}

TEST(OutputFormat, UnknownExtensionNamesTheValueAndTheChoices) {
  const std::string m = MessageOf([] { FormatFromPath("fig.bmp"); });
  EXPECT_NE(m.find("'.bmp'"), std::string::npos) << m;
  EXPECT_NE(m.find(".svg, .png, .pdf"), std::string::npos) << m;
  EXPECT_NE(m.find(".gif, .mp4"), std::string::npos) << m;
  EXPECT_NE(MessageOf([] { FormatFromPath("noext"); }).find("(no extension)"), std::string::npos);
}

TEST(FigureOutput, WritesSvgPngAndPdf) {
  const Scripted s;
  const Drawing d = DrawEpisode(s.Figure());
  TempDir tmp;
  WriteFigure(d, tmp.path() / "f.svg");
  WriteFigure(d, tmp.path() / "f.png");
  WriteFigure(d, tmp.path() / "f.pdf");
  EXPECT_EQ(Head(tmp.path() / "f.svg", 5), "<?xml");
  EXPECT_EQ(Head(tmp.path() / "f.png", 8), std::string("\x89PNG\r\n\x1a\n", 8));
  EXPECT_EQ(Head(tmp.path() / "f.pdf", 5), "%PDF-");
  // Still figures refuse animation formats, with the fix in the message.
  const std::string m = MessageOf([&] { WriteFigure(d, tmp.path() / "f.gif"); });
  EXPECT_NE(m.find("--animate"), std::string::npos) << m;
}

TEST(GifTimeline, RealTimeShowsEveryStep) {
  const auto t = GifTimeline(33, 0.25, 1.0, 1.5);
  ASSERT_EQ(t.size(), 33u);
  for (size_t i = 0; i + 1 < t.size(); ++i) {
    EXPECT_EQ(t[i].frame, i);
    EXPECT_EQ(t[i].delay_cs, 25);
  }
  EXPECT_EQ(t.back().delay_cs, 25 + 150);
}

TEST(GifTimeline, FasterPlaybackMergesFramesAndKeepsTheClock) {
  // 10x: 2.5 cs per step is below what browsers honour, so every 2nd step is shown for 5 cs.
  const auto t = GifTimeline(101, 0.25, 10.0, 0.0);
  EXPECT_EQ(t.front().frame, 0u);
  EXPECT_EQ(t.back().frame, 100u);  // always ends on the outcome
  int total = 0;
  for (size_t i = 0; i + 1 < t.size(); ++i) {
    EXPECT_GE(t[i].delay_cs, 4);
    total += t[i].delay_cs;
  }
  EXPECT_EQ(total, 250);  // 25 s of episode at 10x
  // 2.5x: 10 cs per step, odd rounding must not drift.
  const auto u = GifTimeline(41, 0.25, 3.0, 0.0);
  int total_u = 0;
  for (size_t i = 0; i + 1 < u.size(); ++i) total_u += u[i].delay_cs;
  EXPECT_EQ(total_u, 333);  // 10 s at 3x
}

TEST(Animation, GifHasOneImagePerShownFrameWithItsDelay) {
  const Scripted s;
  TempDir tmp;
  const auto path = tmp.path() / "a.gif";
  AnimationOptions opt;
  opt.speed = 2.0;
  WriteAnimation(s.Figure(), 0.25, path, opt);
  EXPECT_EQ(Head(path, 6), "GIF89a");
  int error = 0;
  GifFileType* gif = DGifOpenFileName(path.c_str(), &error);
  ASSERT_NE(gif, nullptr);
  ASSERT_EQ(DGifSlurp(gif), GIF_OK);
  const auto timeline = GifTimeline(s.result.trajectory.size(), 0.25, 2.0, opt.hold_end_s);
  EXPECT_EQ(static_cast<size_t>(gif->ImageCount), timeline.size());
  int total = 0;
  for (int i = 0; i < gif->ImageCount; ++i) {
    GraphicsControlBlock gcb;
    ASSERT_EQ(DGifSavedExtensionToGCB(gif, i, &gcb), GIF_OK);
    EXPECT_EQ(gcb.DelayTime, timeline[static_cast<size_t>(i)].delay_cs);
    total += gcb.DelayTime;
  }
  // 8 s at 2x between the first and the last frame; the last one stays one step (12.5 cs,
  // rounded) plus the 1.5 s hold.
  EXPECT_EQ(total, 400 + 13 + 150);
  DGifCloseFile(gif, &error);
  // Deterministic too.
  const auto again = tmp.path() / "b.gif";
  WriteAnimation(s.Figure(), 0.25, again, opt);
  EXPECT_EQ(crowdsim::testing::ReadText(path), crowdsim::testing::ReadText(again));
}

// An animation is written whole or not at all: one cut short (here a frame of the wrong size;
// as Ctrl-C would) leaves the previous file as it was and no other file beside it.
TEST(Animation, AnInterruptedGifLeavesThePreviousFileWhole) {
  const Scripted s;
  TempDir tmp;
  const auto path = tmp.path() / "a.gif";
  WriteAnimation(s.Figure(), 0.25, path, AnimationOptions{});
  const std::string good = crowdsim::testing::ReadText(path);
  {
    GifWriter gif(path, 8, 8, {});
    RgbImage wrong;
    wrong.width = 4;
    wrong.height = 4;
    wrong.pixels.assign(4 * 4 * 3, 0);
    EXPECT_THROW(gif.AddFrame(wrong, 10), std::invalid_argument);
  }
  EXPECT_EQ(crowdsim::testing::ReadText(path), good);
  int files = 0;
  for (const auto& e : std::filesystem::directory_iterator(tmp.path()))
    files += e.is_regular_file();
  EXPECT_EQ(files, 1);
}

// `render --animate` of a long episode ran for minutes without a word: it reports each frame.
TEST(Animation, EveryFrameWrittenIsReported) {
  const Scripted s;
  TempDir tmp;
  for (const char* name : {"a.gif", "a.mp4"}) {
    if (std::string(name) == "a.mp4" && !Mp4Supported()) continue;
    std::vector<std::pair<size_t, size_t>> calls;
    AnimationOptions opt;
    opt.on_frame = [&](size_t done, size_t total) { calls.emplace_back(done, total); };
    WriteAnimation(s.Figure(), 0.25, tmp.path() / name, opt);
    ASSERT_FALSE(calls.empty()) << name;
    for (size_t k = 0; k < calls.size(); ++k) {
      EXPECT_EQ(calls[k].first, k + 1) << name;
      EXPECT_EQ(calls[k].second, calls.size()) << name;
    }
  }
}

// As the GIF: an MP4 cut short leaves the previous file as it was and nothing beside it.
TEST(Animation, AnInterruptedMp4LeavesThePreviousFileWhole) {
  if (!Mp4Supported()) GTEST_SKIP() << "this build has no MP4 support (libav not found)";
  const Scripted s;
  TempDir tmp;
  const auto path = tmp.path() / "a.mp4";
  WriteAnimation(s.Figure(), 0.25, path, AnimationOptions{});
  const std::string good = crowdsim::testing::ReadText(path);
  {
    Mp4Writer mp4(path, 8, 8, 25);
    RgbImage wrong;
    wrong.width = 4;
    wrong.height = 4;
    wrong.pixels.assign(4 * 4 * 3, 0);
    EXPECT_THROW(mp4.AddFrame(wrong), std::invalid_argument);
  }
  EXPECT_EQ(crowdsim::testing::ReadText(path), good);
  int files = 0;
  for (const auto& e : std::filesystem::directory_iterator(tmp.path()))
    files += e.is_regular_file();
  EXPECT_EQ(files, 1);
}

TEST(Animation, Mp4WhenBuiltOtherwiseAClearError) {
  const Scripted s;
  TempDir tmp;
  const auto path = tmp.path() / "a.mp4";
  AnimationOptions opt;
  opt.speed = 4.0;
  if (Mp4Supported()) {
    WriteAnimation(s.Figure(), 0.25, path, opt);
    EXPECT_EQ(Head(path, 8).substr(4), "ftyp");
    EXPECT_GT(std::filesystem::file_size(path), 1000u);
  } else {
    const std::string m = MessageOf([&] { WriteAnimation(s.Figure(), 0.25, path, opt); });
    EXPECT_NE(m.find("mp4 support was not built"), std::string::npos) << m;
    EXPECT_NE(m.find(".gif"), std::string::npos) << m;
  }
}

TEST(Animation, BadSpeedAndStillFormatsAreErrors) {
  const Scripted s;
  TempDir tmp;
  AnimationOptions opt;
  opt.speed = 0.0;
  EXPECT_NE(MessageOf([&] {
              WriteAnimation(s.Figure(), 0.25, tmp.path() / "a.gif", opt);
            }).find("--speed"),
            std::string::npos);
  const std::string m =
      MessageOf([&] { WriteAnimation(s.Figure(), 0.25, tmp.path() / "a.png", {}); });
  EXPECT_NE(m.find(".gif or .mp4"), std::string::npos) << m;
}

Suite TwoRowSuite() {
  Suite suite;
  suite.name = "t";
  suite.episodes = 100;
  suite.rows.resize(2);
  suite.rows[0].label = "linear";
  suite.rows[1].label = "orca";
  return suite;
}

TEST(EpisodeArguments, RowsByNumberOrLabel) {
  const Suite suite = TwoRowSuite();
  EXPECT_EQ(ResolveRow(suite, "1"), 0u);
  EXPECT_EQ(ResolveRow(suite, "2"), 1u);
  EXPECT_EQ(ResolveRow(suite, "orca"), 1u);
  const std::string m = MessageOf([&] { ResolveRow(suite, "3"); });
  EXPECT_NE(m.find("row 3 is out of range"), std::string::npos) << m;
  EXPECT_NE(m.find("1..2"), std::string::npos) << m;
  EXPECT_NE(m.find("linear orca"), std::string::npos) << m;
  const std::string l = MessageOf([&] { ResolveRow(suite, "sarl"); });
  EXPECT_NE(l.find("no row labelled 'sarl'"), std::string::npos) << l;
  EXPECT_NE(MessageOf([&] { ResolveRow(suite, "0"); }).find("out of range"), std::string::npos);
}

TEST(EpisodeArguments, EpisodeIndexWithinTheSuite) {
  const Suite suite = TwoRowSuite();
  EXPECT_EQ(ResolveEpisode(suite, "0"), 0);
  EXPECT_EQ(ResolveEpisode(suite, "99"), 99);
  const std::string m = MessageOf([&] { ResolveEpisode(suite, "100"); });
  EXPECT_NE(m.find("episode 100 is out of range"), std::string::npos) << m;
  EXPECT_NE(m.find("0..99"), std::string::npos) << m;
  EXPECT_NE(MessageOf([&] { ResolveEpisode(suite, "-1"); }).find("0..99"), std::string::npos);
  EXPECT_NE(MessageOf([&] { ResolveEpisode(suite, "two"); }).find("not a whole number"),
            std::string::npos);
}

}  // namespace
}  // namespace crowdsim::render
