// The robot's observation as numpy arrays (the layout documented in crowdsim_bench.Env):
// `robot` (9,) x, y, vx, vy, goal x, goal y, radius, v_pref, heading in the world frame;
// `humans` (H, 5) x, y, vx, vy, radius of the people the person sensors see, robot frame, padded
// to H rows with `humans_mask` (H,); `lidar` (beams,) the first range sensor's ranges; `time`.
// Writers fill caller-owned buffers (VectorEnv's batches, without the GIL); ObservationDict
// makes one observation's arrays (Env, Python policies).
#pragma once

#include <pybind11/pybind11.h>

#include "crowdsim/observation.h"

namespace crowdsim::python {

inline constexpr int kRobotStateSize = 9;

/// The robot's own state: kRobotStateSize values.
void WriteRobotState(const Observation& obs, double* out);

/// People seen, counted over every person sensor's reading.
int PeopleSeen(const Observation& obs);

/// The people seen into `rows` rows of 5 values and their mask (rows beyond them zero and
/// false). Throws std::length_error when more people are seen than `rows`.
void WriteHumans(const Observation& obs, int rows, double* humans, bool* mask);

/// The first range sensor's ranges (nullptr when the observation has none).
const std::vector<double>* FirstRanges(const Observation& obs);

/// The robot observation as a dict of numpy arrays, humans padded to at least `max_humans`.
pybind11::dict ObservationDict(const Observation& obs, int max_humans);

}  // namespace crowdsim::python
