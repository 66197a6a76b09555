// Appends episodes.csv lines in few writes. With a delay a background thread writes within
// `max_delay`: a crash loses at most that, Ctrl-C nothing (FlushForSignal).
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
  /// Finish() unless already called (its errors are then ignored).
  ~EpisodeAppender();
  EpisodeAppender(const EpisodeAppender&) = delete;
  EpisodeAppender& operator=(const EpisodeAppender&) = delete;

  /// Adds `line` and a newline; thread-safe. False once a write failed, *why naming file and cause.
  bool Append(std::string_view line, std::string* why);
  /// Writes pending lines, stops the thread, closes the file; false (and *why) if a write failed.
  bool Finish(std::string* why);

  /// Writes the open appender's pending lines with write(2) only, for a signal handler about to
  /// exit.
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
