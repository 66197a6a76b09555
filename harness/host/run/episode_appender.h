// Appends lines to episodes.csv with few write calls. With a delay, lines gather in memory and
// a background thread writes them at the latest `max_delay` after they were added, so a crash
// loses at most the episodes that finished in that last fraction of a second (a resume runs
// them again); Ctrl-C loses none (FlushForSignal). Without a delay every line is written at once.
#pragma once

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <filesystem>
#include <memory>
#include <mutex>
#include <string>
#include <string_view>
#include <thread>

namespace crowdsim {

class EpisodeAppender {
 public:
  /// The runner's delay when episodes run in threads (docs/usage.md, "What a run writes").
  static constexpr std::chrono::milliseconds kThreadedRunDelay{200};

  /// Opens `path` for appending (created if missing); throws RunError naming it.
  EpisodeAppender(std::filesystem::path path, std::chrono::milliseconds max_delay);
  /// Finish() if it was not called (its errors are then ignored).
  ~EpisodeAppender();
  EpisodeAppender(const EpisodeAppender&) = delete;
  EpisodeAppender& operator=(const EpisodeAppender&) = delete;

  /// Adds `line` and a newline; thread-safe. False once a write failed: *why names the file
  /// and the OS reason (a full disk, a lost mount).
  bool Append(std::string_view line, std::string* why);
  /// Writes every pending line, stops the background thread and closes the file; false (and
  /// *why) when a write failed.
  bool Finish(std::string* why);

  /// Writes the pending lines of the appender open in this process, if any, with nothing but
  /// write(2): for a signal handler that ends the process right after.
  static void FlushForSignal() noexcept;

 private:
  bool FlushLocked();  // mutex_ held
  void FlushPeriodically();

  std::filesystem::path path_;
  std::chrono::milliseconds max_delay_;
  int fd_ = -1;
  std::unique_ptr<char[]> buffer_;
  std::atomic<size_t> pending_{0};    ///< bytes of whole lines in buffer_
  std::atomic<bool> writing_{false};  ///< a flush or the signal handler owns the file
  std::mutex mutex_;
  std::condition_variable wake_;
  bool stopping_ = false;
  std::string error_;  ///< the first failed write
  std::thread flusher_;
};

}  // namespace crowdsim
