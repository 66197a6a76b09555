#include "crowdsim/agent_index.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "crowdsim/rng.h"

namespace crowdsim {
namespace {

/// Nearest gives the brute-force answer: within range, nearest first, ties by index.
void ExpectBruteForceAnswer(const std::vector<AgentState>& agents, const AgentIndex& index,
                            const Vec2& p, double range, int k, int exclude) {
  std::vector<std::pair<double, int>> brute;
  for (int i = 0; i < static_cast<int>(agents.size()); ++i) {
    const double d2 = (agents[i].position - p).squaredNorm();
    if (i != exclude && d2 < range * range) brute.emplace_back(d2, i);
  }
  std::sort(brute.begin(), brute.end());
  if (static_cast<int>(brute.size()) > k) brute.resize(k);
  std::vector<int> got(20, -7);  // a reused vector's old content must not survive the query
  index.Nearest(p, range, k, exclude, &got);
  ASSERT_EQ(got.size(), brute.size());
  for (size_t i = 0; i < got.size(); ++i) EXPECT_EQ(got[i], brute[i].second);
}

/// n agents, agent i at place(i).
template <typename Place>
std::vector<AgentState> Crowd(int n, Place place) {
  std::vector<AgentState> agents(n);
  for (int i = 0; i < n; ++i) agents[i].position = place(i);
  return agents;
}

TEST(AgentIndex, NearestMatchesBruteForce) {
  Rng rng(3);
  for (int trial = 0; trial < 50; ++trial) {
    const int n = 1 + static_cast<int>(rng.Below(80));
    std::vector<AgentState> agents(n);
    for (auto& a : agents) a.position = Vec2(rng.Uniform(-15, 15), rng.Uniform(-15, 15));
    AgentIndex index;
    index.Rebuild(agents);
    for (int q = 0; q < 10; ++q) {
      const Vec2 p(rng.Uniform(-16, 16), rng.Uniform(-16, 16));
      const double range = rng.Uniform(0.5, 12);
      const int k = 1 + static_cast<int>(rng.Below(12));
      const int exclude = static_cast<int>(rng.Below(n));
      ExpectBruteForceAnswer(agents, index, p, range, k, exclude);
    }
  }
}

// Large crowds, queries inside and outside the grid, and many exact distance ties (agents on
// a lattice): the ring search with its early stop returns exactly the brute-force answer.
TEST(AgentIndex, NearestMatchesBruteForceInLargeCrowdsWithTies) {
  Rng rng(11);
  for (int trial = 0; trial < 12; ++trial) {
    const int n = 200 + static_cast<int>(rng.Below(800));
    const auto agents = Crowd(n, [&](int i) {
      return trial % 2 == 0 ? Vec2(rng.Uniform(0, 60), rng.Uniform(0, 60))
                            : Vec2(static_cast<double>(i % 30), static_cast<double>(i / 30));
    });
    AgentIndex index;
    index.Rebuild(agents);
    for (int q = 0; q < 40; ++q) {
      const Vec2 p = q % 4 == 0 ? Vec2(rng.Uniform(-20, 80), rng.Uniform(-20, 80))
                                : agents[rng.Below(n)].position;
      const double range = rng.Uniform(0.5, 25);
      const int k = 1 + static_cast<int>(rng.Below(20));
      const int exclude = static_cast<int>(rng.Below(n));
      SCOPED_TRACE("trial " + std::to_string(trial) + " query " + std::to_string(q));
      ExpectBruteForceAnswer(agents, index, p, range, k, exclude);
    }
  }
}

// Dense clusters in a large, otherwise sparse world (Circle's and Blocks' crowds: cells much
// larger than the agents' spacing, the k best found in the first ring near a cluster and not
// at all between clusters): still the brute-force answer.
TEST(AgentIndex, NearestMatchesBruteForceInClustersAndSparseSpace) {
  Rng rng(29);
  for (int trial = 0; trial < 6; ++trial) {
    const int clusters = 1 + static_cast<int>(rng.Below(5));
    const int per_cluster = 20 + static_cast<int>(rng.Below(150));
    std::vector<Vec2> centres;
    for (int c = 0; c < clusters; ++c)
      centres.emplace_back(rng.Uniform(0, 200), rng.Uniform(0, 200));
    const int scattered = 30;
    const int n = clusters * per_cluster + scattered;
    const auto agents = Crowd(n, [&](int i) {
      if (i >= clusters * per_cluster) return Vec2(rng.Uniform(0, 200), rng.Uniform(0, 200));
      const double spread = trial % 2 == 0 ? 3.0 : 8.0;
      return Vec2(centres[i % clusters] +
                  Vec2(rng.Uniform(-spread, spread), rng.Uniform(-spread, spread)));
    });
    AgentIndex index;
    index.Rebuild(agents);
    for (int q = 0; q < 60; ++q) {
      const int who = static_cast<int>(rng.Below(n));
      const Vec2 p =
          q % 5 == 0 ? Vec2(rng.Uniform(-10, 210), rng.Uniform(-10, 210)) : agents[who].position;
      const double range = rng.Uniform(1, 30);
      const int k = 1 + static_cast<int>(rng.Below(20));
      SCOPED_TRACE("trial " + std::to_string(trial) + " query " + std::to_string(q));
      ExpectBruteForceAnswer(agents, index, p, range, k, q % 5 == 0 ? -1 : who);
    }
  }
}

// More neighbours than the query keeps on the stack (32), agents sharing a position, and
// agents and queries exactly on cell sides (a 2 m lattice: the grid's cells are 2 m).
TEST(AgentIndex, NearestMatchesBruteForceForManyNeighboursAndSharedPositions) {
  Rng rng(19);
  for (int trial = 0; trial < 8; ++trial) {
    const int n = 100 + static_cast<int>(rng.Below(400));
    const auto agents = Crowd(n, [&](int i) {
      return trial % 2 == 0 ? Vec2(2.0 * (i % 12), 2.0 * ((i / 12) % 12))
                            : Vec2(std::floor(rng.Uniform(0, 8)), rng.Uniform(0, 40));
    });
    AgentIndex index;
    index.Rebuild(agents);
    for (int q = 0; q < 30; ++q) {
      const Vec2 p = q % 3 == 0 ? Vec2(2.0 * static_cast<double>(rng.Below(14)) - 2.0,
                                       1.0 + 2.0 * static_cast<double>(rng.Below(12)))
                                : agents[rng.Below(n)].position;
      const double range =
          q % 5 == 0 ? 2.0 * static_cast<double>(1 + rng.Below(6)) : rng.Uniform(0.5, 30);
      const int k = 1 + static_cast<int>(rng.Below(100));
      const int exclude = q % 7 == 0 ? -1 : static_cast<int>(rng.Below(n));
      SCOPED_TRACE("trial " + std::to_string(trial) + " query " + std::to_string(q));
      ExpectBruteForceAnswer(agents, index, p, range, k, exclude);
    }
  }
}

// Small crowds (up to 16 agents: every agent is offered instead of walking the grid), on a
// lattice so that distances tie: still the brute-force answer, ties by index.
TEST(AgentIndex, NearestMatchesBruteForceInSmallCrowdsWithTies) {
  Rng rng(23);
  for (int n = 1; n <= 17; ++n) {
    const auto agents = Crowd(n, [](int i) { return Vec2(i % 3, i / 3); });
    AgentIndex index;
    index.Rebuild(agents);
    for (int q = 0; q < 30; ++q) {
      const Vec2 p = q % 2 == 0 ? agents[rng.Below(n)].position
                                : Vec2(0.5 * static_cast<double>(rng.Below(8)) - 1.0,
                                       0.5 * static_cast<double>(rng.Below(14)) - 1.0);
      const double range = q % 3 == 0 ? 1.0 : rng.Uniform(0.5, 6);
      const int k = 1 + static_cast<int>(rng.Below(10));
      const int exclude = q % 4 == 0 ? -1 : static_cast<int>(rng.Below(n));
      SCOPED_TRACE("n " + std::to_string(n) + " query " + std::to_string(q));
      ExpectBruteForceAnswer(agents, index, p, range, k, exclude);
    }
  }
}

// A crowd that moves from step to step, each agent querying from where it stands (its own
// index excluded), as ORCA's humans do: a query starts from the disc its last query found,
// which the motion makes too small (agents jump away), too large (they crowd in) or right.
// Every answer is still the brute-force one, also when the agents swap places in the array
// (a hint then belongs to another agent) and when the crowd changes size.
TEST(AgentIndex, QueriesOfAMovingCrowdMatchBruteForce) {
  Rng rng(31);
  AgentIndex index;
  std::vector<AgentState> agents;
  for (int step = 0; step < 120; ++step) {
    if (step % 40 == 0) {
      agents.assign(60 + 70 * (step / 40), AgentState{});
      for (auto& a : agents) a.position = Vec2(rng.Uniform(0, 40), rng.Uniform(0, 40));
    }
    const int n = static_cast<int>(agents.size());
    for (auto& a : agents) {
      const double jump = rng.Below(50) == 0 ? 15.0 : 0.4;  // now and then far away
      a.position += Vec2(rng.Uniform(-jump, jump), rng.Uniform(-jump, jump));
    }
    if (step % 10 == 5) {  // everybody gathers in a corner: discs too large
      for (auto& a : agents) a.position = 0.2 * a.position;
    }
    if (step % 10 == 7) std::swap(agents[0], agents[n - 1]);
    index.Rebuild(agents);
    const double range = step % 3 == 0 ? 4.0 : 12.0;  // often fewer than k in range
    const int k = 1 + static_cast<int>(rng.Below(15));
    for (int i = 0; i < n; ++i) {
      SCOPED_TRACE("step " + std::to_string(step) + " agent " + std::to_string(i));
      ExpectBruteForceAnswer(agents, index, agents[i].position, range, k, i);
    }
  }
}

TEST(AgentIndex, EmptyAndSingle) {
  AgentIndex index;
  std::vector<AgentState> none;
  index.Rebuild(none);
  std::vector<int> out{1, 2};
  index.Nearest(Vec2(0, 0), 10, 5, -1, &out);
  EXPECT_TRUE(out.empty());
  std::vector<AgentState> one(1);
  index.Rebuild(one);
  index.Nearest(Vec2(0, 0), 10, 5, 0, &out);
  EXPECT_TRUE(out.empty());
  index.Nearest(Vec2(0, 0), 10, 5, -1, &out);
  EXPECT_EQ(out, std::vector<int>{0});
}

}  // namespace
}  // namespace crowdsim
