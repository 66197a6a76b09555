#include "person_sensor.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <span>

#include "crowdsim/collision_world.h"
#include "crowdsim/rng.h"
#include "crowdsim/thread_scratch.h"

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
      {"false_detections",
       ParamType::kDouble,
       0.0,
       0.0,
       50.0,
       {},
       "expected number of phantom people a reading (Poisson), uniform over the free sensed area "
       "(max_range, or 5 m when unlimited, and the field of view), at rest, radius 0.3 m",
       false},
      {"velocity",
       ParamType::kString,
       std::string("true"),
       0,
       0,
       {"true", "estimated"},
       "true: the people's velocities; estimated: the change of a detection's reported position "
       "since its track's last detection over the time between (a new track: zero)",
       false},
      {"tracker",
       ParamType::kString,
       std::string("none"),
       0,
       0,
       {"none", "nearest"},
       "none: no identities (estimated velocities follow the true person); nearest: greedy "
       "nearest-neighbour tracks, each detection's track_id",
       false},
      {"track_gate",
       ParamType::kDouble,
       1.0,
       0.01,
       100.0,
       {},
       "m; the farthest a detection may lie from a track's last position to continue it",
       false},
      {"track_max_gap",
       ParamType::kInt,
       std::int64_t{2},
       0,
       1000,
       {},
       "steps a track survives without a detection; a person seen again later gets a new id",
       false},
  };
}

namespace {

Occlusion OcclusionFrom(const std::string& name) {
  if (name == "obstacles") return Occlusion::kObstacles;
  if (name == "obstacles+people") return Occlusion::kObstaclesAndPeople;
  return Occlusion::kNone;
}

// Which eighth of the circle v points into, counter-clockwise from the x axis (0-7).
std::uint8_t Octant(const Vec2& v) {
  static constexpr std::array<std::uint8_t, 8> kByKey{0, 1, 3, 2, 7, 6, 4, 5};
  const unsigned key = (v.y() < 0.0 ? 4U : 0U) | (v.x() < 0.0 ? 2U : 0U) |
                       (std::abs(v.y()) > std::abs(v.x()) ? 1U : 0U);
  return kByKey[key];
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
      position_noise_(params.GetDouble("position_noise")),
      false_detections_(params.GetDouble("false_detections")),
      estimate_velocity_(params.GetString("velocity") == "estimated"),
      track_(params.GetString("tracker") == "nearest") {
  phantom_area_.range = max_range_ > 0.0 ? max_range_ : kPhantomRange;
  phantom_area_.half_fov = params.GetDouble("fov_deg") * M_PI / 360.0;
  tracker_.association = track_ ? Association::kNearest : Association::kIdentity;
  tracker_.gate = params.GetDouble("track_gate");
  tracker_.max_gap = static_cast<int>(params.GetInt("track_max_gap"));
}

int PersonSensor::HistorySteps() const {
  if (track_) return -1;
  return estimate_velocity_ ? tracker_.max_gap + 1 : 0;
}

bool PersonSensor::InRangeAndView(const SenseInput& in, std::size_t i) const {
  const Vec2 to = in.humans[i].position - in.frame.origin;
  const double d2 = to.squaredNorm();
  if (max_range_ > 0.0 && d2 > max_range_ * max_range_) return false;
  if (half_fov_cos_ < -1.5 || d2 == 0.0) return true;
  // In view when the centre's bearing is within half the field of view of the x axis.
  return in.frame.VectorToLocal(to).x() >= half_fov_cos_ * std::sqrt(d2);
}

namespace {

// The tracker's state after step k is a pure function of the episode's seed and frames 0..k:
// this thread keeps the last one per (sensor, history), so that a reading replays only the
// frames added since instead of the whole episode. The result is the same.
struct Memo {
  const void* sensor = nullptr;
  std::uint64_t history_id = 0;
  std::uint64_t noise_seed = 0;
  int step = -1;  // the last past step folded into `state` (-1: before step 0, no tracks)
  TrackerState state;
  // The last real reading's state after its own step, with what it sensed: it becomes `state`
  // once a past shows the same at that step (-1: none).
  int pending_step = -1;
  Frame frame;
  std::vector<AgentState> humans;
  TrackerState pending;
};

}  // namespace

// One thread's buffers and tracker memos: one thread-local lookup a reading.
struct PersonSensor::Scratch {
  std::vector<std::size_t> detected;  // candidates, then the seen
  std::vector<std::uint8_t> octant;   // of each candidate's bearing
  std::vector<std::size_t> line;      // each candidate's first sight line
  std::vector<Vec2> ends;             // of the sight lines
  std::vector<double> lengths;
  std::vector<std::uint8_t> blocked;  // by a rectangle
  std::vector<double> near;           // each person's nearest reach from the eye, m
  std::vector<Detection> now, past;   // this step's detections, a replayed step's
  TrackerState state;
  std::array<Memo, 4> memos;
  std::size_t next_memo = 0;
};

void PersonSensor::Unoccluded(const SenseInput& in, Scratch& s) const {
  // Three sight lines a person (its centre, either edge of its disc), all tested in one query.
  // People go to it by octant of bearing (a counting sort), so that each four lines it culls
  // together point roughly one way.
  std::vector<std::size_t>* candidates = &s.detected;
  const std::size_t m = candidates->size();
  const Vec2& eye = in.frame.origin;
  std::array<std::size_t, 9> start{};
  s.octant.resize(m);
  for (std::size_t c = 0; c < m; ++c) {
    s.octant[c] = Octant(in.humans[(*candidates)[c]].position - eye);
    ++start[s.octant[c] + 1];
  }
  for (std::size_t o = 1; o < start.size(); ++o) start[o] += start[o - 1];
  s.ends.resize(3 * m);
  s.line.resize(m);
  for (std::size_t c = 0; c < m; ++c) {
    const std::size_t first = 3 * start[s.octant[c]]++;
    s.line[c] = first;
    const AgentState& h = in.humans[(*candidates)[c]];
    const Vec2 to = h.position - eye;
    const double d = to.norm();
    const Vec2 side = d > 0.0 ? Vec2(Vec2(-to.y(), to.x()) * (h.radius / d)) : Vec2::Zero();
    s.ends[first] = h.position;
    s.ends[first + 1] = h.position + side;
    s.ends[first + 2] = h.position - side;
  }
  if (occlusion_ == Occlusion::kObstaclesAndPeople) {
    s.near.resize(in.humans.size());
    for (std::size_t j = 0; j < in.humans.size(); ++j)
      s.near[j] = (in.humans[j].position - eye).norm() - in.humans[j].radius;
  }
  s.lengths.resize(s.ends.size());
  s.blocked.resize(s.ends.size());
  in.world.SightLines(eye, s.ends, s.lengths.data(), s.blocked.data());
  std::size_t kept = 0;
  for (std::size_t c = 0; c < m; ++c) {
    const std::size_t i = (*candidates)[c];
    const std::size_t first = s.line[c];
    bool seen = s.lengths[first] <= in.humans[i].radius;  // touching: nothing lies between
    for (std::size_t k = first; k < first + 3 && !seen; ++k) {
      if (s.blocked[k]) continue;  // a rectangle first
      seen = occlusion_ != Occlusion::kObstaclesAndPeople ||
             !PersonInTheWay(in, s.ends[k], s.lengths[k], i, s.near);
    }
    if (seen) (*candidates)[kept++] = i;
  }
  candidates->resize(kept);
}

bool PersonSensor::PersonInTheWay(const SenseInput& in, const Vec2& end, double length,
                                  std::size_t target, std::span<const double> near) const {
  const Vec2& eye = in.frame.origin;
  for (std::size_t j = 0; j < in.humans.size(); ++j) {
    // Only someone nearer than the line's end can stand on it.
    if (j == target || near[j] >= length) continue;
    const AgentState& other = in.humans[j];
    if (SegmentMeetsDisc(eye, end, other.position, other.radius)) return true;
  }
  return false;
}

void PersonSensor::Detect(const SenseInput& in, Scratch& s, std::vector<Detection>* out) const {
  out->clear();
  const auto observe = [&in](const AgentState& h) {
    return PersonObservation{in.frame.PointToLocal(h.position), in.frame.VectorToLocal(h.velocity),
                             h.radius};
  };
  std::vector<std::size_t>& detected = s.detected;
  detected.clear();
  for (std::size_t i = 0; i < in.humans.size(); ++i) {
    if (InRangeAndView(in, i)) detected.push_back(i);
  }
  if (occlusion_ != Occlusion::kNone && !detected.empty()) Unoccluded(in, s);
  const bool noisy = detection_prob_ < 1.0 || position_noise_ > 0.0;
  for (const std::size_t i : detected) {
    Detection d;
    d.seen = observe(in.humans[i]);
    d.world = in.humans[i].position;
    d.person = HumanId(in, i);
    if (noisy) {
      // One stream per (episode, step, human): the same draws on any thread and in a lookahead.
      Rng rng = NoiseRng(in, static_cast<std::uint64_t>(d.person));
      if (rng.Uniform() >= detection_prob_) continue;  // missed this step
      if (position_noise_ > 0.0) {
        const Vec2 noise(rng.Normal(), rng.Normal());
        d.seen.position += in.frame.VectorToLocal(noise * position_noise_);
        d.world += noise * position_noise_;
      }
    }
    out->push_back(d);
  }
  if (false_detections_ > 0.0) AddFalseDetections(in, phantom_area_, false_detections_, out);
}

namespace {

Memo* FindMemo(std::array<Memo, 4>& memos, std::size_t& next, const void* sensor,
               const SenseInput& in) {
  if (in.history_id == 0) return nullptr;
  for (Memo& m : memos) {
    if (m.sensor == sensor && m.history_id == in.history_id && m.noise_seed == in.noise_seed) {
      return &m;
    }
  }
  Memo& m = memos[next];
  next = (next + 1) % memos.size();
  m.sensor = sensor;
  m.history_id = in.history_id;
  m.noise_seed = in.noise_seed;
  m.step = -1;  // the state before step 0: no tracks (cleared, keeping the vector's memory)
  m.state.tracks.clear();
  m.state.next_id = 0;
  m.pending_step = -1;
  return &m;
}

// Whether `f` is what the pending reading sensed (all the tracker reads of it: the frame, where
// people are and their size).
bool SameState(const Memo& m, const SensedFrame& f) {
  if (m.frame.origin != f.frame.origin || m.frame.cos_h != f.frame.cos_h ||
      m.frame.sin_h != f.frame.sin_h || m.humans.size() != f.humans.size()) {
    return false;
  }
  for (std::size_t i = 0; i < f.humans.size(); ++i) {
    if (m.humans[i].position != f.humans[i].position || m.humans[i].radius != f.humans[i].radius)
      return false;
  }
  return true;
}

void Assign(TrackerState* to, const TrackerState& from) {
  to->tracks.assign(from.tracks.begin(), from.tracks.end());  // no allocation once grown
  to->next_id = from.next_id;
}

}  // namespace

void PersonSensor::TrackedBefore(const SenseInput& in, Scratch& s) const {
  TrackerState* state = &s.state;
  const int first = in.step - static_cast<int>(in.past.size());  // the oldest frame's step
  Memo* memo = FindMemo(s.memos, s.next_memo, this, in);
  if (memo != nullptr && memo->pending_step >= first && memo->pending_step < in.step) {
    // The past now holds the pending reading's step: its state counts if it sensed the same.
    if (SameState(*memo, in.past[static_cast<std::size_t>(memo->pending_step - first)])) {
      std::swap(memo->state, memo->pending);
      memo->step = memo->pending_step;
    }
    memo->pending_step = -1;
  }
  int from = first;
  state->tracks.clear();
  state->next_id = 0;
  if (memo != nullptr && memo->step >= first - 1 && memo->step < in.step) {
    Assign(state, memo->state);
    from = memo->step + 1;
  }
  std::vector<Detection>& detections = s.past;
  for (int k = from; k < in.step; ++k) {
    const SensedFrame& f = in.past[static_cast<std::size_t>(k - first)];
    SenseInput then{f.robot, f.frame, f.humans, in.world, in.noise_seed, k, in.time_step};
    then.human_ids = f.human_ids;
    Detect(then, s, &detections);
    TrackStep(tracker_, k, &detections, state);
  }
  if (memo != nullptr && from < in.step) {
    memo->step = in.step - 1;
    Assign(&memo->state, *state);
  }
}

void PersonSensor::KeepPending(const SenseInput& in, Scratch& s) const {
  const TrackerState& state = s.state;
  Memo* memo = FindMemo(s.memos, s.next_memo, this, in);
  if (memo == nullptr) return;
  memo->pending_step = in.step;
  memo->frame = in.frame;
  memo->humans.assign(in.humans.begin(), in.humans.end());
  Assign(&memo->pending, state);
}

void PersonSensor::Sense(const SenseInput& in, SensorReading* out) const {
  // The reading is reused step after step: its people are overwritten in place (clearing and
  // pushing every person cost more).
  std::vector<PersonObservation>& people = out->people;
  if (!(max_range_ > 0.0) && half_fov_cos_ < -1.5 && occlusion_ == Occlusion::kNone &&
      detection_prob_ >= 1.0 && position_noise_ == 0.0 && false_detections_ == 0.0 &&
      !estimate_velocity_ && !track_) {
    // Unlimited: everybody, in the crowd's order.
    people.resize(in.humans.size());
    for (std::size_t i = 0; i < in.humans.size(); ++i) {
      const AgentState& h = in.humans[i];
      people[i] = PersonObservation{in.frame.PointToLocal(h.position),
                                    in.frame.VectorToLocal(h.velocity), h.radius};
    }
    return;
  }
  Scratch& s = ThreadScratch<Scratch>();
  std::vector<Detection>& detections = s.now;
  if (estimate_velocity_ || track_) {
    // The tracker over the past, then this step.
    TrackedBefore(in, s);
    Detect(in, s, &detections);
    TrackStep(tracker_, in.step, &detections, &s.state);
    // A real step's state is the next reading's past: kept, checked against it then.
    if (!in.lookahead) KeepPending(in, s);
    for (Detection& d : detections) {
      if (estimate_velocity_) d.seen.velocity = in.frame.VectorToLocal(d.velocity);
      if (track_) d.seen.track_id = d.track;
    }
  } else {
    Detect(in, s, &detections);
  }
  // The detected ones only: those beyond the reading's last size are added (sizing it to the
  // whole crowd would construct and drop the others every step).
  const std::size_t n = detections.size();
  for (std::size_t k = 0; k < n; ++k) {
    if (k < people.size()) {
      people[k] = detections[k].seen;
    } else {
      people.push_back(detections[k].seen);
    }
  }
  people.resize(n);
}

}  // namespace crowdsim::person
