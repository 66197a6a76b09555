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

// The first round(share * count) people walk in groups of sizes drawn in [size_min, size_max]
// (the last one smaller, or alone when one person is left); each group walks at the pace of its
// slowest member, so that it can stay together.
void FormGroups(const GroupsSpec& groups, std::uint64_t episode_seed,
                std::vector<HumanAttributes>* people) {
  Rng rng(SplitMix64(episode_seed ^ 0x67726f757073ULL));  // "groups"
  const int count = static_cast<int>(people->size());
  const int grouped = std::min(count, static_cast<int>(std::lround(groups.share * count)));
  const auto span = static_cast<std::uint64_t>(groups.size_max - groups.size_min + 1);
  int next = 0, id = 0;
  while (grouped - next >= 2) {
    const int size = std::min(grouped - next, groups.size_min + static_cast<int>(rng.Below(span)));
    double pace = (*people)[static_cast<size_t>(next)].v_pref;
    for (int k = next; k < next + size; ++k)
      pace = std::min(pace, (*people)[static_cast<size_t>(k)].v_pref);
    for (int k = next; k < next + size; ++k) {
      (*people)[static_cast<size_t>(k)].group = id;
      (*people)[static_cast<size_t>(k)].v_pref = pace;
    }
    next += size;
    ++id;
  }
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
  if (humans.groups) FormGroups(*humans.groups, episode_seed, &people);
  return people;
}

}  // namespace crowdsim
