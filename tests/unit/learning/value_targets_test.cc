// The value targets and the replay memory behind the trainer: TD(0) on a corridor whose values
// are known in closed form, truncated (timeout) transitions that bootstrap while terminal ones
// do not, the memory's composition by episode kind, and the per-episode log's resume cut.
#include "train/value_targets.h"

#include <gtest/gtest.h>

#include <cmath>

#include "temp_dir.h"
#include "train/episode_log.h"
#include "train/replay_memory.h"

namespace crowdsim::training {
namespace {

namespace fs = std::filesystem;

EncodedState Cell(int k) { return EncodedState{{static_cast<float>(k)}}; }

/// A corridor of `n` cells walked left to right, one cell a step, reward 1 on the step that
/// leaves the last cell (terminal). Tabular TD(0) through the replay memory with a target table
/// refreshed every few updates, as the trainer does. `cut`: episodes stop after this many steps
/// (a timeout) and are stored with (`bootstrap`) or without a bootstrapped last target.
std::vector<double> LearnCorridor(int n, double discount, int cut, bool bootstrap) {
  std::vector<double> v(n, 0.0), target(n, 0.0);
  ReplayMemory memory(100);  // small: stale targets of old target tables leave it quickly
  for (int episode = 0; episode < 2000; ++episode) {
    const int start = episode % n;  // every cell is visited as a start
    std::vector<float> rewards;
    std::vector<int> cells;
    int k = start;
    bool terminal = false;
    for (int step = 0; step < cut && !terminal; ++step) {
      cells.push_back(k);
      terminal = k == n - 1;
      rewards.push_back(terminal ? 1.0f : 0.0f);
      ++k;
    }
    std::vector<float> next;
    for (std::size_t i = 1; i < cells.size(); ++i)
      next.push_back(static_cast<float>(target[cells[i]]));
    if (!terminal) {
      if (!bootstrap) continue;  // `off`: a cut episode is not stored at all
      next.push_back(static_cast<float>(target[k]));
    }
    const auto y = TdTargets(rewards, next, discount);
    for (std::size_t i = 0; i < y.size(); ++i) {
      memory.Push(Cell(cells[i]), y[i], terminal ? MemorySource::kSuccess : MemorySource::kTimeout);
    }
    // "SGD": move each cell's value half-way to the mean target of its memory entries.
    std::vector<double> sum(n, 0.0), count(n, 0.0);
    for (std::size_t i = 0; i < memory.size(); ++i) {
      const int c = static_cast<int>(memory.state(i).values[0]);
      sum[c] += memory.value(i);
      count[c] += 1;
    }
    for (int c = 0; c < n; ++c) {
      if (count[c] > 0) v[c] += 0.5 * (sum[c] / count[c] - v[c]);
    }
    if (episode % 5 == 4) target = v;
  }
  return v;
}

TEST(ValueTargetsTest, TdZeroLearnsTheCorridorsClosedFormValues) {
  const int n = 8;
  const double discount = 0.9;
  // Episodes long enough to always reach the end: V(k) = discount^(n - 1 - k).
  const auto v = LearnCorridor(n, discount, 100, true);
  for (int k = 0; k < n; ++k) {
    EXPECT_NEAR(v[k], std::pow(discount, n - 1 - k), 0.02) << "cell " << k;
  }
}

TEST(ValueTargetsTest, TruncatedEpisodesBootstrapToTheTrueValues) {
  // Episodes cut after 3 steps (timeouts): bootstrapped, the far cells still learn their true
  // value from the cells they were cut at; the episodes from the last cells end normally.
  const int n = 8;
  const double discount = 0.9;
  const auto v = LearnCorridor(n, discount, 3, true);
  for (int k = 0; k < n; ++k) {
    EXPECT_NEAR(v[k], std::pow(discount, n - 1 - k), 0.03) << "cell " << k;
  }
}

TEST(ValueTargetsTest, TerminalTargetKeepsTheRewardAndTruncatedBootstraps) {
  const std::vector<float> rewards = {0.0f, 0.0f, -0.25f};
  const auto terminal = TdTargets(rewards, std::vector<float>{0.5f, 0.8f}, 0.9);
  ASSERT_EQ(terminal.size(), 3u);
  EXPECT_FLOAT_EQ(terminal[0], 0.45f);
  EXPECT_FLOAT_EQ(terminal[1], 0.72f);
  EXPECT_FLOAT_EQ(terminal[2], -0.25f);  // no bootstrap past a terminal state
  const auto truncated = TdTargets(rewards, std::vector<float>{0.5f, 0.8f, 0.6f}, 0.9);
  EXPECT_FLOAT_EQ(truncated[2], -0.25f + 0.9f * 0.6f);  // the state it stopped in counts
  EXPECT_THROW(TdTargets(rewards, std::vector<float>{0.5f}, 0.9), std::invalid_argument);
  EXPECT_TRUE(TdTargets({}, {}, 0.9).empty());
}

TEST(ValueTargetsTest, MonteCarloReturnsDiscountFromTheEnd) {
  const auto v = MonteCarloReturns(std::vector<float>{0.0f, 0.0f, 1.0f}, 0.5);
  ASSERT_EQ(v.size(), 3u);
  EXPECT_FLOAT_EQ(v[0], 0.25f);
  EXPECT_FLOAT_EQ(v[1], 0.5f);
  EXPECT_FLOAT_EQ(v[2], 1.0f);
}

TEST(ReplayMemoryTest, CompositionFollowsOverwritesAndCheckpoints) {
  ReplayMemory m(4);
  m.Push(Cell(0), 0.f, MemorySource::kImitation);
  m.Push(Cell(1), 0.f, MemorySource::kImitation);
  m.Push(Cell(2), 0.f, MemorySource::kSuccess);
  m.Push(Cell(3), 0.f, MemorySource::kTimeout);
  using C = std::array<std::size_t, kMemorySources>;
  EXPECT_EQ(m.composition(), (C{2, 1, 0, 1}));
  m.Push(Cell(4), 0.f, MemorySource::kCollision);  // overwrites the oldest (imitation)
  m.Push(Cell(5), 0.f, MemorySource::kCollision);
  EXPECT_EQ(m.composition(), (C{0, 1, 2, 1}));
  EXPECT_EQ(m.size(), 4u);

  testing::TempDir dir;
  m.Save(dir.path() / "memory.bin");
  ReplayMemory loaded(1);
  loaded.Load(dir.path() / "memory.bin");
  EXPECT_EQ(loaded.composition(), m.composition());
  // The ring position survives the round trip: the next entry replaces the success in slot 2.
  loaded.Push(Cell(6), 0.f, MemorySource::kImitation);
  EXPECT_EQ(loaded.composition(), (C{1, 0, 2, 1}));
  EXPECT_FLOAT_EQ(loaded.state(2).values[0], 6.f);
}

TEST(EpisodeLogTest, ResumeCutsBackToTheCheckpointedSize) {
  testing::TempDir dir;
  const fs::path file = dir.path() / "training_episodes.csv";
  EpisodeLog log;
  log.Open(file, -1);
  EpisodeLogRow row;
  row.phase = "rl";
  row.outcome = "success";
  log.Append(row);
  const std::int64_t checkpointed = log.Flush();
  row.index = 1;
  row.outcome = "timeout";
  log.Append(row);  // after the checkpoint: lost to a crash, run again after the resume
  log.Flush();
  EpisodeLog resumed;
  resumed.Open(file, checkpointed);
  row.outcome = "collision_human";
  resumed.Append(row);
  resumed.Flush();
  EXPECT_EQ(testing::ReadText(file), std::string(EpisodeLog::kHeader) +
                                         "\nrl,0,0,success,0,0,0,0,0,0,0,0\n" +
                                         "rl,1,0,collision_human,0,0,0,0,0,0,0,0\n");
}

}  // namespace
}  // namespace crowdsim::training
