// Varied people (`humans: {radius, v_pref, distracted}`): every world places people of their own
// sizes in free space apart, rows meet the same people, distracted people ignore a visible robot,
// and bad values are errors before anything runs.
#include <gtest/gtest.h>

#include <string>

#include "crowdsim/bench/episode.h"
#include "crowdsim/bench/row_instance.h"
#include "crowdsim/bench/suite.h"
#include "suite_file_test.h"
#include "suite_runs.h"
#include "temp_dir.h"
#include "test_paths.h"

namespace crowdsim {
namespace {

using testing::TempDir;

std::string SuiteText(const std::string& sim, const std::string& world, const std::string& humans) {
  return "name: varied\nepisodes: 12\nseed: 9\nsim: {" + sim + "}\nworld: " + world +
         "\nhumans: {count: 5, policy: orca" + humans +
         "}\nrobot:\n  sensors: [person]\nrows:\n  - {label: linear, policy: linear}\n"
         "  - {label: orca, policy: orca}\n";
}

using VariedPeopleTest = testing::SuiteFileTest;

constexpr const char* kCrowdNavPeople = ", radius: [0.3, 0.5], v_pref: [0.5, 1.5]";

TEST_F(VariedPeopleTest, EveryWorldPlacesPeopleOfTheirOwnSizesApart) {
  const std::string worlds[] = {
      "{source: random_rect, obstacles: 3, split: test}",
      "{source: crowdnav, scenario: circle_crossing}",
      "{source: crowdnav, scenario: square_crossing}",
      "{source: floorplan, file: " + (testing::SourceDir() / "worlds/gibson/hard.yaml").string() +
          ", split: test}",
      "{source: social_scenarios, scenario: doorway}",
      "{source: social_scenarios, scenario: narrow_hallway}",
      "{source: social_scenarios, scenario: intersection}",
  };
  for (const std::string& world : worlds) {
    const Suite suite = Loaded(SuiteText("", world, kCrowdNavPeople));
    ASSERT_EQ(suite.rows.size(), 2u) << world;
    const auto source =
        registry_.MakeWorld(*suite.rows[0].world.loaded, suite.rows[0].world.params);
    bool sizes_differ = false;
    for (int k = 0; k < 40; ++k) {
      const Scenario s = MakeEpisodeScenario(suite, suite.rows[0], *source, k);
      const Scenario t = MakeEpisodeScenario(suite, suite.rows[1], *source, k);
      EXPECT_NO_THROW(CheckScenario(s, suite.sim)) << world << " episode " << k;
      for (size_t i = 0; i < s.humans.size(); ++i) {
        const HumanSpec& h = s.humans[i];
        EXPECT_GE(h.radius, 0.3);
        EXPECT_LE(h.radius, 0.5);
        EXPECT_EQ(h.radius, t.humans[i].radius);  // every row meets the same people
        EXPECT_EQ(h.v_pref, t.humans[i].v_pref);
        EXPECT_EQ(h.start, t.humans[i].start);
        sizes_differ = sizes_differ || h.radius != s.humans[0].radius;
        // Scripted scenarios keep their own spacing (0.8 m for the sim's 0.3 m people).
        const bool scripted = world.find("social_scenarios") != std::string::npos;
        for (size_t j = 0; j < i && !scripted; ++j) {
          EXPECT_GE((h.start - s.humans[j].start).norm(),
                    h.radius + s.humans[j].radius + suite.sim.discomfort_dist - 1e-9)
              << world << " episode " << k << " people " << i << ", " << j;
        }
        for (size_t j = 0; j < i; ++j) {
          EXPECT_GE((h.start - s.humans[j].start).norm(), h.radius + s.humans[j].radius)
              << world << " episode " << k << ": people " << i << " and " << j << " overlap";
        }
      }
    }
    EXPECT_TRUE(sizes_differ) << world;
  }
}

TEST_F(VariedPeopleTest, DistractedPeopleIgnoreAVisibleRobot) {
  const std::string world = "{source: random_rect, obstacles: 1, split: test}";
  auto run = [&](const std::string& sim, const std::string& humans, const std::string& out) {
    const auto file = dir_.Write(out + ".yaml", SuiteText(sim, world, humans));
    return testing::RunSuiteFile(file, dir_.path() / out, 2).episodes;
  };
  const std::string unseen = run("robot_visible: false", "", "unseen");
  const std::string distracted = run("robot_visible: true", ", distracted: 1", "distracted");
  const std::string attentive = run("robot_visible: true", "", "attentive");
  EXPECT_EQ(distracted, unseen);  // nobody looks: as if the robot were invisible
  EXPECT_NE(attentive, unseen);   // people who look make way: the check can fail
  const std::string half = run("robot_visible: true", ", distracted: 0.5", "half");
  EXPECT_NE(half, unseen);
  EXPECT_NE(half, attentive);
}

TEST_F(VariedPeopleTest, ThePeopleKeysAreInTheConfigHashOnlyWhenSet) {
  const std::string world = "{source: random_rect, obstacles: 1, split: test}";
  const Suite plain = Loaded(SuiteText("", world, ""));
  const Suite varied = Loaded(SuiteText("", world, kCrowdNavPeople));
  EXPECT_EQ(plain.canonical.find("radius="), std::string::npos);
  EXPECT_NE(varied.canonical.find("radius=0.3:0.5,v_pref=0.5:1.5,"), std::string::npos);
  EXPECT_NE(plain.ConfigHash(), varied.ConfigHash());
}

TEST_F(VariedPeopleTest, BadValuesAreErrorsNamingTheKey) {
  const std::string world = "{source: random_rect, obstacles: 1, split: test}";
  auto error = [&](const std::string& humans) { return FirstError(SuiteText("", world, humans)); };
  EXPECT_NE(error(", radius: [0.5, 0.3]").find("humans.radius: lo is larger than hi"),
            std::string::npos)
      << error(", radius: [0.5, 0.3]");
  EXPECT_NE(error(", radius: [0.3]").find("humans.radius: a range is a list of two values"),
            std::string::npos);
  EXPECT_NE(error(", v_pref: 0").find("humans.v_pref"), std::string::npos);
  EXPECT_NE(error(", radius: -0.1").find("humans.radius"), std::string::npos);
  EXPECT_NE(error(", distracted: 1.5").find("humans.distracted"), std::string::npos);
  EXPECT_NE(error(", raduis: 0.4").find("did you mean 'radius'"), std::string::npos)
      << error(", raduis: 0.4");
}

}  // namespace
}  // namespace crowdsim
