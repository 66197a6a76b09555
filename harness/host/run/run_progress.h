// A suite run's progress line on stderr: rewritten in place on a terminal, else every 10%.
#pragma once

#include <chrono>
#include <string>

namespace crowdsim {

class Progress {
 public:
  /// `total` episodes of which `already` are done (resumed); nothing is printed unless enabled.
  Progress(std::string name, int total, int already, bool enabled);
  /// One more episode finished.
  void Episode(bool success);
  /// Ends the line on a terminal.
  void Finish();

 private:
  using Clock = std::chrono::steady_clock;
  void Print(Clock::time_point now);

  std::string name_;
  int total_, done_, run_ = 0, success_ = 0;
  bool enabled_, tty_;
  Clock::time_point start_, last_{};
  int last_decile_ = -1;
};

}  // namespace crowdsim
