// The learning curve of a training: rolling rates, epsilon and validation points from the
// training folder's files, written as SVG and PNG by `train` (end to end, with --seed), and
// `report` on a training folder.
#include "crowdsim/render/learning_curve.h"

#include <gtest/gtest.h>

#include <string>
#include <tuple>
#include <utility>

#include "shell.h"
#include "temp_dir.h"
#include "test_paths.h"

namespace crowdsim::render {
namespace {

namespace fs = std::filesystem;

using testing::Shell;

const char* kEpisodesHeader =
    "phase,index,epsilon,outcome,return,steps,loss,memory,mem_imitation,mem_success,"
    "mem_collision,mem_timeout\n";

TEST(LearningCurveTest, DrawsRollingRatesEpsilonValidationAndLegend) {
  std::string episodes = kEpisodesHeader;
  episodes +=
      "demonstration,0,0,success,0.5,30,0,30,30,0,0,0\nimitation,0,0,,0,0,0.01,30,30,0,0,0\n";
  for (int i = 0; i < 300; ++i) {
    episodes += "rl," + std::to_string(i) + ",0.3," + (i % 3 == 0 ? "timeout" : "success") +
                ",0,10,0.01,100,50,40,0,10\n";
  }
  const Drawing d = LearningCurveDrawing(episodes,
                                         "rl_episode,success_rate,collision_rate,timeout_rate,nav_"
                                         "time\n0,0.5,0.2,0.3,12\n300,0.7,0.1,0.2,11\n",
                                         "probe");
  EXPECT_EQ(d.Count("rolling success"), 1);
  EXPECT_EQ(d.Count("rolling collision"), 1);
  EXPECT_EQ(d.Count("rolling timeout"), 1);
  EXPECT_EQ(d.Count("epsilon"), 1);
  EXPECT_EQ(d.Count("validation success"), 2);
  EXPECT_EQ(d.Count("validation timeout"), 2);
  bool titled = false;
  for (const auto& item : d.items) titled |= item.text == "probe: learning curve (300 RL episodes)";
  EXPECT_TRUE(titled);
  // The rolling success rate ends at 2/3 (one timeout every three episodes).
  for (const auto& item : d.items) {
    if (item.cls != "rolling success") continue;
    const Vec2 last = item.points.back();
    EXPECT_GT(item.points.size(), 100u);
    // The last 50 episodes (250..299) hold 16 timeouts: success 34/50; y of rate r is
    // top + height * (1 - r).
    EXPECT_NEAR(last.y(), 40 + 350 * (1.0 - 34.0 / 50.0), 1e-9);
  }
}

TEST(LearningCurveTest, EmptyFilesGiveAnEmptyChartAndAFolderWithoutThemIsRefused) {
  const Drawing d = LearningCurveDrawing("", "", "nothing yet");
  EXPECT_EQ(d.Count("rolling success"), 0);
  testing::TempDir dir;
  EXPECT_THROW(WriteLearningCurve(dir.path(), "x"), std::runtime_error);
}

TEST(LearningCurveTest, TrainWritesTheCurveAsSvgAndPng) {
  testing::TempDir dir;
  const fs::path file = dir.Write(
      "t.yaml",
      "name: tiny\nseed: 5\npolicy: cadrl\nparams: {sensors: person}\nsensors: [person]\n"
      "world: {source: random_rect, obstacles: 0}\nhumans: {count: 1}\n"
      "training: {il_episodes: 4, il_epochs: 1, rl_episodes: 6, epsilon_start: 0.5, epsilon_end: "
      "0.1, "
      "epsilon_decay_episodes: 4, batch_size: 8, train_batches: 2, validation_interval: 3, "
      "validation_episodes: 2, store_timeouts: terminal}\n");
  const std::string exe = (testing::BinaryDir() / "bin" / "crowdsim-bench").string();
  auto [rc, text] = Shell(exe + " train " + file.string() + " --quiet --seed 11 --out " +
                          (dir.path() / "out").string());
  ASSERT_EQ(rc, 0) << text;
  EXPECT_GT(fs::file_size(dir.path() / "out" / "learning_curve.svg"), 1000u);
  EXPECT_GT(fs::file_size(dir.path() / "out" / "learning_curve.png"), 1000u);
  const std::string summary = testing::ReadText(dir.path() / "out" / "summary.json");
  EXPECT_NE(summary.find("\"seed\": 11"), std::string::npos) << summary;
  EXPECT_NE(summary.find("\"store_timeouts\": \"terminal\""), std::string::npos) << summary;

  // `report` on the training folder: the HTML page, or the curve alone as a figure.
  std::tie(rc, text) = Shell(exe + " report " + (dir.path() / "out").string() + " --out " +
                             (dir.path() / "t.html").string());
  ASSERT_EQ(rc, 0) << text;
  const std::string html = testing::ReadText(dir.path() / "t.html");
  EXPECT_NE(html.find("<h1>Training tiny</h1>"), std::string::npos);
  EXPECT_NE(html.find("RL episodes by block of 500"), std::string::npos);
  EXPECT_NE(html.find("<td>0-5</td>"), std::string::npos) << html;  // one block of six episodes
  std::tie(rc, text) = Shell(exe + " report " + (dir.path() / "out").string() + " --out " +
                             (dir.path() / "curve.pdf").string());
  ASSERT_EQ(rc, 0) << text;
  EXPECT_GT(fs::file_size(dir.path() / "curve.pdf"), 1000u);
  std::tie(rc, text) = Shell(exe + " report " + dir.path().string() + " --out x.png");
  EXPECT_EQ(rc, 2) << text;  // not a training folder and not a run: HTML only, said so
  EXPECT_NE(text.find("--out must end in .html"), std::string::npos) << text;
}

}  // namespace
}  // namespace crowdsim::render
