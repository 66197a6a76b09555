#include "person_sensor.h"

#include <algorithm>
#include <cmath>

#include "crowdsim/collision_world.h"
#include "crowdsim/rng.h"

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
      {"fov_deg",
       ParamType::kDouble,
       360.0,
       0.01,
       360.0,
       {},
       "degrees; field of view centred on the frame's x axis (the robot's heading); humans whose "
       "centre lies outside are not reported; 360 = all around",
       false},
      {"occlusion",
       ParamType::kString,
       std::string("none"),
       0,
       0,
       {"none", "obstacles", "obstacles+people"},
       "what hides a human: a human is reported when a sight line from the robot's centre reaches "
       "its centre or either edge of its disc",
       false},
      {"detection_prob",
       ParamType::kDouble,
       1.0,
       0.0,
       1.0,
       {},
       "probability that a human in view is reported at a step (each step drawn anew)",
       false},
      {"position_noise",
       ParamType::kDouble,
       0.0,
       0.0,
       10.0,
       {},
       "m; standard deviation of the Gaussian noise added to each axis of a reported position",
       false},
  };
}

namespace {

Occlusion OcclusionFrom(const std::string& name) {
  if (name == "obstacles") return Occlusion::kObstacles;
  if (name == "obstacles+people") return Occlusion::kObstaclesAndPeople;
  return Occlusion::kNone;
}

// Whether the segment a-b passes closer than `radius` to `center`.
bool SegmentMeetsDisc(const Vec2& a, const Vec2& b, const Vec2& center, double radius) {
  const Vec2 ab = b - a;
  const double len2 = ab.squaredNorm();
  const double t = len2 > 0.0 ? std::clamp((center - a).dot(ab) / len2, 0.0, 1.0) : 0.0;
  return (a + t * ab - center).squaredNorm() < radius * radius;
}

}  // namespace

PersonSensor::PersonSensor(const Params& params)
    : max_range_(params.GetDouble("max_range")),
      half_fov_cos_(params.GetDouble("fov_deg") >= 360.0
                        ? -2.0
                        : std::cos(params.GetDouble("fov_deg") * M_PI / 360.0)),
      occlusion_(OcclusionFrom(params.GetString("occlusion"))),
      detection_prob_(params.GetDouble("detection_prob")),
      position_noise_(params.GetDouble("position_noise")) {}

bool PersonSensor::InRangeAndView(const SenseInput& in, std::size_t i) const {
  const Vec2 to = in.humans[i].position - in.frame.origin;
  const double d2 = to.squaredNorm();
  if (max_range_ > 0.0 && d2 > max_range_ * max_range_) return false;
  if (half_fov_cos_ < -1.5 || d2 == 0.0) return true;
  // In view when the centre's bearing is within half the field of view of the x axis.
  return in.frame.VectorToLocal(to).x() >= half_fov_cos_ * std::sqrt(d2);
}

void PersonSensor::Unoccluded(const SenseInput& in, std::vector<std::size_t>* candidates) const {
  // Three sight lines a person (its centre, either edge of its disc), all cast in one scan: one
  // broadphase query for the whole reading.
  thread_local std::vector<Vec2> directions;
  thread_local std::vector<double> lengths, ranges;
  thread_local std::vector<Vec2> ends;
  directions.clear();
  lengths.clear();
  ends.clear();
  const Vec2& eye = in.frame.origin;
  double farthest = 0.0;
  for (const std::size_t i : *candidates) {
    const AgentState& h = in.humans[i];
    const Vec2 to = h.position - eye;
    const double d = to.norm();
    const Vec2 side = d > 0.0 ? Vec2(Vec2(-to.y(), to.x()) * (h.radius / d)) : Vec2::Zero();
    for (const Vec2& end : {h.position, Vec2(h.position + side), Vec2(h.position - side)}) {
      const double length = (end - eye).norm();
      directions.push_back(length > 0.0 ? Vec2((end - eye) / length) : Vec2(1.0, 0.0));
      lengths.push_back(length);
      ends.push_back(end);
      farthest = std::max(farthest, length);
    }
  }
  ranges.resize(directions.size());
  in.world.CastRays(eye, directions, farthest + 1.0, {}, ranges.data());
  std::size_t kept = 0;
  for (std::size_t c = 0; c < candidates->size(); ++c) {
    const std::size_t i = (*candidates)[c];
    bool seen = lengths[3 * c] <= in.humans[i].radius;  // touching: nothing lies between
    for (std::size_t k = 3 * c; k < 3 * c + 3 && !seen; ++k) {
      if (ranges[k] < lengths[k]) continue;  // a rectangle first
      seen = occlusion_ != Occlusion::kObstaclesAndPeople ||
             !PersonInTheWay(in, ends[k], lengths[k], i);
    }
    if (seen) (*candidates)[kept++] = i;
  }
  candidates->resize(kept);
}

bool PersonSensor::PersonInTheWay(const SenseInput& in, const Vec2& end, double length,
                                  std::size_t target) const {
  const Vec2& eye = in.frame.origin;
  for (std::size_t j = 0; j < in.humans.size(); ++j) {
    if (j == target) continue;
    const AgentState& other = in.humans[j];
    // Only someone nearer than the line's end can stand on it.
    if ((other.position - eye).norm() - other.radius >= length) continue;
    if (SegmentMeetsDisc(eye, end, other.position, other.radius)) return true;
  }
  return false;
}

void PersonSensor::Sense(const SenseInput& in, SensorReading* out) const {
  // The reading is reused step after step: its people are overwritten in place (clearing and
  // pushing every person cost more).
  std::vector<PersonObservation>& people = out->people;
  const auto observe = [&in](const AgentState& h) {
    return PersonObservation{in.frame.PointToLocal(h.position), in.frame.VectorToLocal(h.velocity),
                             h.radius};
  };
  if (!(max_range_ > 0.0) && half_fov_cos_ < -1.5 && occlusion_ == Occlusion::kNone &&
      detection_prob_ >= 1.0 && position_noise_ == 0.0) {
    // Unlimited: everybody, in the crowd's order.
    people.resize(in.humans.size());
    for (std::size_t i = 0; i < in.humans.size(); ++i) people[i] = observe(in.humans[i]);
    return;
  }
  // The detected ones only: those beyond the reading's last size are added (sizing it to the
  // whole crowd would construct and drop the others every step).
  thread_local std::vector<std::size_t> detected;
  detected.clear();
  for (std::size_t i = 0; i < in.humans.size(); ++i) {
    if (InRangeAndView(in, i)) detected.push_back(i);
  }
  if (occlusion_ != Occlusion::kNone && !detected.empty()) Unoccluded(in, &detected);
  const bool noisy = detection_prob_ < 1.0 || position_noise_ > 0.0;
  std::size_t n = 0;
  for (const std::size_t i : detected) {
    PersonObservation seen = observe(in.humans[i]);
    if (noisy) {
      // One stream per (episode, step, human): the same draws on any thread and in a lookahead.
      Rng rng = NoiseRng(in, i);
      if (rng.Uniform() >= detection_prob_) continue;  // missed this step
      if (position_noise_ > 0.0) {
        const Vec2 noise(rng.Normal(), rng.Normal());
        seen.position += in.frame.VectorToLocal(noise * position_noise_);
      }
    }
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
