#include "train/training_progress.h"

#include <unistd.h>

#include <cstdio>

namespace crowdsim::training {

namespace {

constexpr std::size_t kWindow = 100;  // episodes in the "recent" rates

std::string Duration(double s) {
  char buf[32];
  const long t = static_cast<long>(s + 0.5);
  if (t >= 3600) {
    std::snprintf(buf, sizeof(buf), "%ldh%02ldm", t / 3600, (t % 3600) / 60);
  } else {
    std::snprintf(buf, sizeof(buf), "%ldm%02lds", t / 60, t % 60);
  }
  return buf;
}

}  // namespace

TrainingProgress::TrainingProgress(std::string name, bool enabled)
    : name_(std::move(name)), enabled_(enabled), tty_(isatty(STDERR_FILENO)) {}

void TrainingProgress::Phase(const std::string& phase, int done, int total) {
  Finish();
  phase_ = phase;
  done_ = done;
  total_ = total;
  run_ = 0;
  recent_.clear();
  start_ = last_ = Clock::now();
}

void TrainingProgress::Episode(EpisodeStatus status, double epsilon, double loss) {
  ++done_;
  ++run_;
  epsilon_ = epsilon;
  loss_ = loss;
  recent_.push_back(status);
  if (recent_.size() > kWindow) recent_.pop_front();
  if (!enabled_) return;
  const auto now = Clock::now();
  const auto every = tty_ ? std::chrono::milliseconds(250) : std::chrono::milliseconds(10000);
  if (now - last_ >= every || done_ == total_) {
    last_ = now;
    Print();
  }
}

void TrainingProgress::Print() {
  int success = 0, collision = 0, timeout = 0;
  for (EpisodeStatus s : recent_) {
    if (s == EpisodeStatus::kSuccess)
      ++success;
    else if (s == EpisodeStatus::kCollisionHuman || s == EpisodeStatus::kCollisionObstacle)
      ++collision;
    else if (s == EpisodeStatus::kTimeout)
      ++timeout;
  }
  const double n = recent_.empty() ? 1.0 : static_cast<double>(recent_.size());
  const double secs = std::chrono::duration<double>(Clock::now() - start_).count();
  const double rate = secs > 0 ? run_ / secs : 0.0;
  const double eta = rate > 0 ? (total_ - done_) / rate : 0.0;
  std::fprintf(stderr,
               "%s[%s] %s %d/%d  eps %.3f  last %zu: success %.2f collision %.2f timeout %.2f"
               "  loss %.5f  %.2f ep/s  ETA %s%s",
               tty_ ? "\r" : "", name_.c_str(), phase_.c_str(), done_, total_, epsilon_,
               recent_.size(), success / n, collision / n, timeout / n, loss_, rate,
               Duration(eta).c_str(), tty_ ? "  " : "\n");
  std::fflush(stderr);
  line_open_ = tty_;
}

void TrainingProgress::Note(const std::string& message) {
  if (!enabled_ && !message.starts_with("warning: ")) return;  // warnings even when quiet
  Finish();
  std::fprintf(stderr, "[%s] %s\n", name_.c_str(), message.c_str());
  std::fflush(stderr);
}

void TrainingProgress::Finish() {
  if (line_open_) std::fprintf(stderr, "\n");
  line_open_ = false;
}

}  // namespace crowdsim::training
