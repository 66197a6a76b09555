// The episode loop on scripted episodes: outcomes, timing, metrics and the lookahead.
#include "crowdsim/bench/episode.h"

#include <gtest/gtest.h>

#include <cmath>
#include <utility>
#include <vector>

#include "scripted.h"

namespace crowdsim {
namespace {

using testing::ConstantVelocityPolicy;
using testing::GoStraightPolicy;
using testing::MakeMap;
using testing::MakeRoom;
using testing::MakeScenario;

TEST(Episode, StraightRunSucceedsAtTheExpectedTime) {
  const Scenario sc = MakeScenario(MakeMap({}), Vec2(0, -4), Vec2(0, 4));
  GoStraightPolicy robot;
  EpisodeAgents agents{&robot, {}, {}, {}};
  Episode ep(sc, SimConfig{}, agents, /*record_trajectory=*/true);
  const EpisodeResult& r = ep.Run();
  EXPECT_EQ(r.status, EpisodeStatus::kSuccess);
  // 8 m at 1 m/s, 0.25 s steps: after 31 steps it is 0.25 m short (> 0.2 m goal radius),
  // the 32nd step ends on the goal.
  EXPECT_EQ(r.steps, 32);
  EXPECT_DOUBLE_EQ(r.time, 8.0);
  EXPECT_NEAR(r.path_length, 8.0, 1e-9);
  EXPECT_EQ(r.min_human_distance, kInfinity);
  EXPECT_EQ(r.danger_steps, 0);
  // +1 on step index 31: gamma^(31 * 0.25 * 1).
  EXPECT_NEAR(r.discounted_return, std::pow(0.9, 31 * 0.25), 1e-12);
  ASSERT_EQ(r.trajectory.size(), 33u);
  EXPECT_DOUBLE_EQ(r.trajectory.back().time, 8.0);
}

/// Needs with only `map` or only `heading_frame` set.
PolicyNeeds NeedsMap(bool map) {
  PolicyNeeds needs;
  needs.map = map;
  return needs;
}
PolicyNeeds NeedsHeadingFrame(bool heading_frame) {
  PolicyNeeds needs;
  needs.heading_frame = heading_frame;
  return needs;
}

/// Declares the needs it is given; records what Reset handed it and the frame of its last
/// observation.
class RecordingPolicy final : public Policy {
 public:
  explicit RecordingPolicy(PolicyNeeds needs) : needs_(std::move(needs)) {}
  PolicyNeeds Needs() const override { return needs_; }
  void Reset(const EpisodeContext& ctx) override {
    map = ctx.map;
    time_step = ctx.sim.time_step;
  }
  Action Decide(const Observation& obs) override {
    frame = obs.frame;
    position = obs.self.position;
    return Action{Vec2::Zero()};
  }
  const StaticMap* map = nullptr;
  double time_step = 0.0;  ///< 0 until Reset
  Frame frame;
  Vec2 position = Vec2::Zero();

 private:
  PolicyNeeds needs_;
};

// The episode's constants reach a policy through Reset alone, and the map only where
// Needs().map asks for it (robot and humans alike).
TEST(Episode, ResetGivesTheMapOnlyToPoliciesThatNeedIt) {
  const Scenario sc = MakeScenario(MakeRoom(), Vec2(0, -4), Vec2(0, 4),
                                   {{Vec2(-3, 0), Vec2(3, 0)}, {Vec2(3, 2), Vec2(-3, 2)}});
  SimConfig sim;
  sim.time_step = 0.1;
  for (const bool robot_wants : {false, true}) {
    RecordingPolicy robot(NeedsMap(robot_wants)), blind(NeedsMap(false)), seeing(NeedsMap(true));
    EpisodeAgents agents{&robot, {&blind, &seeing}, {}, {}};
    Episode ep(sc, sim, agents);
    EXPECT_EQ(robot.map, robot_wants ? sc.map.get() : nullptr);
    EXPECT_EQ(blind.map, nullptr);
    EXPECT_EQ(seeing.map, sc.map.get());
    EXPECT_DOUBLE_EQ(robot.time_step, 0.1);
    EXPECT_DOUBLE_EQ(blind.time_step, 0.1);
  }
}

TEST(Episode, GoalRadiusIsConfigurable) {
  const Scenario sc = MakeScenario(MakeMap({}), Vec2(0, -4), Vec2(0, 4));
  ConstantVelocityPolicy robot(Vec2(0, 1.0));  // overshoots when not stopped
  EpisodeAgents agents{&robot, {}, {}, {}};
  SimConfig crowdnav;
  crowdnav.goal_radius = 0.3;  // CrowdNav: within the robot radius
  Episode ep(sc, crowdnav, agents);
  // After 31 steps the end position is 0.25 m short: inside 0.3, so success one step earlier.
  EXPECT_EQ(ep.Run().status, EpisodeStatus::kSuccess);
  EXPECT_EQ(ep.result().steps, 31);
}

TEST(Episode, TimeoutAfterTimeLimit) {
  const Scenario sc = MakeScenario(MakeMap({}), Vec2(0, -4), Vec2(0, 4));
  ConstantVelocityPolicy robot(Vec2(0, 0));
  EpisodeAgents agents{&robot, {}, {}, {}};
  Episode ep(sc, SimConfig{}, agents);
  const EpisodeResult& r = ep.Run();
  EXPECT_EQ(r.status, EpisodeStatus::kTimeout);
  EXPECT_EQ(r.steps, 100);
  EXPECT_DOUBLE_EQ(r.time, 25.0);
  EXPECT_DOUBLE_EQ(r.discounted_return, 0.0);
}

TEST(Episode, ThinWallAtHighSpeedIsACollisionNotATunnel) {
  // A 2 cm wall; the robot moves 2.5 m per step, far more than wall + diameter.
  const Scenario sc =
      MakeScenario(MakeMap({Rect::FromCorners(-3, -0.01, 3, 0.01)}), Vec2(0, -1), Vec2(0, 4));
  ConstantVelocityPolicy robot(Vec2(0, 10.0));
  EpisodeAgents agents{&robot, {}, {}, {}};
  Episode ep(sc, SimConfig{}, agents);
  const EpisodeResult& r = ep.Run();
  EXPECT_EQ(r.status, EpisodeStatus::kCollisionObstacle);
  EXPECT_EQ(r.steps, 1);
  EXPECT_NEAR(r.discounted_return, -0.25, 1e-12);
}

TEST(Episode, RoomWallsStopTheRobot) {
  const Scenario sc = MakeScenario(MakeRoom(), Vec2(0, 0), Vec2(0, 4));
  ConstantVelocityPolicy robot(Vec2(1.0, 0));  // walks into the east wall at x = 5
  EpisodeAgents agents{&robot, {}, {}, {}};
  Episode ep(sc, SimConfig{}, agents);
  const EpisodeResult& r = ep.Run();
  EXPECT_EQ(r.status, EpisodeStatus::kCollisionObstacle);
  // Contact when x + 0.3 >= 5: during step 19 (x from 4.5 to 4.75).
  EXPECT_EQ(r.steps, 19);
}

TEST(Episode, SweptHumanCollisionCatchesAPassThrough) {
  // A still human on the robot's path; the robot jumps 2.5 m per step: an end-of-step
  // overlap test would miss it, CrowdNav's swept test does not.
  const Scenario sc =
      MakeScenario(MakeMap({}), Vec2(0, -4), Vec2(0, 4), {{Vec2(0, -2.75), Vec2(0, -2.75)}});
  ConstantVelocityPolicy robot(Vec2(0, 10.0));
  ConstantVelocityPolicy still(Vec2(0, 0));
  EpisodeAgents agents{&robot, {&still}, {}, {}};
  Episode ep(sc, SimConfig{}, agents);
  EXPECT_EQ(ep.Run().status, EpisodeStatus::kCollisionHuman);
  EXPECT_EQ(ep.result().steps, 1);
}

TEST(Episode, ACollisionNamesWhatWasHit) {
  ConstantVelocityPolicy robot(Vec2(0, 10.0));
  ConstantVelocityPolicy still(Vec2(0, 0));
  {  // The second of two still humans stands on the path.
    const Scenario sc = MakeScenario(MakeMap({}), Vec2(0, -4), Vec2(0, 4),
                                     {{Vec2(3, 0), Vec2(3, 0)}, {Vec2(0, -2.75), Vec2(0, -2.75)}});
    Episode ep(sc, SimConfig{}, EpisodeAgents{&robot, {&still, &still}, {}, {}});
    const EpisodeResult& r = ep.Run();
    ASSERT_EQ(r.status, EpisodeStatus::kCollisionHuman);
    EXPECT_EQ(r.collided_human, 1);
    EXPECT_EQ(r.collided_rect, -1);
  }
  {  // The second rectangle is the thin wall across the path.
    const Scenario sc = MakeScenario(
        MakeMap({Rect::FromCorners(5, 5, 6, 6), Rect::FromCorners(-3, -0.01, 3, 0.01)}),
        Vec2(0, -1), Vec2(0, 4));
    Episode ep(sc, SimConfig{}, EpisodeAgents{&robot, {}, {}, {}});
    const EpisodeResult& r = ep.Run();
    ASSERT_EQ(r.status, EpisodeStatus::kCollisionObstacle);
    EXPECT_EQ(r.collided_rect, 1);
    EXPECT_EQ(r.collided_human, -1);
  }
  {  // Nothing hit: both stay -1.
    ConstantVelocityPolicy slow(Vec2(0, 1.0));
    const Scenario sc = MakeScenario(MakeMap({}), Vec2(0, -1), Vec2(0, 1));
    Episode ep(sc, SimConfig{}, EpisodeAgents{&slow, {}, {}, {}});
    const EpisodeResult& r = ep.Run();
    ASSERT_EQ(r.status, EpisodeStatus::kSuccess);
    EXPECT_EQ(r.collided_human, -1);
    EXPECT_EQ(r.collided_rect, -1);
  }
}

TEST(Episode, DangerStepsAndDiscomfortReward) {
  // The robot passes a still human at 0.7 m centre distance: 0.1 m surface gap < 0.2.
  const Scenario sc =
      MakeScenario(MakeMap({}), Vec2(0, -4), Vec2(0, 4), {{Vec2(0.7, 0.0), Vec2(0.7, 0.0)}});
  ConstantVelocityPolicy robot(Vec2(0, 1.0));
  ConstantVelocityPolicy still(Vec2(0, 0));
  EpisodeAgents agents{&robot, {&still}, {}, {}};
  Episode ep(sc, SimConfig{}, agents);
  double min_reward = 0.0;
  int danger = 0;
  while (!ep.done()) {
    const StepInfo info = ep.Step();
    if (info.event == StepEvent::kDanger) {
      ++danger;
      EXPECT_NEAR(info.reward, (info.min_human_distance - 0.2) * 0.5 * 0.25, 1e-12);
      min_reward = std::min(min_reward, info.reward);
    }
  }
  EXPECT_EQ(ep.result().status, EpisodeStatus::kSuccess);
  EXPECT_EQ(ep.result().danger_steps, danger);
  EXPECT_GT(danger, 0);
  EXPECT_NEAR(ep.result().min_human_distance, 0.1, 1e-9);
  EXPECT_NEAR(min_reward, (0.1 - 0.2) * 0.5 * 0.25, 1e-12);
}

class CountingThrowPolicy final : public Policy {
 public:
  Action Decide(const Observation&) override {
    if (++calls_ == 3) throw std::runtime_error("boom");
    return Action{Vec2(0, 0.5)};
  }

 private:
  int calls_ = 0;
};

TEST(Episode, PolicyExceptionEndsEpisodeWithPolicyError) {
  const Scenario sc = MakeScenario(MakeMap({}), Vec2(0, -4), Vec2(0, 4));
  CountingThrowPolicy robot;
  EpisodeAgents agents{&robot, {}, {}, {}};
  Episode ep(sc, SimConfig{}, agents);
  const EpisodeResult& r = ep.Run();
  EXPECT_EQ(r.status, EpisodeStatus::kPolicyError);
  EXPECT_EQ(r.steps, 2);
  // Whose policy failed, as for a human's (the plugin's own message said only "boom").
  EXPECT_EQ(r.error, "the robot's policy failed: boom");
}

// A failing human policy or sensor ends the episode as policy_error too, but its message says
// who failed (it read as if the robot's policy had).
TEST(Episode, AFailingHumanPolicyOrSensorIsNamedInTheError) {
  const Scenario sc = MakeScenario(MakeMap({}), Vec2(0, -4), Vec2(0, 4),
                                   {{Vec2(-3, 0), Vec2(3, 0)}, {Vec2(3, 2), Vec2(-3, 2)}});
  ConstantVelocityPolicy robot(Vec2(0, 0.5));
  ConstantVelocityPolicy walking(Vec2(1.0, 0));
  CountingThrowPolicy failing;
  EpisodeAgents humans_fail{&robot, {&walking, &failing}, {}, {}};
  Episode ep(sc, SimConfig{}, humans_fail);
  EXPECT_EQ(ep.Run().status, EpisodeStatus::kPolicyError);
  EXPECT_EQ(ep.result().steps, 2);
  EXPECT_EQ(ep.result().error, "human 1's policy failed: boom");

  class FailingSensor final : public Sensor {
   public:
    void Sense(const SenseInput&, SensorReading*) const override { throw 42; }
  };
  FailingSensor sensor;
  EpisodeAgents sensor_fails{&robot, {&walking, &walking}, {{"eyes", &sensor}}, {}};
  Episode blind(sc, SimConfig{}, sensor_fails);
  EXPECT_EQ(blind.Run().status, EpisodeStatus::kPolicyError);
  EXPECT_EQ(blind.result().error.rfind("sensor 'eyes' failed: threw an exception not derived", 0),
            0u)
      << blind.result().error;
}

TEST(Episode, NonFiniteActionIsAPolicyError) {
  const Scenario sc = MakeScenario(MakeMap({}), Vec2(0, -4), Vec2(0, 4));
  ConstantVelocityPolicy robot(Vec2(std::nan(""), 0));
  EpisodeAgents agents{&robot, {}, {}, {}};
  Episode ep(sc, SimConfig{}, agents);
  EXPECT_EQ(ep.Run().status, EpisodeStatus::kPolicyError);
  EXPECT_NE(ep.result().error.find("non-finite"), std::string::npos);
}

TEST(Episode, AVelocityFarAboveVPrefIsAPolicyError) {
  // 1e300 m/s: a unit bug, not a move (it used to cross the map in one step unjudged).
  const Scenario sc = MakeScenario(MakeRoom(), Vec2(0, -4), Vec2(0, 4));
  ConstantVelocityPolicy robot(Vec2(0, 1e300));
  EpisodeAgents agents{&robot, {}, {}, {}};
  Episode ep(sc, SimConfig{}, agents);
  EXPECT_EQ(ep.Run().status, EpisodeStatus::kPolicyError);
  EXPECT_NE(ep.result().error.find("more than 10 x v_pref"), std::string::npos)
      << ep.result().error;
  // Just above the limit, the message shows the digits that tell the two apart.
  ConstantVelocityPolicy barely(Vec2(0, 10.000001));
  EpisodeAgents barely_agents{&barely, {}, {}, {}};
  Episode over(sc, SimConfig{}, barely_agents);
  EXPECT_EQ(over.Run().status, EpisodeStatus::kPolicyError);
  EXPECT_NE(over.result().error.find("returned 10.000001 m/s, more than 10 x v_pref (10 m/s)"),
            std::string::npos)
      << over.result().error;
  // 10 x v_pref itself is allowed (the thin-wall test moves at it).
  ConstantVelocityPolicy fast(Vec2(0, 10.0));
  EpisodeAgents fast_agents{&fast, {}, {}, {}};
  Episode ok(sc, SimConfig{}, fast_agents);
  EXPECT_NE(ok.Run().status, EpisodeStatus::kPolicyError);
}

TEST(Episode, AHumanFarAboveVPrefIsAPolicyErrorNamingTheHuman) {
  const Scenario sc = MakeScenario(MakeMap({}), Vec2(0, -4), Vec2(0, 4),
                                   {{Vec2(-3, 0), Vec2(3, 0)}, {Vec2(3, 2), Vec2(-3, 2)}});
  ConstantVelocityPolicy robot(Vec2(0, 1.0));
  ConstantVelocityPolicy walking(Vec2(1.0, 0));
  ConstantVelocityPolicy runaway(Vec2(-1e3, 0));
  EpisodeAgents agents{&robot, {&walking, &runaway}, {}, {}};
  Episode ep(sc, SimConfig{}, agents);
  EXPECT_EQ(ep.Run().status, EpisodeStatus::kPolicyError);
  EXPECT_EQ(ep.result().error.rfind("human 1's policy returned 1000 m/s, more than 10 x v_pref", 0),
            0u)
      << ep.result().error;
}

// When two humans fail in one step, the error is the lower index's, also in a crowd large
// enough for the neighbour grid, whose order (human i stands at x = 19 - 2i) is the reverse
// of the index order: a guard for any change of the order of decisions.
TEST(Episode, InALargeCrowdTheLowestFailingHumanIsReported) {
  std::vector<std::pair<Vec2, Vec2>> starts_goals;
  for (int i = 0; i < 20; ++i) {
    const double x = 19.0 - 2.0 * i;
    starts_goals.push_back({Vec2(x, 0), Vec2(x, 10)});
  }
  const Scenario sc = MakeScenario(MakeMap({}), Vec2(0.5, -6), Vec2(0.5, -2), starts_goals);
  ConstantVelocityPolicy robot(Vec2(0, 1.0));
  ConstantVelocityPolicy walking(Vec2(0, 1.0));
  ConstantVelocityPolicy runaway(Vec2(0, 1e3));
  EpisodeAgents agents{&robot, {}, {}, {}};
  for (int i = 0; i < 20; ++i) agents.humans.push_back(i == 3 || i == 15 ? &runaway : &walking);
  Episode ep(sc, SimConfig{}, agents);
  EXPECT_EQ(ep.Run().status, EpisodeStatus::kPolicyError);
  EXPECT_EQ(ep.result().error.rfind("human 3's policy returned 1000 m/s", 0), 0u)
      << ep.result().error;
}

// A human's frame turns towards its goal unless its policy declines the heading frame: then
// it is world-aligned at the human (the robot's frame turns in either case).
TEST(Episode, AHumanPolicyWithoutHeadingFrameGetsTheWorldAlignedFrame) {
  const Scenario sc = MakeScenario(MakeMap({}), Vec2(0, -4), Vec2(0, 4),
                                   {{Vec2(-3, 0), Vec2(-3, 3)}, {Vec2(3, 2), Vec2(3, 5)}});
  ConstantVelocityPolicy robot(Vec2(0, 1.0));
  RecordingPolicy turned(NeedsHeadingFrame(true)), world(NeedsHeadingFrame(false));
  EpisodeAgents agents{&robot, {&turned, &world}, {}, {}};
  Episode ep(sc, SimConfig{}, agents);
  ep.Step();
  EXPECT_NEAR(turned.frame.heading, std::acos(0.0), 1e-12);  // goal straight up: +y
  EXPECT_NEAR(turned.frame.cos_h, 0.0, 1e-12);
  EXPECT_NEAR(turned.frame.sin_h, 1.0, 1e-12);
  EXPECT_EQ(world.frame.heading, 0.0);
  EXPECT_EQ(world.frame.cos_h, 1.0);
  EXPECT_EQ(world.frame.sin_h, 0.0);
  EXPECT_EQ(world.frame.origin, world.position);
  EXPECT_EQ(turned.frame.origin, turned.position);
}

/// Moves at a fixed velocity and logs the frame and heading of every observation.
class FrameLog final : public Policy {
 public:
  explicit FrameLog(Vec2 v) : v_(v) {}
  Action Decide(const Observation& obs) override {
    frames.push_back(obs.frame);
    headings.push_back(obs.self.heading);
    return Action{v_};
  }
  std::vector<Frame> frames;
  std::vector<double> headings;

 private:
  Vec2 v_;
};

/// Asks for the whole history (the episode then keeps a frame a step) and reads nothing.
class HistorySensor final : public Sensor {
 public:
  void Sense(const SenseInput&, SensorReading*) const override {}
  int HistorySteps() const override { return -1; }
};

// The robot's frames come from the history's record when one is kept: the very frames and
// headings of an episode that keeps none, step after step, over two episodes of a thread (the
// second reuses the first's frames).
TEST(Episode, KeepingAHistoryChangesNoFrameTheRobotSees) {
  const Scenario sc =
      MakeScenario(MakeMap({}), Vec2(0, -4), Vec2(0, 4), {{Vec2(-3, 0), Vec2(-3, 3)}});
  const HistorySensor history;
  std::vector<FrameLog> logs;
  for (const int episode : {0, 1, 2}) {
    FrameLog robot(Vec2(0.4, 0.5));  // off the goal's line: the heading turns every step
    ConstantVelocityPolicy human(Vec2(0, 0.5));
    EpisodeAgents agents{&robot, {&human}, {}, {}};
    if (episode > 0) agents.sensors.push_back(MountedSensor{"history", &history});
    Episode(sc, SimConfig{}, agents).Run();
    logs.push_back(robot);
  }
  ASSERT_GT(logs[0].frames.size(), 5u);
  for (const int episode : {1, 2}) {
    const FrameLog& kept = logs[static_cast<std::size_t>(episode)];
    ASSERT_EQ(kept.frames.size(), logs[0].frames.size());
    for (std::size_t k = 0; k < kept.frames.size(); ++k) {
      EXPECT_EQ(kept.frames[k].origin, logs[0].frames[k].origin) << k;
      EXPECT_EQ(kept.frames[k].heading, logs[0].frames[k].heading) << k;
      EXPECT_EQ(kept.frames[k].cos_h, logs[0].frames[k].cos_h) << k;
      EXPECT_EQ(kept.frames[k].sin_h, logs[0].frames[k].sin_h) << k;
      EXPECT_EQ(kept.headings[k], logs[0].headings[k]) << k;
    }
  }
  EXPECT_NE(logs[0].frames.front().heading, logs[0].frames.back().heading);
}

TEST(Episode, MeaninglessScenariosAreRefusedWithTheReason) {
  GoStraightPolicy robot;
  EpisodeAgents agents{&robot, {}, {}, {}};
  auto refused = [&](const Scenario& sc) -> std::string {
    try {
      Episode ep(sc, SimConfig{}, agents);
    } catch (const std::invalid_argument& e) {
      return e.what();
    }
    return "";
  };
  const auto room = MakeRoom({Rect::FromCorners(-1, -1, 1, 1)});
  EXPECT_NE(refused(MakeScenario(room, Vec2(0, 0), Vec2(0, 4)))
                .find("start (0.000, 0.000) lies inside obstacle 4"),
            std::string::npos)
      << refused(MakeScenario(room, Vec2(0, 0), Vec2(0, 4)));
  EXPECT_NE(refused(MakeScenario(room, Vec2(0, -4), Vec2(0.5, 0.5)))
                .find("goal (0.500, 0.500) lies inside obstacle"),
            std::string::npos);
  EXPECT_NE(refused(MakeScenario(room, Vec2(3, -4), Vec2(3, -3.9))).find("starts at its goal"),
            std::string::npos);
  EXPECT_NE(refused(MakeScenario(room, Vec2(0, -40), Vec2(0, 4))).find("outside the map"),
            std::string::npos);
  EXPECT_EQ(refused(MakeScenario(room, Vec2(3, -4), Vec2(3, 4))), "");
  // A disc that starts overlapping an obstacle (its centre outside) collides at once: refused,
  // the robot's and a human's alike; within a millimetre (the floor plans' rounding) it is not.
  EXPECT_NE(refused(MakeScenario(room, Vec2(1.2, 0), Vec2(3, 4)))
                .find("the robot's start (1.200, 0.000) is 0.200 m from obstacle 4, less than its "
                      "radius 0.300 m"),
            std::string::npos)
      << refused(MakeScenario(room, Vec2(1.2, 0), Vec2(3, 4)));
  EXPECT_EQ(refused(MakeScenario(room, Vec2(1.2995, 0), Vec2(3, 4))), "");
  const Scenario human_inside =
      MakeScenario(room, Vec2(3, -4), Vec2(3, 4), {{Vec2(0.2, 0.2), Vec2(3, 0)}});
  ConstantVelocityPolicy still(Vec2::Zero());
  EpisodeAgents with_human{&robot, {&still}, {}, {}};
  try {
    Episode ep(human_inside, SimConfig{}, with_human);
    ADD_FAILURE() << "a human starting inside an obstacle was accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(
        std::string(e.what()).find("human 0's start (0.200, 0.200) is 0.000 m from obstacle 4"),
        std::string::npos)
        << e.what();
  }
}

TEST(Episode, AWorldThatPlacesFewerHumansThanAskedIsRefused) {
  ScenarioRequest request;
  request.num_humans = 3;
  const Scenario one =
      MakeScenario(MakeRoom(), Vec2(3, -4), Vec2(3, 4), {{Vec2(-3, 0), Vec2(3, 0)}});
  try {
    CheckHumanCount(request, one);
    ADD_FAILURE() << "1 human for 3 was accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("the world made 1 human(s) where 3 were asked for"),
              std::string::npos)
        << e.what();
  }
  request.num_humans = 1;
  EXPECT_NO_THROW(CheckHumanCount(request, one));
}

/// Records what the lookahead predicts for its own action and the others.
class LookaheadProbe final : public Policy {
 public:
  PolicyNeeds Needs() const override { return {.map = false, .lookahead = true, .sensors = {}}; }
  Action Decide(const Observation& obs) override {
    const std::vector<Action> actions = {Action{Vec2(0, 1)}, Action{Vec2(1, 0)},
                                         Action{Vec2(0, 20)}};
    obs.lookahead->Evaluate(actions, &outcomes);
    next_humans.assign(obs.lookahead->NextHumans().begin(), obs.lookahead->NextHumans().end());
    return actions[0];
  }
  std::vector<LookaheadOutcome> outcomes;
  std::vector<AgentState> next_humans;
};

TEST(Episode, LookaheadPredictsTheRealStep) {
  const Scenario sc =
      MakeScenario(MakeMap({}), Vec2(0, -4), Vec2(0, 4), {{Vec2(2, 0), Vec2(-2, 0)}});
  LookaheadProbe robot;
  ConstantVelocityPolicy walker(Vec2(-1, 0));
  EpisodeAgents agents{&robot, {&walker}, {}, {}};
  Episode ep(sc, SimConfig{}, agents);
  const StepInfo info = ep.Step();
  ASSERT_EQ(robot.outcomes.size(), 3u);
  EXPECT_EQ(robot.outcomes[0].event, info.event);
  EXPECT_DOUBLE_EQ(robot.outcomes[0].reward, info.reward);
  EXPECT_TRUE(robot.outcomes[0].robot.position.isApprox(ep.robot().position));
  ASSERT_EQ(robot.next_humans.size(), 1u);
  EXPECT_TRUE(robot.next_humans[0].position.isApprox(ep.humans()[0].position));
  EXPECT_TRUE(robot.next_humans[0].velocity.isApprox(ep.humans()[0].velocity));
  // 20 m/s for 0.25 s overshoots the goal region entirely: no success, no collision.
  EXPECT_EQ(robot.outcomes[2].event, StepEvent::kNone);
}

}  // namespace
}  // namespace crowdsim
