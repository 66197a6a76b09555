#include "vector_env.h"

#include <algorithm>
#include <limits>
#include <stdexcept>
#include <string>

#include "observation_arrays.h"

namespace py = pybind11;

namespace crowdsim::python {

// The arrays of one batched observation and step outcome, written by the workers without
// the GIL (the raw pointers are taken while it is held).
struct VectorEnv::Batch {
  py::array_t<double> robot, humans, lidar, time, reward;
  py::array_t<bool> mask, terminated, truncated;
  py::array_t<std::int8_t> status;
  py::array_t<std::int64_t> episode;
  std::vector<py::array_t<double>> features;  // VectorEnv::features_' order
  std::vector<double*> features_p;
  const std::vector<std::pair<std::string, int>>* feature_names = nullptr;
  double *robot_p, *humans_p, *lidar_p = nullptr, *time_p, *reward_p;
  bool *mask_p, *terminated_p, *truncated_p;
  std::int8_t* status_p;
  std::int64_t* episode_p;

  py::dict Observations() const {
    py::dict d;
    d["robot"] = robot;
    d["time"] = time;
    d["humans"] = humans;
    d["humans_mask"] = mask;
    if (lidar_p != nullptr) d["lidar"] = lidar;
    for (size_t k = 0; k < features.size(); ++k)
      d[py::str((*feature_names)[k].first)] = features[k];
    return d;
  }
};

VectorEnv::VectorEnv(std::unique_ptr<PythonRow> row, int num_envs, int threads)
    : row_(std::move(row)), pool_(std::clamp(threads, 1, std::max(1, num_envs))) {
  if (num_envs < 1) throw py::value_error("num_envs must be >= 1, got " + std::to_string(num_envs));
  humans_ = row_->row.humans.count;
  for (int i = 0; i < num_envs; ++i) {
    envs_.push_back(std::make_unique<RowEpisodes>(row_->suite, row_->row, row_->registry));
    // Ctrl-C while a large batch is made: Python's handler only sets a flag, read here.
    if (i % 16 == 15 && PyErr_CheckSignals() != 0) throw py::error_already_set();
  }
  next_episode_.assign(envs_.size(), 0);
  ended_.assign(envs_.size(), false);
  // The range sensor's beam count fixes the lidar batch's shape.
  const Observation& first = envs_[0]->Reset(0, false);
  const std::vector<double>* ranges = FirstRanges(first);
  beams_ = ranges ? static_cast<int>(ranges->size()) : -1;
  // So do the other sensors' feature counts (route: 3).
  for (const SensorReading& r : first.readings) {
    if (!r.values.empty()) features_.emplace_back(r.sensor, static_cast<int>(r.values.size()));
  }
}

VectorEnv::~VectorEnv() = default;

VectorEnv::Batch VectorEnv::MakeBatch() const {
  const py::ssize_t n = num_envs();
  Batch b;
  b.robot = py::array_t<double>({n, py::ssize_t{kRobotStateSize}});
  b.humans = py::array_t<double>({n, py::ssize_t{humans_}, py::ssize_t{5}});
  b.mask = py::array_t<bool>({n, py::ssize_t{humans_}});
  b.time = py::array_t<double>(n);
  b.reward = py::array_t<double>(n);
  b.terminated = py::array_t<bool>(n);
  b.truncated = py::array_t<bool>(n);
  b.status = py::array_t<std::int8_t>(n);
  b.episode = py::array_t<std::int64_t>(n);
  b.robot_p = b.robot.mutable_data();
  b.humans_p = b.humans.mutable_data();
  b.mask_p = b.mask.mutable_data();
  b.time_p = b.time.mutable_data();
  b.reward_p = b.reward.mutable_data();
  b.terminated_p = b.terminated.mutable_data();
  b.truncated_p = b.truncated.mutable_data();
  b.status_p = b.status.mutable_data();
  b.episode_p = b.episode.mutable_data();
  if (beams_ >= 0) {
    b.lidar = py::array_t<double>({n, py::ssize_t{beams_}});
    b.lidar_p = b.lidar.mutable_data();
  }
  b.feature_names = &features_;
  for (const auto& [name, size] : features_) {
    b.features.emplace_back(std::vector<py::ssize_t>{n, py::ssize_t{size}});
    b.features_p.push_back(b.features.back().mutable_data());
  }
  return b;
}

void VectorEnv::Write(size_t i, const Observation& obs, Batch& b) const {
  WriteRobotState(obs, b.robot_p + i * kRobotStateSize);
  WriteHumans(obs, humans_, b.humans_p + i * 5 * humans_, b.mask_p + i * humans_);
  b.time_p[i] = obs.time;
  if (b.lidar_p != nullptr) {
    const std::vector<double>* ranges = FirstRanges(obs);
    if (ranges == nullptr || static_cast<int>(ranges->size()) != beams_)
      throw std::logic_error("the range sensor's beam count changed between steps");
    std::copy(ranges->begin(), ranges->end(), b.lidar_p + i * beams_);
  }
  for (size_t k = 0; k < features_.size(); ++k) {
    const auto& [name, size] = features_[k];
    const SensorReading* r = obs.Reading(name);
    if (r == nullptr || static_cast<int>(r->values.size()) != size)
      throw std::logic_error("sensor '" + name + "' changed its number of values between steps");
    std::copy(r->values.begin(), r->values.end(), b.features_p[k] + i * size);
  }
}

py::dict VectorEnv::Reset(int first) {
  if (first < 0)
    throw py::value_error("the first episode must be >= 0, got " + std::to_string(first));
  Batch b = MakeBatch();
  const int n = num_envs();
  {
    py::gil_scoped_release release;
    pool_.Run(envs_.size(), [&](size_t begin, size_t end) {
      for (size_t i = begin; i < end; ++i) {
        const int episode = first + static_cast<int>(i);
        Write(i, envs_[i]->Reset(episode, false), b);
        next_episode_[i] = std::int64_t{episode} + n;
        ended_[i] = false;
        b.episode_p[i] = episode;
      }
    });
  }
  reset_done_ = true;
  py::dict obs = b.Observations();
  obs["episode"] = b.episode;
  return obs;
}

py::tuple VectorEnv::Step(
    const py::array_t<double, py::array::c_style | py::array::forcecast>& actions) {
  const py::ssize_t n = num_envs();
  if (actions.ndim() != 2 || actions.shape(0) != n || actions.shape(1) != 2) {
    throw py::value_error("actions must have shape (" + std::to_string(n) +
                          ", 2): one velocity (vx, vy) per environment");
  }
  if (!reset_done_) throw py::value_error("step() before reset(): call reset() first");
  for (size_t i = 0; i < envs_.size(); ++i) {
    if (ended_[i] && next_episode_[i] > std::numeric_limits<int>::max()) {
      throw py::value_error("sub-environment " + std::to_string(i) +
                            " has no next episode: it would be " +
                            std::to_string(next_episode_[i]) + ", past the last index " +
                            std::to_string(std::numeric_limits<int>::max()) +
                            "; call reset(seed=...) with a lower first episode");
    }
  }
  const double* a = actions.data();
  Batch b = MakeBatch();
  {
    py::gil_scoped_release release;
    pool_.Run(envs_.size(), [&](size_t begin, size_t end) {
      for (size_t i = begin; i < end; ++i) {
        RowEpisodes& env = *envs_[i];
        double reward = 0.0;
        if (ended_[i]) {  // next-step autoreset: the action of this step is ignored
          env.Reset(static_cast<int>(next_episode_[i]), false);
          next_episode_[i] += n;
          ended_[i] = false;
        } else {
          reward = env.Step(Vec2(a[2 * i], a[2 * i + 1])).reward;
        }
        const EpisodeStatus status = env.episode().result().status;
        ended_[i] = status != EpisodeStatus::kRunning;
        b.reward_p[i] = reward;
        b.terminated_p[i] = ended_[i] && status != EpisodeStatus::kTimeout;
        b.truncated_p[i] = status == EpisodeStatus::kTimeout;
        b.status_p[i] = static_cast<std::int8_t>(status);
        b.episode_p[i] = env.episode_index();
        Write(i, env.observation(), b);
      }
    });
  }
  return py::make_tuple(b.Observations(), b.reward, b.terminated, b.truncated, b.status, b.episode);
}

}  // namespace crowdsim::python
