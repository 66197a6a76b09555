#include "worker_pool.h"

#include <algorithm>

namespace crowdsim::python {

WorkerPool::WorkerPool(int threads) {
  for (int part = 1; part < std::max(1, threads); ++part)
    workers_.emplace_back([this, part] { Loop(part); });
}

WorkerPool::~WorkerPool() {
  {
    std::lock_guard<std::mutex> lock(mu_);
    stop_ = true;
  }
  start_.notify_all();
  for (std::thread& t : workers_) t.join();
}

std::pair<size_t, size_t> WorkerPool::ShareOf(size_t n, int parts, int part) {
  const size_t p = static_cast<size_t>(parts);
  const size_t k = static_cast<size_t>(part);
  return {n * k / p, n * (k + 1) / p};
}

void WorkerPool::Run(size_t n, const Share& fn) {
  if (workers_.empty()) {
    fn(0, n);
    return;
  }
  {
    std::lock_guard<std::mutex> lock(mu_);
    job_ = &fn;
    n_ = n;
    pending_ = static_cast<int>(workers_.size());
    error_ = nullptr;
    ++generation_;
  }
  start_.notify_all();
  std::exception_ptr mine;
  try {
    const auto [begin, end] = ShareOf(n, threads(), 0);
    fn(begin, end);
  } catch (...) {
    mine = std::current_exception();
  }
  std::unique_lock<std::mutex> lock(mu_);
  done_.wait(lock, [this] { return pending_ == 0; });
  job_ = nullptr;
  if (mine) std::rethrow_exception(mine);
  if (error_) std::rethrow_exception(error_);
}

void WorkerPool::Loop(int part) {
  std::uint64_t seen = 0;
  std::unique_lock<std::mutex> lock(mu_);
  for (;;) {
    start_.wait(lock, [&] { return stop_ || generation_ != seen; });
    if (stop_) return;
    seen = generation_;
    const Share* fn = job_;
    const auto [begin, end] = ShareOf(n_, threads(), part);
    lock.unlock();
    std::exception_ptr error;
    try {
      (*fn)(begin, end);
    } catch (...) {
      error = std::current_exception();
    }
    lock.lock();
    if (error && !error_) error_ = error;
    if (--pending_ == 0) done_.notify_one();
  }
}

}  // namespace crowdsim::python
