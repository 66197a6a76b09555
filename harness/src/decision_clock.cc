#include "decision_clock.h"

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

/// The first reading of the process, both clocks at once: what the counter's rate is measured
/// from.
struct Anchor {
  bool counter = CounterUsable();
  std::uint64_t ticks = RawNow(counter);
  std::int64_t nanoseconds = SteadyNanoseconds();
};

const Anchor& TheAnchor() {
  static const Anchor anchor;
  return anchor;
}

std::atomic<double> g_frozen_ticks_per_ns{0.0};  // 0 until a second has passed

}  // namespace

std::uint64_t DecisionClock::Now() {
  static const bool counter = TheAnchor().counter;  // the anchor is taken at the first reading
  return RawNow(counter);
}

double DecisionClock::Microseconds(std::uint64_t ticks) {
  const Anchor& anchor = TheAnchor();
  if (!anchor.counter) return static_cast<double>(ticks) * 1e-3;
  double rate = g_frozen_ticks_per_ns.load(std::memory_order_relaxed);
  if (rate <= 0.0) {
    const std::uint64_t now_ticks = Now();
    const std::int64_t span = SteadyNanoseconds() - anchor.nanoseconds;
    if (span <= 0 || now_ticks <= anchor.ticks) return 0.0;  // no time has passed yet
    rate = static_cast<double>(now_ticks - anchor.ticks) / static_cast<double>(span);
    if (span >= 1'000'000'000) g_frozen_ticks_per_ns.store(rate, std::memory_order_relaxed);
  }
  return static_cast<double>(ticks) / rate * 1e-3;
}

}  // namespace crowdsim
