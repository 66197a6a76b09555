// The clock of the robot's decision times (harness/host/sim/decision_clock.h): the time-stamp
// counter where the kernel keeps time with it, converted at the rate it keeps against
// steady_clock. A span it measures must be the span steady_clock measures: long and short
// spans, in a forked worker (whose first episodes read up to 15% low when the rate was
// measured from the worker's own first, slow clock read), and once the rate is kept.
#include "sim/decision_clock.h"

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <thread>

namespace crowdsim {
namespace {

using Steady = std::chrono::steady_clock;

/// DecisionClock's measure of a span over steady_clock's (1 when they agree); the span is
/// slept when long, spun when short. Each DecisionClock read is bracketed by two steady_clock
/// reads, so that a preemption beside a read (a loaded machine) widens steady_clock's bounds
/// on the span instead of reading as a rate error; the ratio is to the nearer bound, 1 inside.
double Ratio(std::chrono::microseconds span) {
  const auto a0 = Steady::now();
  const std::uint64_t t0 = DecisionClock::Now();
  const auto b0 = Steady::now();
  if (span >= std::chrono::milliseconds(1)) {
    std::this_thread::sleep_for(span);
  } else {
    while (Steady::now() - a0 < span) {
    }
  }
  const auto a1 = Steady::now();
  const std::uint64_t t1 = DecisionClock::Now();
  const auto b1 = Steady::now();
  const auto us = [](Steady::duration d) {
    return std::chrono::duration<double, std::micro>(d).count();
  };
  const double measured = DecisionClock::Microseconds(t1 - t0);
  const double shortest = us(a1 - b0), longest = us(b1 - a0);
  if (measured < shortest) return measured / shortest;
  if (measured > longest) return measured / longest;
  return 1.0;
}

TEST(DecisionClock, MeasuresWhatSteadyClockMeasures) {
  for (int round = 0; round < 3; ++round) {
    EXPECT_NEAR(Ratio(std::chrono::milliseconds(20)), 1.0, 0.02) << "round " << round;
  }
  EXPECT_EQ(DecisionClock::Microseconds(0), 0.0);
}

TEST(DecisionClock, ShortSpansInAForkedWorkerFromItsFirstReading) {
  // As an isolated run's worker: forked before it ever read the clock, then timing decisions
  // of tens of microseconds. Each span's two clock reads add their own ~10-50 ns.
  const pid_t child = fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    // The first calls after a fork fault their pages in (~10 us): done before the span, so
    // that neither read lands late against the other (a decision's own reads are both after
    // such a first call). What is measured is then the conversion, from the inherited anchor.
    Steady::now();
    DecisionClock::Now();
    for (int k = 0; k < 5; ++k) {
      if (std::abs(Ratio(std::chrono::microseconds(40)) - 1.0) > 0.03) _exit(1);
    }
    _exit(0);
  }
  int status = 0;
  ASSERT_EQ(waitpid(child, &status, 0), child);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 0) << "a 40 us span read off by more than 3% in the child";
}

TEST(DecisionClock, KeepsItsRateOnceMeasuredOverASecond) {
  std::this_thread::sleep_for(std::chrono::milliseconds(1100));
  for (int round = 0; round < 3; ++round) {
    EXPECT_NEAR(Ratio(std::chrono::milliseconds(5)), 1.0, 0.02) << "round " << round;
    EXPECT_NEAR(Ratio(std::chrono::microseconds(40)), 1.0, 0.03) << "round " << round;
  }
}

}  // namespace
}  // namespace crowdsim
