#include "scene_validation.h"

#include <cmath>
#include <optional>
#include <stdexcept>
#include <string>

#include "crowd_tracks/track_position.h"
#include "crowd_tracks/tracks.h"
#include "crowdsim/bench/episode.h"
#include "crowdsim/rng.h"
#include "crowdsim/world_source.h"

namespace crowdsim::crowds {

namespace {

// The robot's policy: it stands still, and nobody sees it (sim.robot_visible false).
class StandStill final : public Policy {
 public:
  Action Decide(const Observation&) override { return Action{}; }
};

// The model, started at the person's recorded velocity: the episode starts everybody at rest,
// so its first decision sees the velocity the track gives instead.
class FromRecordedVelocity final : public Policy {
 public:
  FromRecordedVelocity(Policy& model, const Vec2& velocity) : model_(model), velocity_(velocity) {}
  PolicyNeeds Needs() const override { return model_.Needs(); }
  void Reset(const EpisodeContext& ctx) override {
    first_ = true;
    model_.Reset(ctx);
  }
  Action Decide(const Observation& obs) override {
    if (!first_) return model_.Decide(obs);
    first_ = false;
    Observation started = obs;
    started.self.velocity = velocity_;
    if (velocity_.squaredNorm() > 0.0)
      started.self.heading = std::atan2(velocity_.y(), velocity_.x());
    return model_.Decide(started);
  }

 private:
  Policy& model_;
  Vec2 velocity_;
  bool first_ = true;
};

// Whether person `self` overlaps another present person of `episode`.
bool Overlaps(const Episode& episode, int self) {
  const AgentState& me = episode.humans()[static_cast<std::size_t>(self)];
  const std::span<const AgentState> present = episode.present_humans();
  const std::span<const int> ids = episode.present_ids();
  for (std::size_t k = 0; k < present.size(); ++k) {
    if ((ids.empty() ? static_cast<int>(k) : ids[k]) == self) continue;
    if ((present[k].position - me.position).norm() < me.radius + present[k].radius) return true;
  }
  return false;
}

// The step at which `h` starts to be validated: it is observed from its first frame to its last
// inside the episode, and for `horizon` s from that step; nullopt when it is not.
std::optional<double> ValidationStart(const HumanSpec& h, const SimConfig& sim, double horizon) {
  const double tolerance = kPresenceTolerance;
  if (h.track.empty() || h.track.front().time < -tolerance || h.leave > sim.time_limit + tolerance)
    return std::nullopt;
  const double start = std::ceil(h.appear / sim.time_step - tolerance) * sim.time_step;
  if (start + horizon > h.leave + tolerance) return std::nullopt;
  return start;
}

// The person's velocity on its track over the frame period from `time`.
Vec2 RecordedVelocity(const HumanSpec& h, double time) {
  return (crowd_tracks::TrackPosition(h.track, time + crowd_tracks::kFramePeriod) -
          crowd_tracks::TrackPosition(h.track, time)) /
         crowd_tracks::kFramePeriod;
}

}  // namespace

SceneValidation::SceneValidation(PluginRegistry& registry, const std::filesystem::path& tracks,
                                 const ValidationSettings& settings)
    : settings_(settings) {
  const LoadedPlugin& world = registry.Load("crowds", PluginKind::kWorld);
  for (const std::string& split : settings_.splits) {
    Params params = Params::Defaults(world.schema);
    params.Set("file", std::filesystem::absolute(tracks).string());
    params.Set("split", split);
    worlds_.push_back(registry.MakeWorld(world, params));
  }
  const std::string identity = worlds_.front()->Identity();  // crowds:SCENE:SPLIT
  scene_ = identity.substr(identity.find(':') + 1, identity.rfind(':') - identity.find(':') - 1);
  const LoadedPlugin& replay = registry.Load("replay", PluginKind::kPolicy);
  for (int i = 0; i < settings_.crowd; ++i)
    replay_.push_back(registry.MakePolicy(replay, Params::Defaults(replay.schema)));
}

SceneValidation::~SceneValidation() = default;

std::vector<PersonValidation> SceneValidation::Run(Policy& model) const {
  std::vector<PersonValidation> out;
  for (std::size_t s = 0; s < worlds_.size(); ++s)
    RunWorld(*worlds_[s], settings_.splits[s], model, &out);
  return out;
}

void SceneValidation::RunWorld(const WorldSource& world, const std::string& split, Policy& model,
                               std::vector<PersonValidation>* out) const {
  for (int k = 0; k < world.LayoutCount(); ++k) {
    ScenarioRequest request;
    request.seed = DeriveSeed(settings_.seed, world.Identity(), k);
    request.episode_index = k;
    request.num_humans = settings_.crowd;
    request.sim = settings_.sim;
    const Scenario scenario = world.Make(request);
    for (std::size_t i = 0; i < scenario.humans.size(); ++i) {
      const std::optional<double> start =
          ValidationStart(scenario.humans[i], settings_.sim, settings_.horizon);
      if (!start) continue;
      PersonValidation v{split, k, static_cast<int>(i), {}, false};
      try {
        Walk(scenario, v.person, *start, model, &v);
      } catch (const std::exception& e) {
        throw std::runtime_error("crowds validate: " + scene_ + " " + split + " window " +
                                 std::to_string(k) + ", person " + std::to_string(i) + ": " +
                                 e.what());
      }
      out->push_back(v);
    }
  }
}

void SceneValidation::Walk(const Scenario& scenario, int self, double start, Policy& model,
                           PersonValidation* v) const {
  const double tolerance = kPresenceTolerance;
  const HumanSpec& h = scenario.humans[static_cast<std::size_t>(self)];
  StandStill robot;
  FromRecordedVelocity walker(model, RecordedVelocity(h, start));
  EpisodeAgents agents;
  agents.robot = &robot;
  for (const auto& p : replay_) agents.humans.push_back(p.get());
  agents.humans[static_cast<std::size_t>(self)] = &walker;
  Episode episode(scenario, settings_.sim, agents);
  if (!episode.result().error.empty()) throw std::runtime_error(episode.result().error);
  // The walked path at every step from the start, overlaps checked after it.
  std::vector<TrackPoint> path;
  for (;;) {
    if (episode.time() >= start - tolerance) {
      path.push_back(
          TrackPoint{episode.time(), episode.humans()[static_cast<std::size_t>(self)].position});
      if (episode.time() > start + tolerance && Overlaps(episode, self)) v->collided = true;
    }
    if (episode.time() >= start + settings_.horizon - tolerance) break;
    episode.StepPeopleOnly();
  }
  // Both compared at the recording's frame times from the start.
  const int points = static_cast<int>(std::lround(settings_.horizon / crowd_tracks::kFramePeriod));
  std::vector<Vec2> simulated, recorded;
  for (int n = 0; n <= points; ++n) {
    const double t = start + n * crowd_tracks::kFramePeriod;
    simulated.push_back(crowd_tracks::TrackPosition(path, t));
    recorded.push_back(crowd_tracks::TrackPosition(h.track, t));
  }
  v->comparison = CompareTracks(simulated, recorded, settings_.horizon);
}

}  // namespace crowdsim::crowds
