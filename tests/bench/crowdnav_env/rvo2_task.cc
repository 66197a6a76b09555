// RVO2's C++ alone on the CrowdNav task's crowd, for scale beside compare.sh's two envs: six
// agents (CrowdNav's five humans and its ORCA robot) on a circle of radius 4 m bound for the
// antipode, radius 0.3 m + CrowdNav's 0.01 m padding, 1 m/s, time step 0.25 s, neighbours
// within 10 m (10 at most), horizons 5 s; episodes of 30 steps (CrowdNav's episodes take 30.4)
// from random starts. No sensing, collision test, rewards or bookkeeping: the ORCA solve that
// both envs also do. Prints CPU time per step.
//
//   g++ -O2 -DNDEBUG -std=c++17 rvo2_task.cc RVO2/src/*.cc -IRVO2/src && ./a.out [EPISODES]
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <random>
#include <vector>

#include "RVO.h"

namespace {

double CpuSeconds() {
  timespec t;
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

}  // namespace

int main(int argc, char** argv) {
  const int episodes = argc > 1 ? std::atoi(argv[1]) : 20000;
  constexpr int kAgents = 6;
  constexpr int kSteps = 30;
  std::mt19937 rng(1);
  std::uniform_real_distribution<float> angle(0.0F, 6.28318530718F);
  double cpu = 0.0;
  for (int e = 0; e < episodes; ++e) {
    RVO::RVOSimulator sim;
    sim.setTimeStep(0.25F);
    sim.setAgentDefaults(10.0F, 10, 5.0F, 5.0F, 0.31F, 1.0F);
    std::vector<RVO::Vector2> goals;
    for (int i = 0; i < kAgents; ++i) {
      const float a = angle(rng);
      const RVO::Vector2 start(4.0F * std::cos(a), 4.0F * std::sin(a));
      sim.addAgent(start);
      goals.push_back(-start);
    }
    const double t0 = CpuSeconds();
    for (int s = 0; s < kSteps; ++s) {
      for (int i = 0; i < kAgents; ++i) {
        RVO::Vector2 to_goal = goals[i] - sim.getAgentPosition(i);
        if (RVO::absSq(to_goal) > 1.0F) to_goal = RVO::normalize(to_goal);
        sim.setAgentPrefVelocity(i, to_goal);
      }
      sim.doStep();
    }
    cpu += CpuSeconds() - t0;
  }
  std::printf("RVO2 C++ alone, %d agents: %.3f us per step (%d episodes of %d steps)\n", kAgents,
              1e6 * cpu / (static_cast<double>(episodes) * kSteps), episodes, kSteps);
}
