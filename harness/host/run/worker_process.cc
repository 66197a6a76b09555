#include "run/worker_process.h"

#include <poll.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <optional>
#include <stdexcept>
#include <vector>

namespace crowdsim {

std::string WorkerLoss::Describe() const {
  switch (kind) {
    case Kind::kSignal: {
      const char* abbrev = sigabbrev_np(signal);
      const char* text = strsignal(signal);
      return "killed by signal " + (abbrev ? "SIG" + std::string(abbrev) : std::to_string(signal)) +
             (text ? " (" + std::string(text) + ")" : "");
    }
    case Kind::kExit:
      return "exited with status " + std::to_string(exit_status);
    case Kind::kTimeout: {
      char buf[64];
      std::snprintf(buf, sizeof(buf), "%g", seconds);
      return std::string("killed at the episode_timeout_s of ") + buf + " s";
    }
  }
  return "lost";
}

bool WorkerLoss::Interrupted() const {
  return kind == Kind::kSignal && (signal == SIGINT || signal == SIGTERM || signal == SIGHUP);
}

namespace {

using Clock = std::chrono::steady_clock;

/// Moves exactly n bytes via `call` (::read or ::write), retrying on signals; false at EOF (peer
/// died) or error.
template <typename Byte, typename Call>
bool Exactly(Call call, int fd, Byte* p, size_t n) {
  while (n > 0) {
    const ssize_t k = call(fd, p, n);
    if (k < 0 && errno == EINTR) continue;
    if (k <= 0) return false;
    p += k;
    n -= static_cast<size_t>(k);
  }
  return true;
}

bool WriteAll(int fd, const void* data, size_t n) {
  return Exactly(::write, fd, static_cast<const char*>(data), n);
}
bool ReadAll(int fd, void* data, size_t n) {
  return Exactly(::read, fd, static_cast<char*>(data), n);
}

/// A worker's loop: task numbers in, [length][bytes] out, until its pipe closes. An escaping
/// exception terminates; the parent records the loss.
[[noreturn]] void WorkerMain(int tasks_fd, int results_fd,
                             const WorkerPoolCallbacks& callbacks) noexcept {
  for (;;) {
    std::uint64_t t = 0;
    if (!ReadAll(tasks_fd, &t, sizeof t)) _exit(0);
    const std::string bytes = callbacks.run(static_cast<std::size_t>(t));
    const std::uint64_t n = bytes.size();
    if (!WriteAll(results_fd, &n, sizeof n) || !WriteAll(results_fd, bytes.data(), bytes.size()))
      _exit(0);
  }
}

struct Worker {
  pid_t pid = -1;
  int tasks_fd = -1;    ///< the parent writes task numbers
  int results_fd = -1;  ///< the parent reads results
  std::optional<std::size_t> task;
  Clock::time_point deadline;
};

class Pool {
 public:
  Pool(std::size_t count, const WorkerPoolOptions& options, const WorkerPoolCallbacks& callbacks)
      : count_(count), options_(options), callbacks_(callbacks), parent_(getpid()) {}

  ~Pool() {
    for (Worker& w : workers_) End(w, /*kill=*/true);
  }

  void Run() {
    const std::size_t n =
        std::min<std::size_t>(static_cast<std::size_t>(std::max(1, options_.workers)), count_);
    workers_.resize(n);
    for (Worker& w : workers_) Spawn(w);
    for (;;) {
      for (Worker& w : workers_) {
        if (w.pid > 0 && !w.task && next_ < count_) HandOut(w);
      }
      std::vector<pollfd> fds;
      std::vector<Worker*> busy;
      std::optional<Clock::time_point> first_deadline;
      for (Worker& w : workers_) {
        if (!w.task) continue;
        fds.push_back({w.results_fd, POLLIN, 0});
        busy.push_back(&w);
        if (options_.task_timeout_s > 0 && (!first_deadline || w.deadline < *first_deadline))
          first_deadline = w.deadline;
      }
      if (busy.empty()) break;
      int wait_ms = -1;
      if (first_deadline) {
        const auto left =
            std::chrono::ceil<std::chrono::milliseconds>(*first_deadline - Clock::now());
        wait_ms = static_cast<int>(std::max<std::int64_t>(0, left.count()));
      }
      const int ready = ::poll(fds.data(), fds.size(), wait_ms);
      if (ready < 0 && errno != EINTR)
        throw std::runtime_error(std::string("poll failed: ") + std::strerror(errno));
      for (size_t i = 0; i < fds.size(); ++i) {
        if (ready > 0 && fds[i].revents != 0) {
          if (!Collect(*busy[i])) return;
        } else if (first_deadline && Clock::now() >= busy[i]->deadline) {
          if (!TimeOut(*busy[i])) return;
        }
      }
    }
    for (Worker& w : workers_) End(w, /*kill=*/false);
  }

 private:
  void Spawn(Worker& w) {
    int tasks[2], results[2];
    if (::pipe(tasks) != 0)
      throw std::runtime_error(std::string("cannot make a pipe: ") + std::strerror(errno));
    if (::pipe(results) != 0) {
      const int e = errno;
      ::close(tasks[0]);
      ::close(tasks[1]);
      throw std::runtime_error(std::string("cannot make a pipe: ") + std::strerror(e));
    }
    std::fflush(nullptr);  // nothing buffered twice if a plugin calls exit() in the worker
    const pid_t pid = ::fork();
    if (pid < 0) {
      const int e = errno;
      for (int fd : {tasks[0], tasks[1], results[0], results[1]}) ::close(fd);
      throw std::runtime_error(std::string("cannot start a worker process: ") + std::strerror(e));
    }
    if (pid == 0) {
      // The worker: siblings' pipe ends closed (so they see EOF), dies with the parent, ignores
      // Ctrl-C (the parent reports it).
      for (const Worker& other : workers_) {
        if (other.tasks_fd >= 0) ::close(other.tasks_fd);
        if (other.results_fd >= 0) ::close(other.results_fd);
      }
      ::close(tasks[1]);
      ::close(results[0]);
      ::prctl(PR_SET_PDEATHSIG, SIGKILL);
      if (getppid() != parent_) _exit(0);
      std::signal(SIGINT, SIG_IGN);
      std::signal(SIGTERM, SIG_DFL);
      WorkerMain(tasks[0], results[1], callbacks_);
    }
    ::close(tasks[0]);
    ::close(results[1]);
    w = Worker{pid, tasks[1], results[0], std::nullopt, {}};
  }

  void HandOut(Worker& w) {
    const std::uint64_t t = next_;
    if (!WriteAll(w.tasks_fd, &t, sizeof t)) {
      // Died while idle (nothing of ours ran in it): replace it and hand out again.
      End(w, /*kill=*/true);
      Spawn(w);
      if (!WriteAll(w.tasks_fd, &t, sizeof t))
        throw std::runtime_error("a new worker process died at once");
    }
    ++next_;
    w.task = t;
    w.deadline = Clock::now() + std::chrono::duration_cast<Clock::duration>(
                                    std::chrono::duration<double>(options_.task_timeout_s));
  }

  /// The worker's result, or its death; false to stop.
  bool Collect(Worker& w) {
    const std::size_t t = *w.task;
    std::uint64_t n = 0;
    std::string bytes;
    bool ok = ReadAll(w.results_fd, &n, sizeof n);
    if (ok) {
      bytes.resize(n);
      ok = ReadAll(w.results_fd, bytes.data(), n);
    }
    if (ok) {
      w.task.reset();
      return callbacks_.done(t, std::move(bytes));
    }
    WorkerLoss loss;
    const int status = End(w, /*kill=*/false);
    if (WIFSIGNALED(status)) {
      loss.kind = WorkerLoss::Kind::kSignal;
      loss.signal = WTERMSIG(status);
    } else {
      loss.kind = WorkerLoss::Kind::kExit;
      loss.exit_status = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    }
    return Replace(w, t, loss);
  }

  bool TimeOut(Worker& w) {
    const std::size_t t = *w.task;
    End(w, /*kill=*/true);
    WorkerLoss loss;
    loss.kind = WorkerLoss::Kind::kTimeout;
    loss.seconds = options_.task_timeout_s;
    return Replace(w, t, loss);
  }

  bool Replace(Worker& w, std::size_t t, const WorkerLoss& loss) {
    if (!callbacks_.lost(t, loss)) return false;
    if (next_ < count_) Spawn(w);
    return true;
  }

  /// Closes the pipes (an idle worker exits), kills first if asked, reaps; returns the wait status.
  int End(Worker& w, bool kill) {
    int status = 0;
    if (w.pid > 0 && kill) ::kill(w.pid, SIGKILL);
    if (w.tasks_fd >= 0) ::close(w.tasks_fd);
    if (w.results_fd >= 0) ::close(w.results_fd);
    if (w.pid > 0) {
      while (::waitpid(w.pid, &status, 0) < 0 && errno == EINTR) {
      }
    }
    w = Worker{};
    return status;
  }

  std::size_t count_;
  WorkerPoolOptions options_;
  const WorkerPoolCallbacks& callbacks_;
  pid_t parent_;
  std::vector<Worker> workers_;
  std::size_t next_ = 0;
};

/// Ignores SIGPIPE while the pool runs: writing to a dead worker fails with EPIPE, not the run.
class IgnoreSigpipe {
 public:
  IgnoreSigpipe() { old_ = std::signal(SIGPIPE, SIG_IGN); }
  ~IgnoreSigpipe() { std::signal(SIGPIPE, old_); }

 private:
  void (*old_)(int);
};

}  // namespace

void RunInWorkerProcesses(std::size_t count, const WorkerPoolOptions& options,
                          const WorkerPoolCallbacks& callbacks) {
  if (count == 0) return;
  IgnoreSigpipe ignore;
  Pool pool(count, options, callbacks);
  pool.Run();
}

OnceInWorker RunOnceInWorker(double timeout_s, const std::function<std::string()>& task) {
  OnceInWorker out;
  WorkerPoolOptions options;
  options.task_timeout_s = timeout_s;
  WorkerPoolCallbacks callbacks;
  callbacks.run = [&](std::size_t) { return task(); };
  callbacks.done = [&](std::size_t, std::string bytes) {
    out.bytes = std::move(bytes);
    return true;
  };
  callbacks.lost = [&](std::size_t, const WorkerLoss& loss) {
    out.loss = loss;
    return false;
  };
  RunInWorkerProcesses(1, options, callbacks);
  return out;
}

}  // namespace crowdsim
