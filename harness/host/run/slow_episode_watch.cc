#include "run/slow_episode_watch.h"

#include <algorithm>
#include <cstdio>
#include <system_error>

namespace crowdsim {

SlowEpisodeWatch::SlowEpisodeWatch(int workers, double note_s)
    : note_s_(note_s), slots_(static_cast<size_t>(std::max(workers, 1))) {
  if (note_s_ <= 0) return;
  try {
    thread_ = std::thread([this] { Watch(); });
  } catch (const std::system_error&) {
    // No thread to spare: the run goes on unwatched.
  }
}

SlowEpisodeWatch::~SlowEpisodeWatch() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stop_ = true;
  }
  wake_.notify_all();
  if (thread_.joinable()) thread_.join();
}

void SlowEpisodeWatch::Began(int worker, std::string where) {
  std::lock_guard<std::mutex> lock(mutex_);
  Slot& s = slots_[static_cast<size_t>(worker)];
  s = {std::move(where), std::chrono::steady_clock::now(), note_s_, true};
}

void SlowEpisodeWatch::Ended(int worker) {
  std::lock_guard<std::mutex> lock(mutex_);
  slots_[static_cast<size_t>(worker)].busy = false;
}

void SlowEpisodeWatch::Watch() {
  const auto period = std::chrono::duration<double>(std::clamp(note_s_ / 4, 0.05, 1.0));
  std::unique_lock<std::mutex> lock(mutex_);
  while (!wake_.wait_for(lock, period, [this] { return stop_; })) {
    const auto now = std::chrono::steady_clock::now();
    for (Slot& s : slots_) {
      const double ran = std::chrono::duration<double>(now - s.start).count();
      if (!s.busy || ran < s.next_note_s) continue;
      std::fprintf(stderr,
                   "\nnote: %s has run %.0f s; a plugin that never returns holds a threaded run "
                   "(give the suite episode_timeout_s: each episode then runs in a worker "
                   "process, killed past it)\n",
                   s.where.c_str(), ran);
      s.next_note_s *= 2;
    }
  }
}

}  // namespace crowdsim
