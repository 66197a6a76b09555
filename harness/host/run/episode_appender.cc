#include "run/episode_appender.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <system_error>

#include "atomic_file.h"
#include "crowdsim/bench/runner.h"

namespace crowdsim {

namespace {

constexpr size_t kCapacity = size_t{1} << 16;
/// The appender open in this process (a run has one at a time), for the signal handler.
std::atomic<EpisodeAppender*> g_open{nullptr};

using common::WriteAll;

}  // namespace

EpisodeAppender::EpisodeAppender(std::filesystem::path path, std::chrono::milliseconds max_delay)
    : path_(std::move(path)), max_delay_(max_delay), buffer_(new char[kCapacity]) {
  fd_ = ::open(path_.c_str(), O_WRONLY | O_APPEND | O_CREAT | O_CLOEXEC, 0644);
  if (fd_ < 0) throw RunError("cannot append to " + path_.string() + ": " + std::strerror(errno));
  g_open.store(this);
  if (max_delay_.count() > 0) {
    try {
      flusher_ = std::thread([this] { FlushPeriodically(); });
    } catch (const std::system_error&) {
      max_delay_ = std::chrono::milliseconds(0);  // no thread to spare: each line written at once
    }
  }
}

EpisodeAppender::~EpisodeAppender() {
  std::string ignored;
  Finish(&ignored);
}

bool EpisodeAppender::FlushLocked() {
  const size_t size = pending_.load();
  if (size == 0 || !error_.empty()) return error_.empty();
  // The signal handler holds the file only when the process is about to end: leave it be.
  if (writing_.exchange(true)) return true;
  if (const int err = WriteAll(fd_, buffer_.get(), size); err != 0) {
    error_ = "cannot append to " + path_.string() + ": " + std::strerror(err);
  }
  pending_.store(0);
  writing_.store(false);
  return error_.empty();
}

void EpisodeAppender::FlushPeriodically() {
  std::unique_lock<std::mutex> lock(mutex_);
  while (!stopping_) {
    wake_.wait_for(lock, max_delay_);
    FlushLocked();
  }
}

bool EpisodeAppender::Append(std::string_view line, std::string* why) {
  std::lock_guard<std::mutex> lock(mutex_);
  const size_t size = line.size() + 1;
  if (pending_.load() + size > kCapacity) FlushLocked();
  if (error_.empty() && size > kCapacity) {  // longer than the buffer: out on its own
    const std::string whole = std::string(line) + "\n";
    if (const int err = WriteAll(fd_, whole.data(), whole.size()); err != 0) {
      error_ = "cannot append to " + path_.string() + ": " + std::strerror(err);
    }
  } else if (error_.empty()) {
    const size_t at = pending_.load();
    std::memcpy(buffer_.get() + at, line.data(), line.size());
    buffer_[at + line.size()] = '\n';
    pending_.store(at + size);  // whole before the signal handler can see it
    if (max_delay_.count() == 0) FlushLocked();
  }
  if (!error_.empty()) *why = error_;
  return error_.empty();
}

bool EpisodeAppender::Finish(std::string* why) {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    if (fd_ < 0) {
      *why = error_;
      return error_.empty();
    }
    stopping_ = true;
  }
  wake_.notify_all();
  if (flusher_.joinable()) flusher_.join();
  std::lock_guard<std::mutex> lock(mutex_);
  FlushLocked();
  EpisodeAppender* self = this;
  g_open.compare_exchange_strong(self, nullptr);
  if (::close(fd_) != 0 && error_.empty()) {
    error_ = "cannot append to " + path_.string() + ": " + std::strerror(errno);
  }
  fd_ = -1;
  *why = error_;
  return error_.empty();
}

void EpisodeAppender::FlushForSignal() noexcept {
  EpisodeAppender* open = g_open.load();
  if (open == nullptr || open->writing_.exchange(true)) return;
  WriteAll(open->fd_, open->buffer_.get(), open->pending_.load());
  open->pending_.store(0);
}

}  // namespace crowdsim
