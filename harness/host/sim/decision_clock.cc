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

/// Whether the time-stamp counter can stand in for steady_clock: x86-64, and the kernel keeps
/// time with it (it checked the counter's rate and synchronisation at boot).
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

/// Both clocks at one instant: the counter read between two steady_clock reads, the tightest
/// of a few tries (a first steady_clock read of a process or of a forked child is slow, and a
/// preemption can fall between two reads), steady_clock taken at the middle.
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

/// What the counter's rate is measured from: taken when the core library is loaded, so that a
/// forked worker inherits its parent's (a short span since a late anchor magnified the error of
/// its reads: early decision times read up to 15% low in a fresh worker).
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
