#include "crowdsim/bench/human_attributes.h"

#include <algorithm>
#include <cmath>

#include "crowdsim/rng.h"

namespace crowdsim {

namespace {

double Draw(const std::optional<AttributeRange>& range, double fallback, Rng& rng) {
  const double u = rng.Uniform();  // drawn even when unused: keys do not shift each other's draws
  if (!range) return fallback;
  return range->lo + (range->hi - range->lo) * u;
}

}  // namespace

std::vector<HumanAttributes> DrawHumanAttributes(const HumansSpec& humans, const SimConfig& sim,
                                                 std::uint64_t episode_seed, int count) {
  std::vector<HumanAttributes> people;
  if (!humans.Varied() || count <= 0) return people;
  people.reserve(static_cast<size_t>(count));
  for (int i = 0; i < count; ++i) {
    // A stream per person, apart from the world's and the agents' ("people").
    Rng rng(SplitMix64(episode_seed ^ 0x70656f706c65ULL) + static_cast<std::uint64_t>(i));
    HumanAttributes a;
    a.radius = Draw(humans.radius, sim.human_radius, rng);
    if (humans.radius) {
      a.radius =
          std::clamp(std::round(a.radius * 100.0) / 100.0, humans.radius->lo, humans.radius->hi);
    }
    a.v_pref = Draw(humans.v_pref, sim.human_v_pref, rng);
    a.ignores_robot = rng.Uniform() < humans.distracted;
    people.push_back(a);
  }
  return people;
}

}  // namespace crowdsim
