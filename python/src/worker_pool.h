// Persistent threads that run one function over contiguous shares of [0, n) (VectorEnv's
// steps): the calling thread takes the first share, Run returns when all shares are done and
// rethrows the first exception a share threw.
#pragma once

#include <condition_variable>
#include <cstdint>
#include <exception>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace crowdsim::python {

class WorkerPool {
 public:
  using Share = std::function<void(size_t begin, size_t end)>;

  /// `threads` in all, the caller's included (1: Run calls fn on the caller's thread only).
  explicit WorkerPool(int threads);
  ~WorkerPool();
  WorkerPool(const WorkerPool&) = delete;
  WorkerPool& operator=(const WorkerPool&) = delete;

  int threads() const { return static_cast<int>(workers_.size()) + 1; }
  void Run(size_t n, const Share& fn);

 private:
  static std::pair<size_t, size_t> ShareOf(size_t n, int parts, int part);
  void Loop(int part);

  std::vector<std::thread> workers_;
  std::mutex mu_;
  std::condition_variable start_;
  std::condition_variable done_;
  const Share* job_ = nullptr;
  size_t n_ = 0;
  std::uint64_t generation_ = 0;
  int pending_ = 0;
  bool stop_ = false;
  std::exception_ptr error_;
};

}  // namespace crowdsim::python
