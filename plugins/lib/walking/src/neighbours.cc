#include "walking/neighbours.h"

#include "crowdsim/agent_index.h"

namespace crowdsim::walking {

void GatherNeighbours(const Observation& obs, double range, int max_neighbors,
                      std::vector<int>* ids, std::vector<Neighbour>* out) {
  out->clear();
  if (obs.agents != nullptr) {
    obs.agents->Nearest(obs.self.position, range, max_neighbors, obs.self_index, ids);
    const auto all = obs.agents->agents();
    for (const int id : *ids) out->push_back({all[id].position, all[id].velocity, all[id].radius});
    return;
  }
  const SensorReading* reading = obs.Reading("person");
  if (reading == nullptr) return;
  for (const PersonObservation& person : reading->people) {
    const Vec2 position = obs.frame.origin + obs.frame.VectorToWorld(person.position);
    if ((position - obs.self.position).norm() < range)
      out->push_back({position, obs.frame.VectorToWorld(person.velocity), person.radius});
  }
}

}  // namespace crowdsim::walking
