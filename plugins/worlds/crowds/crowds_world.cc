#include "crowds_world.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "crowd_tracks/track_position.h"
#include "crowdsim/rng.h"
#include "scene_layout.h"

namespace crowdsim::crowds {

namespace {

// Robot start draws before one clear of the people present at time 0 is given up on.
constexpr int kStartTries = 50;

// The person's recorded speed as v_pref: its mean, at least a fifth of its peak (so the harness's
// limit of 10 x v_pref never refuses a recorded step) and 0.1 m/s.
double RecordedVPref(const std::vector<TrackPoint>& track) {
  double length = 0.0;
  double peak = 0.0;
  for (std::size_t k = 1; k < track.size(); ++k) {
    const double d = (track[k].position - track[k - 1].position).norm();
    length += d;
    peak = std::max(peak, d / (track[k].time - track[k - 1].time));
  }
  const double span = track.back().time - track.front().time;
  const double mean = span > 0.0 ? length / span : 0.0;
  return std::max({mean, peak / 5.0, 0.1});
}

}  // namespace

ParamSchema Schema() {
  return {
      {"file",
       ParamType::kString,
       std::string("worlds/crowds/eth.tracks"),
       -kInfinity,
       kInfinity,
       {},
       "track file of a recorded scene (relative: suite folder, then data root)"},
      {"split",
       ParamType::kString,
       std::string("test"),
       -kInfinity,
       kInfinity,
       {"train", "test"},
       "which frozen time windows of the recording to play (docs/crowds.md)"},
  };
}

std::vector<std::filesystem::path> CrowdsWorld::DataFiles(const Params& params) {
  return {params.ResolvePath(params.GetString("file"))};
}

CrowdsWorld::CrowdsWorld(const Params& params) : split_(params.GetString("split")) {
  const std::string value = params.GetString("file");
  const std::filesystem::path path = params.ResolvePath(value);
  if (!std::filesystem::exists(path)) {
    throw std::runtime_error("crowds: track file " + params.MissingFile(value) +
                             "; import one with `crowdsim-bench crowds import`");
  }
  const crowd_tracks::Tracks tracks = crowd_tracks::ReadTracks(path);
  scene_ = tracks.scene.empty() ? path.stem().string() : tracks.scene;
  try {
    windows_ = SplitWindows(tracks, split_);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(path.string() + ": " + e.what());
  }
  map_ = SceneMap(tracks, "crowds/" + scene_);
  box_ = TracksBox(tracks);
  axis_ = MainFlowAxis(tracks);
  for (const crowd_tracks::RecordedPerson& p : tracks.people) {
    std::vector<TrackPoint>& t = tracks_.emplace_back();
    for (std::size_t k = 0; k < p.positions.size(); ++k) {
      t.push_back(TrackPoint{p.first_time() + static_cast<double>(k) * crowd_tracks::kFramePeriod,
                             p.positions[k]});
    }
    v_pref_.push_back(RecordedVPref(t));
  }
}

std::string CrowdsWorld::Identity() const { return "crowds:" + scene_ + ":" + split_; }

std::vector<HumanSpec> CrowdsWorld::PeopleOf(double start, double length,
                                             const ScenarioRequest& request) const {
  const double dt = request.sim.time_step;
  std::vector<HumanSpec> people;
  for (std::size_t p = 0; p < tracks_.size(); ++p) {
    const std::vector<TrackPoint>& t = tracks_[p];
    const double appear = std::max(t.front().time - start, 0.0);
    const double leave = t.back().time - start;
    // Present at some step of the episode: a step time within [appear, leave].
    const double first_step = std::ceil(appear / dt - kPresenceTolerance) * dt;
    if (first_step > leave + kPresenceTolerance || first_step > length) continue;
    HumanSpec h;
    h.appear = appear;
    h.leave = leave;
    // The points that bound the episode's steps, in episode time.
    for (std::size_t k = 0; k < t.size(); ++k) {
      const bool before = k + 1 < t.size() && t[k + 1].time <= start;
      const bool after = k > 0 && t[k - 1].time >= start + length;
      if (!before && !after) h.track.push_back(TrackPoint{t[k].time - start, t[k].position});
    }
    h.start = crowd_tracks::TrackPosition(h.track, first_step);
    h.goals = {h.track.back().position};
    h.radius = HumanAttributesOf(request, static_cast<int>(people.size())).radius;
    h.v_pref = v_pref_[p];
    people.push_back(std::move(h));
  }
  return people;
}

Scenario CrowdsWorld::Make(const ScenarioRequest& request) const {
  const std::int64_t k = FrozenLayoutIndex(request, static_cast<std::int64_t>(windows_.size()));
  Scenario s;
  s.map = map_;
  s.seed = request.seed;
  s.layout = scene_ + "/" + split_ + "/" + std::to_string(k);
  s.humans = PeopleOf(windows_[static_cast<std::size_t>(k)], request.sim.time_limit, request);
  if (static_cast<int>(s.humans.size()) > request.num_humans) {
    std::size_t most = 0;
    for (const double w : windows_)
      most = std::max(most, PeopleOf(w, request.sim.time_limit, request).size());
    throw std::invalid_argument(
        "crowds: window " + s.layout + " holds " + std::to_string(s.humans.size()) +
        " people, more than humans.count " + std::to_string(request.num_humans) +
        ": set humans.count to at least " + std::to_string(most) +
        " (the most of any window of this split)");
  }
  // The rest of the requested crowd is never present: a track file fixes who walks.
  HumanSpec nobody;
  nobody.start = box_.Center();
  nobody.goals = {nobody.start};
  nobody.appear = kInfinity;
  nobody.leave = kInfinity;
  s.humans.resize(static_cast<std::size_t>(request.num_humans), nobody);
  // The robot's start keeps clear of the people present at time 0 where it can.
  Rng rng(request.seed);
  const double gap = request.sim.robot_radius + request.sim.discomfort_dist;
  for (int attempt = 0; attempt < kStartTries; ++attempt) {
    const StartGoal pair = CrossingPair(box_, axis_, rng);
    s.robot_start = pair.start;
    s.robot_goal = pair.goal;
    const bool clear = std::none_of(s.humans.begin(), s.humans.end(), [&](const HumanSpec& h) {
      return PresentAt(h, 0.0) && (h.start - pair.start).norm() < h.radius + gap;
    });
    if (clear) break;
  }
  return s;
}

}  // namespace crowdsim::crowds
