// The trainer's progress line on stderr: in place on a terminal, else every few seconds.
#pragma once

#include <chrono>
#include <deque>
#include <string>

#include "crowdsim/bench/episode.h"

namespace crowdsim::training {

class TrainingProgress {
 public:
  TrainingProgress(std::string name, bool enabled);

  /// Starts a phase of `total` episodes of which `done` are finished already.
  void Phase(const std::string& phase, int done, int total);
  /// One finished episode with its outcome, the epsilon used and the mean loss after it.
  void Episode(EpisodeStatus status, double epsilon, double loss);
  /// Prints a free message on its own line.
  void Note(const std::string& message);
  /// Ends the in-place line.
  void Finish();

 private:
  using Clock = std::chrono::steady_clock;
  void Print();

  std::string name_;
  bool enabled_;
  bool tty_;
  std::string phase_;
  int done_ = 0, total_ = 0, run_ = 0;
  double epsilon_ = 0, loss_ = 0;
  std::deque<EpisodeStatus> recent_;
  Clock::time_point start_, last_;
  bool line_open_ = false;
};

}  // namespace crowdsim::training
