// The state transform, the action space and the networks against hand-worked numbers from
// CrowdNav (reference 1.6-1.9).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <set>

#include "crowdsim/lookahead.h"
#include "value_rl/action_space.h"
#include "value_rl/state_encoding.h"
#include "value_rl/value_policy.h"

namespace crowdsim::value_rl {
namespace {

ValueRlConfig Config(Model model, SensorSet sensors) {
  ValueRlConfig c;
  c.model = model;
  c.sensors = sensors;
  return c;
}

// Robot at (1, 2) heading for (4, 6): rot = atan2(4, 3), cos 0.6, sin 0.8, dg 5.
AgentState Robot() {
  AgentState r;
  r.position = Vec2(1, 2);
  r.goal = Vec2(4, 6);
  r.velocity = Vec2(0.5, -0.5);
  r.radius = 0.3;
  r.v_pref = 1.0;
  r.heading = HeadingToGoal(r);
  return r;
}

// What the person sensor reports for a human at (2, 5) moving at (1, 0), radius 0.25.
PersonObservation Person(const Frame& f) {
  return PersonObservation{f.PointToLocal(Vec2(2, 5)), f.VectorToLocal(Vec2(1, 0)), 0.25};
}

TEST(StateEncodingTest, MatchesRotateByHand) {
  const AgentState robot = Robot();
  const Frame frame = Frame::Make(robot.position, robot.heading);
  SensorReading people;
  people.sensor = "person";
  people.people.push_back(Person(frame));
  const std::vector<SensorReading> readings = {people};
  const EncodedState s =
      EncodeState(Config(Model::kCadrl, SensorSet::kPerson), robot, frame, readings);
  // dg, v_pref, theta, radius, vx, vy | px1, py1, vx1, vy1, radius1, da, radius_sum
  const std::vector<double> expected = {
      5.0, 1.0, 0.0, 0.3, -0.1, -0.7, 3.0, 1.0, 0.6, -0.8, 0.25, std::sqrt(10.0), 0.55};
  ASSERT_EQ(s.values.size(), expected.size());
  for (size_t i = 0; i < expected.size(); ++i) EXPECT_NEAR(s.values[i], expected[i], 1e-6) << i;
}

TEST(StateEncodingTest, LidarIsScaledByMaxRangeBeforeTheHumans) {
  const AgentState robot = Robot();
  const Frame frame = Frame::Make(robot.position, robot.heading);
  ValueRlConfig c = Config(Model::kSarl, SensorSet::kLidarPerson);
  c.lidar_beams = 3;
  SensorReading lidar;
  lidar.sensor = "lidar2d";
  lidar.ranges = {1.0, 5.0, 2.5};
  lidar.max_range = 5.0;
  SensorReading people;
  people.sensor = "person";
  people.people.push_back(Person(frame));
  const std::vector<SensorReading> readings = {lidar, people};
  const EncodedState s = EncodeState(c, robot, frame, readings);
  ASSERT_EQ(s.values.size(), 6u + 3u + 7u);
  EXPECT_FLOAT_EQ(s.values[6], 0.2f);
  EXPECT_FLOAT_EQ(s.values[7], 1.0f);
  EXPECT_FLOAT_EQ(s.values[8], 0.5f);
  EXPECT_NEAR(s.values[9], 3.0, 1e-6);
  EXPECT_EQ(HumanRows(c, s), 1);

  lidar.ranges = {1.0, 2.0};  // the sensor has 2 beams, the policy expects 3
  const std::vector<SensorReading> wrong = {lidar, people};
  EXPECT_THROW(EncodeState(c, robot, frame, wrong), std::runtime_error);
}

TEST(StateEncodingTest, NobodySeenGivesTheFarStandIn) {
  const AgentState robot = Robot();
  const Frame frame = Frame::Make(robot.position, robot.heading);
  SensorReading people;
  people.sensor = "person";
  const std::vector<SensorReading> readings = {people};
  const EncodedState s =
      EncodeState(Config(Model::kCadrl, SensorSet::kPerson), robot, frame, readings);
  ASSERT_EQ(s.values.size(), 13u);
  EXPECT_FLOAT_EQ(s.values[6], -static_cast<float>(kAbsentHumanDistance));
  EXPECT_FLOAT_EQ(s.values[11], static_cast<float>(kAbsentHumanDistance));
  const std::vector<SensorReading> none;
  EXPECT_THROW(EncodeState(Config(Model::kCadrl, SensorSet::kPerson), robot, frame, none),
               std::runtime_error);
}

TEST(StateEncodingTest, RouteJoinsTheSelfStateBeforeTheLidar) {
  const AgentState robot = Robot();
  const Frame frame = Frame::Make(robot.position, robot.heading);
  ValueRlConfig c = Config(Model::kSarl, SensorSet::kLidarPerson);
  c.route = true;
  c.lidar_beams = 2;
  SensorReading lidar;
  lidar.sensor = "lidar2d";
  lidar.ranges = {5.0, 2.5};
  lidar.max_range = 5.0;
  SensorReading route;
  route.sensor = "route";
  route.values = {7.5, 0.6, 0.8};
  SensorReading people;
  people.sensor = "person";
  people.people.push_back(Person(frame));
  // The readings' order is the row's; the layout is the encoder's.
  const std::vector<SensorReading> readings = {people, lidar, route};
  const EncodedState s = EncodeState(c, robot, frame, readings);
  ASSERT_EQ(s.values.size(), 6u + 3u + 2u + 7u);
  EXPECT_NEAR(s.values[0], 5.0, 1e-6);  // dg stays the straight distance
  EXPECT_FLOAT_EQ(s.values[6], 7.5f);
  EXPECT_FLOAT_EQ(s.values[7], 0.6f);
  EXPECT_FLOAT_EQ(s.values[8], 0.8f);
  EXPECT_FLOAT_EQ(s.values[9], 1.0f);
  EXPECT_FLOAT_EQ(s.values[10], 0.5f);
  EXPECT_NEAR(s.values[11], 3.0, 1e-6);
  EXPECT_EQ(SelfInputs(c), 9);
  EXPECT_EQ(HumanRows(c, s), 1);

  route.values = {7.5, 0.6};
  EXPECT_THROW(EncodeState(c, robot, frame, std::vector<SensorReading>{people, lidar, route}),
               std::runtime_error);
  EXPECT_THROW(EncodeState(c, robot, frame, std::vector<SensorReading>{people, lidar}),
               std::runtime_error);
}

TEST(StateEncodingTest, RouteIsASuffixOfTheSensorsParameter) {
  const ParamSchema schema = Schema(Model::kSarl);
  Params params = Params::Defaults(schema);
  params.Set("sensors", std::string("lidar+person+route"));
  const ValueRlConfig c = ConfigFromParams(Model::kSarl, params);
  EXPECT_EQ(c.sensors, SensorSet::kLidarPerson);
  EXPECT_TRUE(c.route);
  EXPECT_EQ(SensorsLabel(c), "lidar+person+route");
  EXPECT_EQ(SensorPlugins(c), (std::vector<std::string>{"lidar2d", "person", "route"}));
  params.Set("sensors", std::string("person"));
  const ValueRlConfig plain = ConfigFromParams(Model::kSarl, params);
  EXPECT_FALSE(plain.route);
  EXPECT_EQ(SensorPlugins(plain), (std::vector<std::string>{"person"}));
}

// A SARL person+route configuration and two of its states that differ only in the route's
// path distance: 5 m and 12 m.
struct RoutedStates {
  RoutedStates() {
    config.route = true;
    config.init_seed = 7;
    // dg, v_pref, theta, radius, vx, vy | route distance, waypoint | one human row.
    near.values = {4.0f, 1.0f, 0.0f, 0.3f, 0.2f, 0.0f, 5.0f, 1.0f,
                   0.0f, 1.0f, 1.0f, 0.0f, 0.0f, 0.3f, 1.4f, 0.6f};
    far = near;
    far.values[6] = 12.0f;
  }
  ValueRlConfig config = Config(Model::kSarl, SensorSet::kPerson);
  EncodedState near, far;
  std::vector<const EncodedState*> states = {&near, &far};
};

TEST(StateEncodingTest, RoutePriorTakesItsShareOfThePathDistanceOffTheValue) {
  const RoutedStates r;
  ValueRlConfig prior = r.config;
  prior.route_prior = 0.05;
  const std::vector<float> without = ValuePolicy(r.config).Values(r.states);
  const std::vector<float> with = ValuePolicy(prior).Values(r.states);
  EXPECT_NEAR(with[0], without[0] - 0.05 * 5.0, 1e-5);
  EXPECT_NEAR(with[1], without[1] - 0.05 * 12.0, 1e-5);
  // The prior needs the route in the state.
  Params params = Params::Defaults(Schema(Model::kSarl));
  params.Set("route_prior", 0.05);
  EXPECT_THROW(ConfigFromParams(Model::kSarl, params), std::invalid_argument);
  params.Set("sensors", std::string("person+route"));
  EXPECT_DOUBLE_EQ(ConfigFromParams(Model::kSarl, params).route_prior, 0.05);
}

TEST(StateEncodingTest, DiscountedRoutePriorAddsTheFreeRoutesDiscountedReward) {
  const RoutedStates r;
  ValueRlConfig prior = r.config;
  prior.route_prior = 1.0;
  prior.route_prior_shape = RoutePriorShape::kDiscounted;
  ValuePolicy with(prior);
  // Untrained, the network's output layer is zero: the value is the prior alone, with
  // SimConfig's gamma (0.9) before any episode.
  std::vector<float> v = with.Values(r.states);
  EXPECT_NEAR(v[0], std::pow(0.9, 5.0), 1e-6);
  EXPECT_NEAR(v[1], std::pow(0.9, 12.0), 1e-6);
  // An episode's gamma replaces it, in the target network too.
  EpisodeContext ctx;
  ctx.sim.gamma = 0.8;
  with.Reset(ctx);
  EXPECT_NEAR(with.Values(r.states)[0], std::pow(0.8, 5.0), 1e-6);
  EXPECT_NEAR(with.TargetValues(r.states)[1], std::pow(0.8, 12.0), 1e-6);
  // gamma 0 is allowed: 0^d, finite (1 at the goal, 0 elsewhere), never NaN.
  ctx.sim.gamma = 0.0;
  with.Reset(ctx);
  EXPECT_EQ(with.Values(r.states)[0], 0.0f);
  EncodedState at_goal = r.near;
  at_goal.values[6] = 0.0f;
  const std::vector<const EncodedState*> goal_state = {&at_goal};
  EXPECT_EQ(with.Values(goal_state)[0], 1.0f);
  ctx.sim.gamma = 0.8;
  with.Reset(ctx);
  // Trained, the network adds its own part on top (the zero layer is a start, not a clamp).
  with.SetLearningRate(0.1, 0.0);
  const std::vector<float> targets = {0.9f, 0.9f};
  with.TrainBatch(r.states, targets);
  EXPECT_GT(with.Values(r.states)[0], std::pow(0.8, 5.0) + 1e-4);
  // The shape is a parameter; without a weight it would do nothing, which is an error.
  Params params = Params::Defaults(Schema(Model::kSarl));
  params.Set("sensors", std::string("lidar+person+route"));
  params.Set("route_prior_shape", std::string("discounted"));
  EXPECT_THROW(ConfigFromParams(Model::kSarl, params), std::invalid_argument);
  params.Set("route_prior", 1.0);
  EXPECT_EQ(ConfigFromParams(Model::kSarl, params).route_prior_shape, RoutePriorShape::kDiscounted);
}

TEST(ActionSpaceTest, ExponentialSpeedsAsCrowdNav) {
  const auto two = ExponentialSpeeds(2, 1.0);
  ASSERT_EQ(two.size(), 2u);
  EXPECT_NEAR(two[0], 0.377541, 1e-6);
  EXPECT_NEAR(two[1], 1.0, 1e-12);
  const auto five = ExponentialSpeeds(5, 2.0);
  const double expected[] = {0.128851, 0.286231, 0.478454, 0.713236, 1.0};
  for (int i = 0; i < 5; ++i) EXPECT_NEAR(five[i], 2.0 * expected[i], 2e-6);
}

TEST(ActionSpaceTest, SixteenActionsRotationOuterSpeedInner) {
  const auto a = BuildActionSpace(2, 8, false, 1.0);
  ASSERT_EQ(a.size(), 16u);
  EXPECT_NEAR(a[0].velocity.x(), 0.377541, 1e-6);
  EXPECT_NEAR(a[0].velocity.y(), 0.0, 1e-12);
  EXPECT_NEAR(a[1].velocity.x(), 1.0, 1e-12);
  const double h = std::sqrt(0.5);
  EXPECT_NEAR(a[2].velocity.x(), 0.377541 * h, 1e-6);
  EXPECT_NEAR(a[2].velocity.y(), 0.377541 * h, 1e-6);
  EXPECT_NEAR(a[5].velocity.x(), 0.0, 1e-12);  // 90 degrees, fast
  EXPECT_NEAR(a[5].velocity.y(), 1.0, 1e-12);
  EXPECT_NEAR(a[15].velocity.x(), h, 1e-12);  // 315 degrees, fast
  EXPECT_NEAR(a[15].velocity.y(), -h, 1e-12);
  const auto with_stop = BuildActionSpace(2, 8, true, 1.0);
  ASSERT_EQ(with_stop.size(), 17u);
  EXPECT_EQ(with_stop[0].velocity, Vec2::Zero());
  EXPECT_EQ(with_stop[1].velocity, a[0].velocity);
}

TEST(ActionSpaceTest, UnicycleActionsAreCrowdNavsRotationsAsCommands) {
  // Stop, then rotations linspace(-pi/4, pi/4, 7) outer, speeds inner; dt 0.25 s.
  const auto a = BuildUnicycleActionSpace(2, 7, true, 1.0, 0.25);
  ASSERT_EQ(a.size(), 15u);
  for (const Action& action : a) EXPECT_TRUE(action.command);
  EXPECT_EQ(a[0].linear, 0.0);
  EXPECT_EQ(a[0].angular, 0.0);
  EXPECT_NEAR(a[1].linear, 0.377541, 1e-6);
  EXPECT_NEAR(a[1].angular * 0.25, -std::numbers::pi / 4, 1e-12);
  EXPECT_NEAR(a[2].linear, 1.0, 1e-12);
  EXPECT_NEAR(a[7].angular, 0.0, 1e-12);  // the middle rotation: straight on
  EXPECT_NEAR(a[14].angular * 0.25, std::numbers::pi / 4, 1e-12);
  const auto straight = BuildUnicycleActionSpace(2, 1, false, 1.0, 0.25);
  ASSERT_EQ(straight.size(), 2u);
  EXPECT_EQ(straight[1].angular, 0.0);
}

TEST(ValueNetworkTest, ParameterCountsAsCrowdNav) {
  EXPECT_EQ(ValuePolicy(Config(Model::kCadrl, SensorSet::kPerson)).ParameterCount(), 27401);
  EXPECT_EQ(ValuePolicy(Config(Model::kSarl, SensorSet::kPerson)).ParameterCount(), 96502);
  // The lidar encoder (45 -> 64 -> 32) and its 32 extra inputs of the first layer.
  const int64_t encoder = 45 * 64 + 64 + 64 * 32 + 32;
  EXPECT_EQ(ValuePolicy(Config(Model::kCadrl, SensorSet::kLidarPerson)).ParameterCount(),
            27401 + encoder + 32 * 150);
  EXPECT_EQ(ValuePolicy(Config(Model::kSarl, SensorSet::kLidar)).ParameterCount(),
            encoder + (38 * 150 + 150) + (150 * 100 + 100) + (100 * 100 + 100) + 101);
  // +route: 3 more self inputs, in the self MLP of SARL's humans and in its value MLP.
  ValueRlConfig routed = Config(Model::kSarl, SensorSet::kLidarPerson);
  const int64_t plain = ValuePolicy(routed).ParameterCount();
  routed.route = true;
  EXPECT_EQ(ValuePolicy(routed).ParameterCount(), plain + 3 * 150 + 3 * 150);
}

/// Encodes one state with `n` humans spread around the robot.
EncodedState StateWith(int n, float shift) {
  EncodedState s;
  s.values = {4.0f, 1.0f, 0.0f, 0.3f, 0.5f + shift, -0.2f};
  for (int i = 0; i < n; ++i) {
    const float x = 1.0f + i + shift, y = -1.0f + 0.5f * i;
    s.values.insert(s.values.end(), {x, y, 0.3f, -0.1f, 0.3f, std::sqrt(x * x + y * y), 0.6f});
  }
  return s;
}

TEST(ValueNetworkTest, PaddedBatchEqualsOneByOne) {
  for (Model model : {Model::kCadrl, Model::kSarl}) {
    ValuePolicy policy(Config(model, SensorSet::kPerson));
    const std::vector<EncodedState> states = {StateWith(1, 0.0f), StateWith(5, 0.1f),
                                              StateWith(3, 0.2f)};
    std::vector<const EncodedState*> all;
    for (const auto& s : states) all.push_back(&s);
    const std::vector<float> batch = policy.Values(all);
    for (size_t i = 0; i < states.size(); ++i) {
      const EncodedState* one[] = {&states[i]};
      EXPECT_NEAR(policy.Values(one)[0], batch[i], 1e-5) << ModelName(model) << " state " << i;
    }
  }
}

/// A lookahead whose outcomes all look alike except for their rewards.
class FixedLookahead final : public Lookahead {
 public:
  explicit FixedLookahead(std::vector<double> rewards, std::vector<StepEvent> events = {})
      : rewards_(std::move(rewards)), events_(std::move(events)) {}
  std::span<const AgentState> NextHumans() const override { return {}; }
  void Evaluate(std::span<const Action> actions,
                std::vector<LookaheadOutcome>* out) const override {
    out->assign(actions.size(), LookaheadOutcome{});
    for (size_t k = 0; k < actions.size(); ++k) {
      LookaheadOutcome& o = (*out)[k];
      o.robot = Robot();
      o.frame = Frame::Make(o.robot.position, o.robot.heading);
      SensorReading people;
      people.sensor = "person";
      o.readings = {people};
      o.reward = k < rewards_.size() ? rewards_[k] : 0.0;
      o.event = k < events_.size() ? events_[k] : StepEvent::kNone;
    }
  }

 private:
  std::vector<double> rewards_;
  std::vector<StepEvent> events_;
};

TEST(ValuePolicyTest, PicksTheBestRewardAndTiesGoToTheEarliest) {
  ValuePolicy policy(Config(Model::kSarl, SensorSet::kPerson));
  EpisodeContext ctx;
  policy.Reset(ctx);
  Observation obs;
  obs.self = Robot();
  const auto actions = BuildActionSpace(2, 8, false, 1.0);

  FixedLookahead best_is_7(std::vector<double>{0, 0, 0, 0, 0, 0, 0, 0.5});
  obs.lookahead = &best_is_7;
  EXPECT_EQ(policy.Decide(obs).velocity, actions[7].velocity);
  ASSERT_EQ(policy.last_action_values().size(), 16u);
  EXPECT_NEAR(policy.last_action_values()[7] - policy.last_action_values()[0], 0.5, 1e-6);

  // Identical candidates are valued through different batch rows, whose last bits differ on
  // some CPUs' BLAS kernels: they still tie, and the tie goes to the earliest action.
  FixedLookahead all_equal({});
  obs.lookahead = &all_equal;
  EXPECT_EQ(policy.Decide(obs).velocity, actions[0].velocity);
  // A real difference above the tie tolerance still wins.
  FixedLookahead best_is_3(std::vector<double>{0, 0, 0, 1e-3});
  obs.lookahead = &best_is_3;
  EXPECT_EQ(policy.Decide(obs).velocity, actions[3].velocity);

  obs.lookahead = nullptr;
  EXPECT_THROW(policy.Decide(obs), std::runtime_error);
}

TEST(ValuePolicyTest, CollisionFreeExplorationDrawsOnlyActionsThatDoNotCollide) {
  ValuePolicy policy(Config(Model::kCadrl, SensorSet::kPerson));
  policy.Reset(EpisodeContext{});
  Observation obs;
  obs.self = Robot();
  const auto actions = BuildActionSpace(2, 8, false, 1.0);
  // Every action but 5 and 12 runs into something.
  std::vector<StepEvent> events(16, StepEvent::kCollisionObstacle);
  events[3] = StepEvent::kCollisionHuman;
  events[5] = StepEvent::kNone;
  events[12] = StepEvent::kDanger;
  FixedLookahead walls({}, events);
  obs.lookahead = &walls;
  const auto draws = [&](bool avoid) {
    policy.SetExploration(Exploration{1.0, 7, avoid});
    std::set<size_t> seen;
    for (int i = 0; i < 200; ++i) {
      const Vec2 v = policy.Decide(obs).velocity;
      for (size_t k = 0; k < actions.size(); ++k)
        if (actions[k].velocity == v) seen.insert(k);
    }
    return seen;
  };
  EXPECT_EQ(draws(true), (std::set<size_t>{5, 12}));
  EXPECT_GT(draws(false).size(), 10u);  // uniform: nearly all 16 in 200 draws
  // When every action collides there is nothing to avoid: any action.
  FixedLookahead boxed_in({}, std::vector<StepEvent>(16, StepEvent::kCollisionObstacle));
  obs.lookahead = &boxed_in;
  EXPECT_GT(draws(true).size(), 10u);
  // Greedy decisions (epsilon 0) are not affected by the rule.
  policy.SetExploration(Exploration{0.0, 7, true});
  FixedLookahead best_is_3(std::vector<double>{0, 0, 0, 0.5}, events);
  obs.lookahead = &best_is_3;
  EXPECT_EQ(policy.Decide(obs).velocity, actions[3].velocity);
}

TEST(ValuePolicyTest, NeedsLookaheadAndItsSensors) {
  const PolicyNeeds needs = ValuePolicy(Config(Model::kCadrl, SensorSet::kLidarPerson)).Needs();
  EXPECT_TRUE(needs.lookahead);
  EXPECT_EQ(needs.sensors, (std::vector<std::string>{"lidar2d", "person"}));
  EXPECT_EQ(ValuePolicy(Config(Model::kCadrl, SensorSet::kLidar)).Needs().sensors,
            std::vector<std::string>{"lidar2d"});
}

}  // namespace
}  // namespace crowdsim::value_rl
