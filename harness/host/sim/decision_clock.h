// The clock timing robot decisions, read twice a step: the cheap TSC where the kernel's clocksource
// is "tsc", else steady_clock.
#pragma once

#include <cstdint>

namespace crowdsim {

class DecisionClock {
 public:
  /// A tick count; only differences of two readings mean something.
  static std::uint64_t Now();
  /// `ticks` (a difference of Now() readings) in microseconds; the TSC rate is calibrated against
  /// steady_clock over a second, conversions costing a few reads until then.
  static double Microseconds(std::uint64_t ticks);
};

}  // namespace crowdsim
