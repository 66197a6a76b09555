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
  // The reading is reused step after step: its people are overwritten in place and only the
  // ones beyond its last size are added (clearing and pushing every person cost more).
  std::vector<PersonObservation>& people = out->people;
  std::size_t n = 0;
  const double range2 = max_range_ * max_range_;
  for (const AgentState& h : in.humans) {
    if (max_range_ > 0.0 && (h.position - in.frame.origin).squaredNorm() > range2) continue;
    const PersonObservation seen{in.frame.PointToLocal(h.position),
                                 in.frame.VectorToLocal(h.velocity), h.radius};
    if (n < people.size()) {
      people[n] = seen;
    } else {
      people.push_back(seen);
    }
    ++n;
  }
  people.resize(n);
}

}  // namespace crowdsim::person
