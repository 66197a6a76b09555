#include "person_sensor.h"

namespace crowdsim::person {

ParamSchema Schema() {
  return {
      {"max_range",
       ParamType::kDouble,
       0.0,
       0.0,
       kInfinity,
       {},
       "m; humans whose centre is farther are not reported; 0 = unlimited"},
  };
}

PersonSensor::PersonSensor(const Params& params) : max_range_(params.GetDouble("max_range")) {}

void PersonSensor::Sense(const SenseInput& in, SensorReading* out) const {
  // The reading is reused step after step: its people are overwritten in place (clearing and
  // pushing every person cost more).
  std::vector<PersonObservation>& people = out->people;
  const auto observe = [&in](const AgentState& h) {
    return PersonObservation{in.frame.PointToLocal(h.position), in.frame.VectorToLocal(h.velocity),
                             h.radius};
  };
  if (!(max_range_ > 0.0)) {  // unlimited: everybody, in the crowd's order
    people.resize(in.humans.size());
    for (std::size_t i = 0; i < in.humans.size(); ++i) people[i] = observe(in.humans[i]);
    return;
  }
  // In range only: the ones beyond the reading's last size are added (sizing it to the whole
  // crowd would construct and drop the far ones every step).
  std::size_t n = 0;
  const double range2 = max_range_ * max_range_;
  for (const AgentState& h : in.humans) {
    if ((h.position - in.frame.origin).squaredNorm() > range2) continue;
    if (n < people.size()) {
      people[n] = observe(h);
    } else {
      people.push_back(observe(h));
    }
    ++n;
  }
  people.resize(n);
}

}  // namespace crowdsim::person
