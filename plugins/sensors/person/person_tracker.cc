#include "person_tracker.h"

#include <algorithm>
#include <stdexcept>
#include <tuple>

#include "crowdsim/thread_scratch.h"

namespace crowdsim::person {

namespace {

// A candidate association: the squared distance, then the indices (a fixed order for ties).
struct Pair {
  double d2;
  std::size_t track;
  std::size_t detection;
  bool operator<(const Pair& o) const {
    return std::tie(d2, track, detection) < std::tie(o.d2, o.track, o.detection);
  }
};

// One thread's buffers for a step's association.
struct Scratch {
  std::vector<char> matched;  // per detection
  std::vector<char> taken;    // per track
  std::vector<Pair> pairs;
};

void Continue(const TrackerConfig& config, int step, Track* t, Detection* d) {
  if (!(config.time_step > 0.0)) {
    throw std::invalid_argument(
        "person: estimated velocities need the episode's time step (SenseInput::time_step > 0)");
  }
  d->track = t->id;
  d->velocity = (d->world - t->position) / ((step - t->last_step) * config.time_step);
  t->position = d->world;
  t->last_step = step;
}

}  // namespace

void TrackStep(const TrackerConfig& config, int step, std::vector<Detection>* detections,
               TrackerState* state) {
  std::vector<Track>& tracks = state->tracks;
  Scratch& scratch = ThreadScratch<Scratch>();  // one lookup for the three buffers
  std::vector<char>& matched = scratch.matched;
  matched.assign(detections->size(), 0);
  if (config.association == Association::kIdentity) {
    for (std::size_t k = 0; k < detections->size(); ++k) {
      Detection& d = (*detections)[k];
      if (d.person < 0) continue;  // a phantom is never the same person twice
      for (Track& t : tracks) {
        if (t.id == d.person) {
          Continue(config, step, &t, &d);
          matched[k] = 1;
          break;
        }
      }
    }
  } else {
    // Every (track, detection) within the gate, nearest first; each side taken once.
    std::vector<Pair>& pairs = scratch.pairs;
    pairs.clear();
    const double gate2 = config.gate * config.gate;
    for (std::size_t t = 0; t < tracks.size(); ++t) {
      for (std::size_t k = 0; k < detections->size(); ++k) {
        const double d2 = ((*detections)[k].world - tracks[t].position).squaredNorm();
        if (d2 <= gate2) pairs.push_back(Pair{d2, t, k});
      }
    }
    std::sort(pairs.begin(), pairs.end());
    std::vector<char>& taken = scratch.taken;
    taken.assign(tracks.size(), 0);
    for (const Pair& p : pairs) {
      if (taken[p.track] || matched[p.detection]) continue;
      taken[p.track] = 1;
      matched[p.detection] = 1;
      Continue(config, step, &tracks[p.track], &(*detections)[p.detection]);
    }
  }
  // The rest start tracks (a phantom too, with the nearest rule: a tracker cannot tell).
  for (std::size_t k = 0; k < detections->size(); ++k) {
    if (matched[k]) continue;
    Detection& d = (*detections)[k];
    d.velocity = Vec2::Zero();
    if (config.association == Association::kIdentity) {
      if (d.person < 0) continue;
      d.track = d.person;
    } else {
      d.track = state->next_id++;
    }
    tracks.push_back(Track{d.track, d.world, step});
  }
  // A track last seen more than max_gap steps before the next one cannot continue there.
  std::erase_if(tracks,
                [&](const Track& t) { return step + 1 - t.last_step - 1 > config.max_gap; });
}

}  // namespace crowdsim::person
