// Crash isolation: suite tasks run in forked workers, so a crashing, exiting or hanging plugin
// loses one worker, not the run. The single-threaded parent hands out tasks over pipes, detects
// deaths and timeouts, and replaces workers.
#pragma once

#include <cstddef>
#include <functional>
#include <optional>
#include <string>

namespace crowdsim {

/// Why a task produced no result.
struct WorkerLoss {
  enum class Kind { kSignal, kExit, kTimeout };
  Kind kind = Kind::kSignal;
  int signal = 0;       ///< kSignal: the signal that ended the worker
  int exit_status = 0;  ///< kExit: the worker's exit status
  double seconds = 0;   ///< kTimeout: the limit it ran past

  /// "killed by signal SIGSEGV (Segmentation fault)", "exited with status 3", "killed at the
  /// episode_timeout_s of 2 s".
  std::string Describe() const;
  /// Stopped from outside the run (SIGINT, SIGTERM, SIGHUP): the task is not at fault.
  bool Interrupted() const;
};

struct WorkerPoolOptions {
  int workers = 1;            ///< processes running at a time
  double task_timeout_s = 0;  ///< wall-clock limit per task, from its hand-out; 0 = none
};

/// The parent's handler of task outcomes; returning false kills every worker and ends the pool.
struct WorkerPoolCallbacks {
  /// In a worker: runs task `t` and returns its result bytes. Runs in the forked child only.
  std::function<std::string(std::size_t t)> run;
  /// In the parent: task `t` finished with these bytes.
  std::function<bool(std::size_t t, std::string bytes)> done;
  /// In the parent: task `t`'s worker died or ran past the limit.
  std::function<bool(std::size_t t, const WorkerLoss& loss)> lost;
};

/// Runs `task` once in a forked worker within `timeout_s` (0 = none): its bytes, or why none came.
struct OnceInWorker {
  std::string bytes;
  std::optional<WorkerLoss> loss;
};
OnceInWorker RunOnceInWorker(double timeout_s, const std::function<std::string()>& task);

/// Runs tasks 0..count-1 in workers, each once (no retries). Throws std::runtime_error if a process
/// or pipe fails. Hold no locks the child needs.
void RunInWorkerProcesses(std::size_t count, const WorkerPoolOptions& options,
                          const WorkerPoolCallbacks& callbacks);

}  // namespace crowdsim
