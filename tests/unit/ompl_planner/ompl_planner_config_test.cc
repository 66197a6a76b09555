// The `ompl_planner` parameters: documented defaults, and bad values rejected with a message
// that names the key, the value and the valid choices (from the factory and from a suite).
#include <gtest/gtest.h>

#include "crowdsim/bench/plugin_registry.h"
#include "crowdsim/bench/suite.h"
#include "ompl_planner_policy.h"
#include "planner_config.h"
#include "temp_dir.h"
#include "test_paths.h"

namespace crowdsim::ompl_planner {
namespace {

using crowdsim::testing::PluginDir;

std::string ThrownMessage(const Params& params) {
  try {
    ConfigFromParams(params);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "(nothing thrown)";
}

TEST(OmplPlannerConfig, DefaultsAreADeterministicPlannerWithABudgetOfSamples) {
  const Params params = Params::Defaults(Schema());
  const PolicyConfig c = ConfigFromParams(params);
  EXPECT_EQ(c.plan.planner, "rrtstar");
  ASSERT_NE(FindPlanner(c.plan.planner), nullptr);
  EXPECT_TRUE(FindPlanner(c.plan.planner)->deterministic);
  EXPECT_EQ(c.plan.plan_samples, 1500);
  EXPECT_EQ(c.plan.plan_time_s, 0.0);  // wall time off: deterministic by default
  EXPECT_DOUBLE_EQ(c.plan.margin, 0.1);
  EXPECT_TRUE(c.plan.simplify);
  EXPECT_EQ(c.local, LocalMode::kOrca);
  EXPECT_EQ(c.replan_stall_steps, 8);
}

TEST(OmplPlannerConfig, SchemaListsEveryPlannerAsAChoice) {
  for (const ParamSpec& spec : Schema()) {
    if (spec.name != "planner") continue;
    ASSERT_EQ(spec.choices.size(), Planners().size());
    for (std::size_t i = 0; i < Planners().size(); ++i)
      EXPECT_EQ(spec.choices[i], Planners()[i].name);
    return;
  }
  FAIL() << "no planner parameter";
}

TEST(OmplPlannerConfig, UnknownPlannerNameListsTheValidOnes) {
  Params params = Params::Defaults(Schema());
  params.Set("planner", std::string("rrt_star"));
  const std::string message = ThrownMessage(params);
  EXPECT_NE(message.find("planner"), std::string::npos) << message;
  EXPECT_NE(message.find("'rrt_star'"), std::string::npos) << message;
  for (const PlannerInfo& p : Planners())
    EXPECT_NE(message.find(p.name), std::string::npos) << message;
}

TEST(OmplPlannerConfig, NegativeBudgetsAreErrors) {
  Params samples = Params::Defaults(Schema());
  samples.Set("plan_samples", std::int64_t{-5});
  std::string message = ThrownMessage(samples);
  EXPECT_NE(message.find("plan_samples: -5"), std::string::npos) << message;
  Params time = Params::Defaults(Schema());
  time.Set("plan_time_s", -1.0);
  message = ThrownMessage(time);
  EXPECT_NE(message.find("plan_time_s"), std::string::npos) << message;
  Params local = Params::Defaults(Schema());
  local.Set("local", std::string("rvo"));
  message = ThrownMessage(local);
  EXPECT_NE(message.find("orca, actions"), std::string::npos) << message;
}

TEST(OmplPlannerConfig, ThePluginFactoryReportsABadPlannerName) {
  PluginRegistry registry({PluginDir()});
  const LoadedPlugin& plugin = registry.Load("ompl_planner", PluginKind::kPolicy);
  Params params = Params::Defaults(plugin.schema);
  params.Set("planner", std::string("astar"));
  try {
    registry.MakePolicy(plugin, params);
    FAIL() << "no error";
  } catch (const PluginError& e) {
    EXPECT_NE(std::string(e.what()).find("valid planners: " + PlannerNameList()), std::string::npos)
        << e.what();
  }
}

TEST(OmplPlannerConfig, SuiteValidationRejectsBadPlannerAndNegativeBudget) {
  crowdsim::testing::TempDir dir;
  const auto file = dir.Write("suite.yaml", R"(name: bad
episodes: 1
world: {source: random_rect, obstacles: 1, split: test}
robot: {sensors: [person]}
rows:
  - {label: a, policy: ompl_planner, params: {planner: dijkstra}}
  - {label: b, policy: ompl_planner, params: {plan_samples: -100}}
)");
  PluginRegistry registry({PluginDir()});
  const SuiteLoadResult r = LoadSuite(file, registry);
  ASSERT_FALSE(r.suite.has_value());
  std::string all;
  for (const SuiteError& e : r.errors) all += e.Format() + "\n";
  EXPECT_NE(all.find("dijkstra"), std::string::npos) << all;
  EXPECT_NE(all.find("rrtconnect"), std::string::npos) << all;  // the choices are listed
  EXPECT_NE(all.find("plan_samples"), std::string::npos) << all;
}

TEST(OmplPlannerConfig, NeedsTheMapAndThePersonSensor) {
  const OmplPlannerPolicy policy(Params::Defaults(Schema()));
  const PolicyNeeds needs = policy.Needs();
  EXPECT_TRUE(needs.map);
  EXPECT_FALSE(needs.lookahead);
  EXPECT_EQ(needs.sensors, std::vector<std::string>{"person"});
}

}  // namespace
}  // namespace crowdsim::ompl_planner
