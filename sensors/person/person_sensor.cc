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
  out->people.clear();
  const double range2 = max_range_ * max_range_;
  for (const AgentState& h : in.humans) {
    if (max_range_ > 0.0 && (h.position - in.frame.origin).squaredNorm() > range2) continue;
    out->people.push_back(PersonObservation{in.frame.PointToLocal(h.position),
                                            in.frame.VectorToLocal(h.velocity), h.radius});
  }
}

}  // namespace crowdsim::person
