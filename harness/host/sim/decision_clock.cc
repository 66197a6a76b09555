#include "sim/decision_clock.h"

#include <atomic>
#include <chrono>
#include <fstream>
#include <string>

#if defined(__x86_64__)
#include <x86intrin.h>
#endif

namespace crowdsim {
namespace {

using Steady = std::chrono::steady_clock;

std::int64_t SteadyNanoseconds() {
  return std::chrono::duration_cast<std::chrono::nanoseconds>(Steady::now().time_since_epoch())
      .count();
}

/// Whether the TSC can replace steady_clock: x86-64 and the kernel's clocksource is "tsc".
bool CounterUsable() {
#if defined(__x86_64__)
  std::ifstream in("/sys/devices/system/clocksource/clocksource0/current_clocksource");
  std::string source;
  return static_cast<bool>(in >> source) && source == "tsc";
#else
  return false;
#endif
}

std::uint64_t RawNow(bool counter) {
#if defined(__x86_64__)
  if (counter) return __rdtsc();
#endif
  return static_cast<std::uint64_t>(SteadyNanoseconds());
}

/// Both clocks at one instant: the counter between two steady_clock reads, tightest of a few tries,
/// steady_clock at the middle.
struct Pair {
  std::uint64_t ticks = 0;
  std::int64_t nanoseconds = 0;
  std::int64_t spread = 0;  // ns between the two steady_clock reads around the counter
};
Pair ReadBoth(bool counter) {
  SteadyNanoseconds();  // warm: the first read of a process pays for the vDSO's set-up
  Pair best;
  best.spread = -1;
  for (int k = 0; k < 5; ++k) {
    const std::int64_t before = SteadyNanoseconds();
    const std::uint64_t ticks = RawNow(counter);
    const std::int64_t after = SteadyNanoseconds();
    if (best.spread < 0 || after - before < best.spread) {
      best = {ticks, before + (after - before) / 2, after - before};
    }
  }
  return best;
}

/// The rate's anchor, taken at library load so forked workers inherit a long span (short spans
/// magnify read errors).
struct Anchor {
  bool counter = CounterUsable();
  Pair at = ReadBoth(counter);
};

const Anchor& TheAnchor() {
  static const Anchor anchor;
  return anchor;
}
[[maybe_unused]] const Anchor& g_anchor_at_load = TheAnchor();

std::atomic<double> g_frozen_ticks_per_ns{0.0};  // 0 until measured over a second

}  // namespace

std::uint64_t DecisionClock::Now() {
  static const bool counter = TheAnchor().counter;
  return RawNow(counter);
}

double DecisionClock::Microseconds(std::uint64_t ticks) {
  const Anchor& anchor = TheAnchor();
  if (!anchor.counter) return static_cast<double>(ticks) * 1e-3;
  double rate = g_frozen_ticks_per_ns.load(std::memory_order_relaxed);
  if (rate <= 0.0) {
    const Pair now = ReadBoth(true);
    const std::int64_t span = now.nanoseconds - anchor.at.nanoseconds;
    if (span <= 0 || now.ticks <= anchor.at.ticks) return 0.0;  // no time has passed yet
    rate = static_cast<double>(now.ticks - anchor.at.ticks) / static_cast<double>(span);
    // Kept for good once the two pairs' uncertainty is below 1e-6 of the span between them.
    if (span >= 1'000'000'000 && (now.spread + anchor.at.spread) * 1'000'000 < span) {
      g_frozen_ticks_per_ns.store(rate, std::memory_order_relaxed);
    }
  }
  return static_cast<double>(ticks) / rate * 1e-3;
}

}  // namespace crowdsim
