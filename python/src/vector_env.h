// VectorEnv: n copies of one suite row's episodes stepped together in C++ (on worker threads
// when asked), with numpy batches in and out, so a Python learner pays the interpreter once per
// batch rather than once per step. Sub-environment i plays the row's episodes first + i,
// first + i + n, first + i + 2n, ... (deterministic whatever the threads), and resets itself on
// the step after its episode ended (Gymnasium's "next step" autoreset: that step ignores its
// action and returns the new episode's first observation with reward 0).
#pragma once

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "python_row.h"
#include "row_episodes.h"
#include "worker_pool.h"

namespace crowdsim::python {

class VectorEnv {
 public:
  /// `threads` in all (1: the caller's only); at most num_envs are used.
  VectorEnv(std::unique_ptr<PythonRow> row, int num_envs, int threads);
  ~VectorEnv();

  /// Starts episodes first, first + 1, ..., first + n - 1; returns the batched observation.
  pybind11::dict Reset(int first);
  /// actions: (n, 2) velocities, m/s, world frame. Returns (obs, reward, terminated,
  /// truncated, status, episode): status as EpisodeStatus codes (0 = running).
  pybind11::tuple Step(const pybind11::array_t<double, pybind11::array::c_style |
                                                           pybind11::array::forcecast>& actions);

  int num_envs() const { return static_cast<int>(envs_.size()); }
  int threads() const { return pool_.threads(); }
  int humans() const { return humans_; }
  int beams() const { return beams_; }  ///< -1: no range sensor

 private:
  struct Batch;
  Batch MakeBatch() const;
  void Write(size_t i, const Observation& obs, Batch& batch) const;

  std::unique_ptr<PythonRow> row_;
  std::vector<std::unique_ptr<RowEpisodes>> envs_;
  std::vector<std::int64_t> next_episode_;  // past the last index once all are played
  std::vector<std::uint8_t> ended_;         // not vector<bool>: workers write neighbouring entries
  // Set by Reset: the constructor resets sub-environment 0 alone (to read the sensors' shapes),
  // so "env 0 has an episode" does not mean every sub-environment has one.
  bool reset_done_ = false;
  int humans_ = 0;
  int beams_ = -1;
  /// Sensors reporting other features (SensorReading::values), with their sizes.
  std::vector<std::pair<std::string, int>> features_;
  WorkerPool pool_;
};

}  // namespace crowdsim::python
