// The person sensor's false detections, estimated velocities and tracked identities (issue 48):
// every reading a pure function of the episode's seed, its past frames and the current state.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "crowdsim/bench/episode.h"
#include "crowdsim/bench/plugin_registry.h"
#include "crowdsim/bench/suite.h"
#include "crowdsim/collision_world.h"
#include "scripted.h"
#include "suite_runs.h"
#include "temp_dir.h"
#include "test_paths.h"

namespace crowdsim {
namespace {

using testing::ConstantVelocityPolicy;
using testing::MakeMap;
using testing::MakeScenario;

constexpr double kDt = 0.25;

class PersonTracking : public ::testing::Test {
 protected:
  PersonTracking() : registry_({testing::PluginDir()}) {
    auto map = std::make_shared<StaticMap>();
    map->bounds = Rect::FromCorners(-10, -10, 10, 10);
    map->rectangles = {Rect::FromCorners(1.0, 1.0, 2.0, 2.0)};  // ahead and to the left
    world_ = std::make_unique<CollisionWorld>(map);
  }

  /// A person sensor with the defaults but for `set` (name, value) pairs.
  std::shared_ptr<Sensor> Make(const std::vector<std::pair<std::string, ParamValue>>& set) {
    const LoadedPlugin& p = registry_.Load("person", PluginKind::kSensor);
    Params params = Params::Defaults(p.schema);
    for (const auto& [name, value] : set) params.Set(name, value);
    return registry_.MakeSensor(p, params);
  }

  /// The robot at the origin heading `heading`, the humans at `positions` (velocity as given).
  static SensedFrame At(std::vector<Vec2> positions, double heading = 0.0) {
    SensedFrame f;
    f.robot.heading = heading;
    f.frame = Frame::Make(Vec2::Zero(), heading);
    for (const Vec2& p : positions) {
      AgentState h;
      h.position = p;
      f.humans.push_back(h);
    }
    return f;
  }

  /// The reading at the last of `frames` (step frames.size() - 1), the others its past.
  std::vector<PersonObservation> Read(const Sensor& sensor, const std::vector<SensedFrame>& frames,
                                      std::uint64_t seed = 1, std::uint64_t history_id = 0) {
    const SensedFrame& now = frames.back();
    const std::span<const SensedFrame> past(frames.data(), frames.size() - 1);
    SensorReading reading;
    sensor.Sense(SenseInput{now.robot, now.frame, now.humans, *world_, seed,
                            static_cast<int>(frames.size()) - 1, kDt, past, history_id},
                 &reading);
    return reading.people;
  }

  PluginRegistry registry_;
  std::unique_ptr<CollisionWorld> world_;
};

// One person 3 m ahead (in the 180-degree view), or 3 m behind (out of it) at the hidden steps;
// a second one always ahead at (3, -2), so that ids count. track_max_gap 2: a track survives 2
// steps without a detection.
std::vector<SensedFrame> Hidden(int hidden_steps) {
  std::vector<SensedFrame> frames;
  const auto add = [&](double x0) {
    SensedFrame f;
    f.frame = Frame::Make(Vec2::Zero(), 0.0);
    AgentState a, b;
    a.position = Vec2(x0, 0.0);
    b.position = Vec2(3.0, -2.0);
    f.humans = {a, b};
    frames.push_back(f);
  };
  add(3.0);
  for (int k = 0; k < hidden_steps; ++k) add(-3.0);
  add(3.1);  // back in view, 0.1 m from where it was last seen: within the 1 m gate
  return frames;
}

TEST_F(PersonTracking, AnIdentitySurvivesShortGapsAndChangesAfterLongerOnes) {
  const auto sensor = Make({{"fov_deg", 180.0}, {"tracker", std::string("nearest")}});
  EXPECT_EQ(sensor->HistorySteps(), -1);
  // Step 0: the first person gets id 0, the second id 1 (the detections' order: the crowd's).
  const std::vector<SensedFrame> first = Hidden(0);
  const auto start = Read(*sensor, {first[0]});
  ASSERT_EQ(start.size(), 2u);
  EXPECT_EQ(start[0].track_id, 0);
  EXPECT_EQ(start[1].track_id, 1);
  for (const int hidden : {0, 1, 2}) {
    // Seen again after `hidden` <= track_max_gap steps out of view: the same id 0.
    const auto back = Read(*sensor, Hidden(hidden));
    ASSERT_EQ(back.size(), 2u) << hidden;
    EXPECT_EQ(back[0].track_id, 0) << hidden;
    EXPECT_EQ(back[1].track_id, 1) << hidden;
  }
  // Out of view for 3 steps: its track died after 2, so it starts id 2; the other keeps 1.
  const auto renewed = Read(*sensor, Hidden(3));
  ASSERT_EQ(renewed.size(), 2u);
  EXPECT_EQ(renewed[0].track_id, 2);
  EXPECT_EQ(renewed[1].track_id, 1);
  // Without a tracker nobody has an id.
  const auto untracked = Read(*Make({{"fov_deg", 180.0}}), Hidden(1));
  for (const PersonObservation& p : untracked) EXPECT_EQ(p.track_id, -1);
}

TEST_F(PersonTracking, TheGateSplitsTracksThatJumpTooFar) {
  const auto sensor = Make({{"tracker", std::string("nearest")}, {"track_gate", 0.5}});
  // 0.4 m in a step: within the 0.5 m gate, the same id; 0.6 m: a new track (id 1).
  EXPECT_EQ(Read(*sensor, {At({Vec2(3, 0)}), At({Vec2(3.4, 0)})})[0].track_id, 0);
  EXPECT_EQ(Read(*sensor, {At({Vec2(3, 0)}), At({Vec2(3.6, 0)})})[0].track_id, 1);
}

TEST_F(PersonTracking, EstimatedVelocitiesAreTheReportedPositionsFiniteDifference) {
  for (const std::string tracker : {"none", "nearest"}) {
    const auto sensor = Make({{"velocity", std::string("estimated")}, {"tracker", tracker}});
    // The robot heads +y (pi/2): world +x is the frame's -y. The person moves from (3, 0) to
    // (3.1, 0.05) in 0.25 s: (0.4, 0.2) m/s in the world, (0.2, -0.4) in the frame.
    const double up = std::acos(-1.0) / 2;
    const auto people = Read(*sensor, {At({Vec2(3, 0)}, up), At({Vec2(3.1, 0.05)}, up)});
    ASSERT_EQ(people.size(), 1u);
    EXPECT_NEAR(people[0].velocity.x(), 0.2, 1e-12) << tracker;
    EXPECT_NEAR(people[0].velocity.y(), -0.4, 1e-12) << tracker;
    // A new track (step 0) reports zero, whatever the person's true velocity.
    SensedFrame moving = At({Vec2(3, 0)});
    moving.humans[0].velocity = Vec2(1, 0);
    EXPECT_EQ(Read(*sensor, {moving})[0].velocity, Vec2::Zero()) << tracker;
  }
  // Over a gap the difference is divided by the time between: 0.3 m in 2 steps, 0.6 m/s.
  const auto sensor = Make({{"velocity", std::string("estimated")}, {"fov_deg", 180.0}});
  EXPECT_EQ(sensor->HistorySteps(), 3);  // track_max_gap + 1
  const auto people = Read(*sensor, {At({Vec2(3, 0)}), At({Vec2(-3, 0)}), At({Vec2(3.3, 0)})});
  ASSERT_EQ(people.size(), 1u);
  EXPECT_NEAR(people[0].velocity.x(), 0.6, 1e-12);
}

// A person at rest seen with position noise sigma = 0.1 m at two steps: the estimate's error,
// the difference of two independent errors over dt, has standard deviation sqrt(2) sigma / dt
// = 0.5657 m/s per axis. Over 4,000 readings (seeds) within 4 standard errors (sd / sqrt(2n)).
TEST_F(PersonTracking, EstimatedVelocityNoiseIsSqrtTwoSigmaOverDt) {
  const auto sensor = Make({{"velocity", std::string("estimated")}, {"position_noise", 0.1}});
  const std::vector<SensedFrame> frames = {At({Vec2(3, 0)}), At({Vec2(3, 0)})};
  constexpr int kN = 4000;
  double sx = 0, sxx = 0, sy = 0, syy = 0;
  for (int seed = 1; seed <= kN; ++seed) {
    const auto people = Read(*sensor, frames, static_cast<std::uint64_t>(seed));
    ASSERT_EQ(people.size(), 1u);
    const Vec2 v = people[0].velocity;
    sx += v.x();
    sxx += v.x() * v.x();
    sy += v.y();
    syy += v.y() * v.y();
  }
  const double expected = std::sqrt(2.0) * 0.1 / kDt;
  const double tolerance = 4.0 * expected / std::sqrt(2.0 * kN);
  EXPECT_NEAR(std::sqrt(sxx / kN - std::pow(sx / kN, 2)), expected, tolerance);
  EXPECT_NEAR(std::sqrt(syy / kN - std::pow(sy / kN, 2)), expected, tolerance);
  EXPECT_NEAR(sx / kN, 0.0, 4.0 * expected / std::sqrt(kN));
}

// 2 phantoms expected a reading, 4 m range, 180 degrees: over 10,000 readings the mean count
// is 2 within 4 standard errors (sqrt(2 / n) = 0.014), and every phantom lies within range and
// view, its disc clear of the rectangle (which covers 1/25.1 of the sector: some draws land in it).
TEST_F(PersonTracking, FalseDetectionsHaveTheirRateAndLieInTheFreeSensedArea) {
  const auto sensor = Make({{"false_detections", 2.0}, {"max_range", 4.0}, {"fov_deg", 180.0}});
  EXPECT_EQ(sensor->HistorySteps(), 0);
  AgentState robot;
  const Frame frame = Frame::Make(Vec2::Zero(), 0.0);
  constexpr int kN = 10000;
  long total = 0;
  for (int k = 0; k < kN; ++k) {
    SensorReading r;
    sensor->Sense(
        SenseInput{
            robot, frame, {}, *world_, static_cast<std::uint64_t>(k / 100 + 1), k % 100, kDt},
        &r);
    total += static_cast<long>(r.people.size());
    for (const PersonObservation& p : r.people) {
      EXPECT_LE(p.position.norm(), 4.0 + 1e-12);
      EXPECT_GE(p.position.x(), -1e-12);  // in the 180-degree view
      EXPECT_FALSE(world_->DiscOverlaps(p.position, p.radius)) << p.position.transpose();
      EXPECT_EQ(p.velocity, Vec2::Zero());
      EXPECT_EQ(p.radius, 0.3);
      EXPECT_EQ(p.track_id, -1);
    }
  }
  const double mean = static_cast<double>(total) / kN;
  EXPECT_NEAR(mean, 2.0, 4.0 * std::sqrt(2.0 / kN)) << mean;
  // With the tracker the phantoms get ids too (a tracker cannot tell them from people).
  const auto tracked = Make({{"false_detections", 3.0}, {"tracker", std::string("nearest")}});
  SensorReading r;
  tracked->Sense(SenseInput{robot, frame, {}, *world_, 5, 0, kDt}, &r);
  for (std::size_t i = 0; i < r.people.size(); ++i) {
    EXPECT_EQ(r.people[i].track_id, static_cast<int>(i));
  }
}

// The same (seed, step, history) gives the same reading, replayed from scratch or continued
// from the memo of the same history, and twice.
TEST_F(PersonTracking, AReadingIsAPureFunctionOfSeedHistoryAndState) {
  const auto sensor = Make({{"tracker", std::string("nearest")},
                            {"velocity", std::string("estimated")},
                            {"position_noise", 0.1},
                            {"detection_prob", 0.7},
                            {"false_detections", 1.0},
                            {"fov_deg", 180.0}});
  std::vector<SensedFrame> frames;
  for (int k = 0; k < 30; ++k) {
    frames.push_back(At({Vec2(3 - 0.1 * k, 0.5), Vec2(1 + 0.05 * k, -1), Vec2(4, 0.1 * k)}));
  }
  const auto same = [](const std::vector<PersonObservation>& a,
                       const std::vector<PersonObservation>& b) {
    if (a.size() != b.size()) return false;
    for (std::size_t i = 0; i < a.size(); ++i) {
      if (a[i].position != b[i].position || a[i].velocity != b[i].velocity ||
          a[i].track_id != b[i].track_id) {
        return false;
      }
    }
    return true;
  };
  for (std::size_t n = 1; n <= frames.size(); ++n) {
    const std::vector<SensedFrame> upto(frames.begin(), frames.begin() + n);
    const auto replayed = Read(*sensor, upto, 9);
    EXPECT_TRUE(same(replayed, Read(*sensor, upto, 9))) << n;
    EXPECT_TRUE(same(replayed, Read(*sensor, upto, 9, 77))) << n;  // the memo, step after step
    if (n % 3 == 0) {
      // A reading of a state the past will not show at this step (the people 1 m off): the
      // next reading must not build on it.
      std::vector<SensedFrame> other = upto;
      for (AgentState& h : other.back().humans) h.position.x() += 1.0;
      Read(*sensor, other, 9, 77);
    }
  }
  EXPECT_FALSE(same(Read(*sensor, frames, 9), Read(*sensor, frames, 10)));
}

/// Records each real reading and the lookahead's reading of the action it then takes.
class ReadingProbe final : public Policy {
 public:
  PolicyNeeds Needs() const override { return {.map = false, .lookahead = true, .sensors = {}}; }
  Action Decide(const Observation& obs) override {
    real.push_back(obs.readings.at(0).people);
    const std::vector<Action> actions = {Action{Vec2(0.1, 0.8)}, Action{Vec2(-1, 0)}};
    obs.lookahead->Evaluate(actions, &outcomes);
    predicted.push_back(outcomes.at(0).readings.at(0).people);
    return actions[0];
  }
  std::vector<LookaheadOutcome> outcomes;
  std::vector<std::vector<PersonObservation>> real, predicted;
};

// Walkers at constant velocity: the lookahead predicts the next state exactly, so its reading of
// the action taken is the next step's real reading, ids and estimated velocities included.
TEST_F(PersonTracking, ALookaheadReadsWhatTheRealStepItPredictsReads) {
  const Scenario sc = MakeScenario(MakeMap({}), Vec2(0, -4), Vec2(0, 4),
                                   {{Vec2(2, 0), Vec2(-2, 0)}, {Vec2(-1, 1), Vec2(1, -1)}});
  ReadingProbe robot;
  ConstantVelocityPolicy a(Vec2(-0.6, 0.1)), b(Vec2(0.3, -0.3));
  const auto sensor = Make({{"tracker", std::string("nearest")},
                            {"velocity", std::string("estimated")},
                            {"position_noise", 0.05},
                            {"detection_prob", 0.8},
                            {"false_detections", 0.5}});
  EpisodeAgents agents{&robot, {&a, &b}, {MountedSensor{"person", sensor.get()}}, {}};
  Episode ep(sc, SimConfig{}, agents);
  for (int k = 0; k < 12 && !ep.done(); ++k) ep.Step();
  ASSERT_GE(robot.real.size(), 5u);
  int tracked = 0;
  for (std::size_t s = 0; s + 1 < robot.real.size(); ++s) {
    const auto& next = robot.real[s + 1];
    const auto& guess = robot.predicted[s];
    ASSERT_EQ(next.size(), guess.size()) << s;
    for (std::size_t i = 0; i < next.size(); ++i) {
      EXPECT_EQ(next[i].position, guess[i].position) << s;
      EXPECT_EQ(next[i].velocity, guess[i].velocity) << s;
      EXPECT_EQ(next[i].track_id, guess[i].track_id) << s;
      tracked += next[i].track_id >= 0;
    }
  }
  EXPECT_GT(tracked, 0);
}

TEST_F(PersonTracking, TrackedDetectorsGiveTheSameEpisodesOnAnyThreads) {
  testing::TempDir dir;
  const auto file = dir.Write(
      "track.yaml",
      "name: track\nepisodes: 6\nseed: 4\nworld: {source: random_rect, obstacles: 3}\n"
      "humans: {count: 5, policy: orca}\n"
      "robot: {sensors: [{type: person, fov_deg: 180, occlusion: obstacles+people, "
      "detection_prob: 0.9, position_noise: 0.1, false_detections: 0.5, velocity: estimated, "
      "tracker: nearest}]}\n"
      "rows:\n  - {label: orca, policy: orca}\n  - {label: sarl, policy: sarl}\n");
  const auto runs = testing::RunOnOneAndTwoThreads(file, dir.path());
  EXPECT_EQ(runs[0].episodes, runs[1].episodes);
}

TEST_F(PersonTracking, BadValuesAreRefusedAndDefaultsStayOutOfTheHash) {
  testing::TempDir dir;
  const auto suite = [&](const std::string& person) {
    return dir.Write("s.yaml",
                     "name: s\nepisodes: 1\nworld: {source: random_rect}\n"
                     "robot: {sensors: [" +
                         person + "]}\nrows:\n  - {label: a, policy: orca}\n");
  };
  PluginRegistry registry;
  const auto errors = [&](const std::string& person) {
    std::string all;
    for (const SuiteError& e : LoadSuite(suite(person), registry).errors) all += e.Format() + "\n";
    return all;
  };
  const auto names = [&](const std::string& person, const std::string& key) {
    const std::string e = errors(person);
    return e.find(key) != std::string::npos ? ::testing::AssertionSuccess()
                                            : ::testing::AssertionFailure() << person << ": " << e;
  };
  EXPECT_TRUE(names("{type: person, false_detections: -1}", "false_detections"));
  EXPECT_TRUE(names("{type: person, velocity: measured}", "velocity"));
  EXPECT_TRUE(names("{type: person, velocity: measured}", "estimated"));
  EXPECT_TRUE(names("{type: person, tracker: kalman}", "tracker"));
  EXPECT_TRUE(names("{type: person, tracker: kalman}", "nearest"));
  EXPECT_TRUE(names("{type: person, track_gate: 0}", "track_gate"));
  EXPECT_TRUE(names("{type: person, track_gate: -1}", "track_gate"));
  EXPECT_TRUE(names("{type: person, track_max_gap: -1}", "track_max_gap"));
  EXPECT_EQ(errors("{type: person, velocity: true, tracker: nearest}"), "");
  const auto hash = [&](const std::string& person) {
    return LoadSuite(suite(person), registry).suite->ConfigHash();
  };
  EXPECT_EQ(hash("person"), hash("{type: person, false_detections: 0, velocity: true, tracker: "
                                 "none, track_gate: 1, track_max_gap: 2}"));
  EXPECT_NE(hash("person"), hash("{type: person, tracker: nearest}"));
  EXPECT_NE(hash("person"), hash("{type: person, false_detections: 0.5}"));
}

}  // namespace
}  // namespace crowdsim
