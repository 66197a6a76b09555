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
  // Sized for everybody, then cut to those in range: the reading is reused step after step,
  // so this constructs nothing once it has held the crowd (a push_back per person did).
  std::vector<PersonObservation>& people = out->people;
  people.resize(in.humans.size());
  std::size_t n = 0;
  const double range2 = max_range_ * max_range_;
  for (const AgentState& h : in.humans) {
    if (max_range_ > 0.0 && (h.position - in.frame.origin).squaredNorm() > range2) continue;
    people[n++] = PersonObservation{in.frame.PointToLocal(h.position),
                                    in.frame.VectorToLocal(h.velocity), h.radius};
  }
  people.resize(n);
}

}  // namespace crowdsim::person
