#include "track_comparison.h"

#include <stdexcept>

namespace crowdsim::crowds {

namespace {

double PathLength(std::span<const Vec2> path) {
  double length = 0.0;
  for (std::size_t k = 1; k < path.size(); ++k) length += (path[k] - path[k - 1]).norm();
  return length;
}

}  // namespace

TrackComparison CompareTracks(std::span<const Vec2> simulated, std::span<const Vec2> recorded,
                              double horizon) {
  if (simulated.size() != recorded.size() || simulated.size() < 2 || !(horizon > 0.0)) {
    throw std::invalid_argument(
        "CompareTracks needs equally many points (at least two) and a positive horizon");
  }
  TrackComparison c;
  double sum = 0.0;
  for (std::size_t k = 1; k < simulated.size(); ++k) sum += (simulated[k] - recorded[k]).norm();
  c.ade = sum / static_cast<double>(simulated.size() - 1);
  c.fde = (simulated.back() - recorded.back()).norm();
  c.simulated_speed = PathLength(simulated) / horizon;
  c.recorded_speed = PathLength(recorded) / horizon;
  return c;
}

}  // namespace crowdsim::crowds
