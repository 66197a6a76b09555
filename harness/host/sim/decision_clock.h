// The clock that times each robot decision (episodes.csv's decision_time_us). Read twice a
// step, so its cost is part of every episode: steady_clock costs ~24 ns a read on this
// project's machines (about 4% of a CrowdNav episode), the CPU's time-stamp counter ~10 ns.
// The counter is used where the kernel itself keeps time with it (its clocksource is "tsc":
// constant rate, synchronised across cores), steady_clock everywhere else.
#pragma once

#include <cstdint>

namespace crowdsim {

class DecisionClock {
 public:
  /// A tick count; only differences of two readings mean something.
  static std::uint64_t Now();
  /// `ticks` (a difference of Now() readings) in microseconds. With the time-stamp counter,
  /// its rate is measured against steady_clock from the moment the core library was loaded
  /// (each end read between two steady_clock reads, the tightest of five), and kept once
  /// measured over a second; until then a conversion costs a few clock reads.
  static double Microseconds(std::uint64_t ticks);
};

}  // namespace crowdsim
