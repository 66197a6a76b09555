// The clock of the robot's decision times (harness/src/decision_clock.h): the time-stamp
// counter where the kernel keeps time with it, converted at the rate it keeps against
// steady_clock. A span it measures must be the span steady_clock measures.
#include "decision_clock.h"

#include <gtest/gtest.h>

#include <chrono>
#include <thread>

namespace crowdsim {
namespace {

TEST(DecisionClock, MeasuresWhatSteadyClockMeasures) {
  using Steady = std::chrono::steady_clock;
  for (int round = 0; round < 3; ++round) {
    const auto s0 = Steady::now();
    const std::uint64_t t0 = DecisionClock::Now();
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
    const std::uint64_t t1 = DecisionClock::Now();
    const double steady_us = std::chrono::duration<double, std::micro>(Steady::now() - s0).count();
    ASSERT_GE(t1, t0);
    const double clock_us = DecisionClock::Microseconds(t1 - t0);
    // The two spans differ by the clock reads around them (well under 1%) and by the rate's
    // measurement, taken over the same 20+ ms.
    EXPECT_NEAR(clock_us / steady_us, 1.0, 0.05) << "round " << round;
    EXPECT_GE(clock_us, 19'000.0);
  }
  EXPECT_EQ(DecisionClock::Microseconds(0), 0.0);
}

}  // namespace
}  // namespace crowdsim
