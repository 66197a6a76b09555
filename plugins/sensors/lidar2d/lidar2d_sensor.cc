#include "lidar2d_sensor.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>
#include <stdexcept>

#include "crowdsim/collision_world.h"
#include "crowdsim/thread_scratch.h"

namespace crowdsim::lidar2d {

ParamSchema Schema() {
  return {
      {"beams", ParamType::kInt, std::int64_t{45}, 1, 3600, {}, "number of beams"},
      {"fov_deg",
       ParamType::kDouble,
       180.0,
       0.0,
       360.0,
       {},
       "field of view in degrees, (0, 360]; centred on the robot's heading"},
      {"max_range",
       ParamType::kDouble,
       5.0,
       0.0,
       kInfinity,
       {},
       "m, > 0; beams that hit nothing report this"},
      {"see_humans",
       ParamType::kBool,
       true,
       0,
       1,
       {},
       "beams stop at human discs (false: only static obstacles are seen)"},
      {"range_noise",
       ParamType::kDouble,
       0.0,
       0.0,
       10.0,
       {},
       "m; standard deviation of the Gaussian noise added to each return (none on a beam that "
       "hits nothing), clipped to [0, max_range]",
       /*hashed_at_default=*/false},
      {"dropout_prob",
       ParamType::kDouble,
       0.0,
       0.0,
       1.0,
       {},
       "probability that a beam returns nothing (max_range) at a step",
       /*hashed_at_default=*/false},
  };
}

std::vector<double> BeamAngles(int beams, double fov_deg) {
  std::vector<double> angles(static_cast<size_t>(beams));
  const double fov = fov_deg * std::numbers::pi / 180.0;
  if (fov_deg >= 360.0) {
    // A full circle: the last beam would repeat the first, so the endpoint is left out.
    for (int k = 0; k < beams; ++k) angles[k] = k * fov / beams;
  } else if (beams == 1) {
    angles[0] = 0.0;
  } else {
    // Written from the centre out so that the layout is exactly symmetric and, with an odd
    // count, the centre beam is exactly 0.
    const double step = fov / (2.0 * (beams - 1));
    for (int k = 0; k < beams; ++k) angles[k] = (2 * k - (beams - 1)) * step;
  }
  return angles;
}

namespace {

double Positive(const Params& params, const char* name) {
  const double v = params.GetDouble(name);
  if (!(v > 0.0)) {
    std::ostringstream msg;
    msg << "lidar2d: parameter '" << name << "' must be > 0 (got " << v
        << "); set a positive value in the sensor's parameters";
    throw std::invalid_argument(msg.str());
  }
  return v;
}

}  // namespace

Lidar2dSensor::Lidar2dSensor(const Params& params)
    : angles_(BeamAngles(static_cast<int>(params.GetInt("beams")), Positive(params, "fov_deg"))),
      max_range_(Positive(params, "max_range")),
      see_humans_(params.GetBool("see_humans")),
      range_noise_(params.GetDouble("range_noise")),
      dropout_prob_(params.GetDouble("dropout_prob")) {
  for (double a : angles_) directions_.emplace_back(std::cos(a), std::sin(a));
}

void Lidar2dSensor::Sense(const SenseInput& in, SensorReading* out) const {
  // Per-thread buffers: Sense runs once per step and per lookahead candidate, on several
  // threads, and must stay const.
  struct Directions {};
  struct Discs {};
  std::vector<Vec2>& world_directions = ThreadScratch<std::vector<Vec2>, Directions>();
  std::vector<Circle>& discs = ThreadScratch<std::vector<Circle>, Discs>();
  // The beam directions rotated by the heading: four products per beam instead of a sine and
  // a cosine (Frame carries the heading's cosine and sine).
  const double c = in.frame.cos_h;
  const double s = in.frame.sin_h;
  world_directions.resize(directions_.size());
  for (size_t k = 0; k < directions_.size(); ++k) {
    const Vec2& d = directions_[k];
    world_directions[k] = Vec2(d.x() * c - d.y() * s, d.y() * c + d.x() * s);
  }
  discs.clear();
  if (see_humans_) {
    for (const AgentState& h : in.humans) discs.push_back({h.position, h.radius});
  }
  out->angles = angles_;
  out->ranges.resize(angles_.size());
  out->max_range = max_range_;
  in.world.CastRays(in.frame.origin, world_directions, max_range_, discs, out->ranges.data());
  if (range_noise_ > 0.0 || dropout_prob_ > 0.0) AddNoise(in, &out->ranges);
}

void Lidar2dSensor::AddNoise(const SenseInput& in, std::vector<double>* ranges) const {
  constexpr std::uint64_t kLidarStream = 1;  // apart from the person sensor's draws (stream 0)
  for (size_t k = 0; k < ranges->size(); ++k) {
    Rng rng = NoiseRng(in, k, kLidarStream);
    double& r = (*ranges)[k];
    if (dropout_prob_ > 0.0 && rng.Uniform() < dropout_prob_) {
      r = max_range_;
    } else if (range_noise_ > 0.0 && r < max_range_) {
      r = std::clamp(r + range_noise_ * rng.Normal(), 0.0, max_range_);
    }
  }
}

}  // namespace crowdsim::lidar2d
