#include "false_detections.h"

#include <cmath>

#include "crowdsim/collision_world.h"

namespace crowdsim::person {

int PoissonCount(Rng& rng, double mean) {
  if (!(mean > 0.0)) return 0;
  const double limit = std::exp(-mean);
  int k = 0;
  for (double p = rng.Uniform(); p > limit; p *= rng.Uniform()) ++k;
  return k;
}

void AddFalseDetections(const SenseInput& in, const SensedArea& area, double rate,
                        std::vector<Detection>* out) {
  // One stream a reading, apart from the people's (stream 0) and the lidar's (1).
  constexpr std::uint64_t kPhantomStream = 2;
  Rng rng = NoiseRng(in, 0, kPhantomStream);
  const int count = PoissonCount(rng, rate);
  const StaticMap& map = in.world.map();
  for (int n = 0; n < count; ++n) {
    for (int attempt = 0; attempt < kPhantomTries; ++attempt) {
      // Uniform over the sector's area: the radius as the square root of a uniform.
      const double r = area.range * std::sqrt(rng.Uniform());
      const double bearing = area.half_fov * (2.0 * rng.Uniform() - 1.0);
      const Vec2 local(r * std::cos(bearing), r * std::sin(bearing));
      const Vec2 world = in.frame.origin + in.frame.VectorToWorld(local);
      if (map.bounds.Area() > 0.0 && !map.bounds.Contains(world)) continue;
      if (in.world.DiscOverlaps(world, kPhantomRadius)) continue;
      Detection d;
      d.seen = PersonObservation{in.frame.PointToLocal(world), Vec2::Zero(), kPhantomRadius};
      d.world = world;
      out->push_back(d);
      break;
    }
  }
}

}  // namespace crowdsim::person
