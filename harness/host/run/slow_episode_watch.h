// Names on stderr an episode that runs long in a threaded run, where nothing can stop it.
#pragma once

#include <chrono>
#include <condition_variable>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

namespace crowdsim {

class SlowEpisodeWatch {
 public:
  /// Watches `workers` worker slots; an episode is named at `note_s` seconds and at each
  /// doubling. No watching when note_s <= 0 or the system refuses the watcher's thread.
  SlowEpisodeWatch(int workers, double note_s);
  ~SlowEpisodeWatch();

  /// Worker `worker` starts the episode `where` names ("row 'orca', episode 3").
  void Began(int worker, std::string where);
  /// Worker `worker` has finished its episode.
  void Ended(int worker);

 private:
  struct Slot {
    std::string where;
    std::chrono::steady_clock::time_point start;
    double next_note_s = 0;
    bool busy = false;
  };
  void Watch();

  std::mutex mutex_;
  std::condition_variable wake_;
  bool stop_ = false;
  double note_s_;
  std::vector<Slot> slots_;
  std::thread thread_;
};

}  // namespace crowdsim
