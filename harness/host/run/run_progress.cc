#include "run/run_progress.h"

#include <unistd.h>

#include <cstdio>

namespace crowdsim {

Progress::Progress(std::string name, int total, int already, bool enabled)
    : name_(std::move(name)),
      total_(total),
      done_(already),
      enabled_(enabled),
      tty_(isatty(STDERR_FILENO)),
      start_(Clock::now()) {
  // Said first, so the progress line's counts (which include them) and success rate (this run's)
  // read right.
  if (enabled_ && already > 0) {
    std::fprintf(stderr, "[%s] %d of %d episodes resumed from the stored results; running %d\n",
                 name_.c_str(), already, total_, total_ - already);
  }
}

void Progress::Episode(bool success) {
  ++done_;
  ++run_;
  if (success) ++success_;
  if (!enabled_) return;
  const auto now = Clock::now();
  const int decile = total_ > 0 ? done_ * 10 / total_ : 10;
  if (tty_ ? (now - last_ > std::chrono::milliseconds(200) || done_ == total_)
           : (decile != last_decile_)) {
    last_ = now;
    last_decile_ = decile;
    Print(now);
  }
}

void Progress::Finish() {
  if (enabled_ && tty_) std::fprintf(stderr, "\n");
}

void Progress::Print(Clock::time_point now) {
  const double secs = std::chrono::duration<double>(now - start_).count();
  const double rate = secs > 0 ? run_ / secs : 0.0;
  const double eta = rate > 0 ? (total_ - done_) / rate : 0.0;
  std::fprintf(stderr, "%s[%s] %d/%d episodes  %.1f ep/s  ETA %.0fs  success of those run %.3f%s",
               tty_ ? "\r" : "", name_.c_str(), done_, total_, rate, eta,
               run_ > 0 ? static_cast<double>(success_) / run_ : 0.0, tty_ ? "   " : "\n");
  std::fflush(stderr);
}

}  // namespace crowdsim
