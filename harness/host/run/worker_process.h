// Crash isolation for suite runs: tasks run in forked worker processes, so a plugin that
// segfaults, aborts, exits or hangs takes down one worker, not the run. The parent stays
// single-threaded (it runs no task itself), hands out one task at a time over a pipe, reads each
// result back over another, and notices a worker's death (EOF on its pipe, then waitpid) or a
// task past its wall-clock limit (the parent kills the worker); a new worker takes the tasks
// that remain. What a task is and what its result bytes mean is the caller's (runner.cc).
#pragma once

#include <cstddef>
#include <functional>
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
  /// A signal sent from outside the run (SIGINT, SIGTERM, SIGHUP): the run was stopped, the
  /// task did nothing wrong.
  bool Interrupted() const;
};

struct WorkerPoolOptions {
  int workers = 1;            ///< processes running at a time
  double task_timeout_s = 0;  ///< wall-clock limit per task, from its hand-out; 0 = none
};

/// What the parent does with each task's outcome; returning false stops the pool (every worker
/// is killed and RunInWorkerProcesses returns).
struct WorkerPoolCallbacks {
  /// In a worker: runs task `t` and returns its result bytes. Runs in the forked child only.
  std::function<std::string(std::size_t t)> run;
  /// In the parent: task `t` finished with these bytes.
  std::function<bool(std::size_t t, std::string bytes)> done;
  /// In the parent: task `t`'s worker died or ran past the limit.
  std::function<bool(std::size_t t, const WorkerLoss& loss)> lost;
};

/// Runs tasks 0..count-1 in worker processes, each task handed out once (a lost task is not
/// retried: its outcome is the loss). Throws std::runtime_error when a process or pipe cannot
/// be made. The calling process must not hold locks other threads could need in the child.
void RunInWorkerProcesses(std::size_t count, const WorkerPoolOptions& options,
                          const WorkerPoolCallbacks& callbacks);

}  // namespace crowdsim
