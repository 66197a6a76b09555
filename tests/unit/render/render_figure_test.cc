// Episode figures: what the SVG shows (countable by class), determinism, --compare, the sensor
// snapshot and the floor-plan mask, on scripted episodes and on a replayed suite episode.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "crowdsim/bench/episode.h"
#include "crowdsim/bench/plugin_registry.h"
#include "crowdsim/bench/suite.h"
#include "crowdsim/render/episode_figure.h"
#include "crowdsim/render/episode_replay.h"
#include "crowdsim/render/figure_sensors.h"
#include "crowdsim/render/palette.h"
#include "crowdsim/render/svg_writer.h"
#include "crowdsim/sensor.h"
#include "scripted.h"
#include "test_paths.h"

namespace crowdsim::render {
namespace {

using crowdsim::testing::ConstantVelocityPolicy;
using crowdsim::testing::GoStraightPolicy;
using crowdsim::testing::MakeRoom;
using crowdsim::testing::MakeScenario;

int CountOf(const std::string& text, const std::string& needle) {
  int n = 0;
  for (size_t pos = text.find(needle); pos != std::string::npos; pos = text.find(needle, pos + 1))
    ++n;
  return n;
}

// A room (4 walls) with 2 obstacles off the robot's straight path and 2 walking humans.
Scenario ScriptedScenario() {
  return MakeScenario(
      MakeRoom({Rect::FromCorners(-1, 1.5, 1, 2.5), Rect::FromCorners(-1, -3, 0, -2)}), Vec2(-4, 0),
      Vec2(4, 0), {{Vec2(-3, 4), Vec2(3, 4)}, {Vec2(3, -4), Vec2(-3, -4)}});
}

EpisodeResult RunScripted(const Scenario& sc) {
  GoStraightPolicy robot;
  ConstantVelocityPolicy h1(Vec2(0.5, 0.0)), h2(Vec2(-0.5, 0.0));
  EpisodeAgents agents{&robot, {&h1, &h2}, {}, {}};
  Episode ep(sc, SimConfig{}, agents, /*record_trajectory=*/true);
  return ep.Run();
}

EpisodeFigure Figure(const Scenario& sc, const EpisodeResult& r) {
  EpisodeFigure fig;
  fig.scenario = &sc;
  fig.title = "scripted";
  fig.robots.push_back(RobotTrack{"robot: success", &r, palette::kRobot});
  return fig;
}

// The texts of the items of class `cls`, in paint order.
std::vector<std::string> TextsOf(const Drawing& d, const std::string& cls) {
  std::vector<std::string> out;
  for (const DrawItem& it : d.items)
    if (it.cls == cls) out.push_back(it.text);
  return out;
}

bool Has(const std::vector<std::string>& v, const std::string& s) {
  return std::find(v.begin(), v.end(), s) != v.end();
}

TEST(EpisodeFigure, SvgShowsEveryRectangleAndTrajectory) {
  const Scenario sc = ScriptedScenario();
  const EpisodeResult r = RunScripted(sc);
  ASSERT_EQ(r.status, EpisodeStatus::kSuccess);
  ASSERT_DOUBLE_EQ(r.time, 8.0);  // 8 m at 1 m/s
  const std::string svg = ToSvg(DrawEpisode(Figure(sc, r)));

  EXPECT_EQ(svg.rfind("<?xml", 0), 0u);
  EXPECT_EQ(CountOf(svg, "<rect class=\"obstacle\""), 6);  // 4 walls + 2 obstacles
  EXPECT_EQ(CountOf(svg, "<polyline class=\"trajectory robot\""), 1);
  EXPECT_EQ(CountOf(svg, "<polyline class=\"trajectory human\""), 2);
  EXPECT_EQ(CountOf(svg, "<circle class=\"final robot\""), 1);
  EXPECT_EQ(CountOf(svg, "<circle class=\"final human\""), 2);
  EXPECT_EQ(CountOf(svg, "<polygon class=\"start robot\""), 1);
  EXPECT_EQ(CountOf(svg, "<polygon class=\"goal robot\""), 1);
  EXPECT_EQ(CountOf(svg, "<polygon class=\"goal human\""), 2);
  // Time dots every 2 s of the 8 s episode: 2, 4, 6, 8 for the robot and for each human.
  EXPECT_EQ(CountOf(svg, "<circle class=\"timemark robot\""), 4);
  EXPECT_EQ(CountOf(svg, "<circle class=\"timemark human\""), 8);
  EXPECT_EQ(CountOf(svg, ">8s</text>"), 3);
  EXPECT_NE(svg.find("robot: success"), std::string::npos);
  EXPECT_EQ(CountOf(svg, "class=\"beam\""), 0);  // no snapshot asked for
  EXPECT_EQ(CountOf(svg, "class=\"mask\""), 0);
}

// The two humans as one walking group: one dashed link between them; alone, none.
TEST(EpisodeFigure, AWalkingGroupIsLinked) {
  Scenario sc = ScriptedScenario();
  EXPECT_EQ(CountOf(ToSvg(DrawEpisode(Figure(sc, RunScripted(sc)))), "class=\"group\""), 0);
  for (HumanSpec& h : sc.humans) h.group = 0;
  const std::string svg = ToSvg(DrawEpisode(Figure(sc, RunScripted(sc))));
  EXPECT_EQ(CountOf(svg, "<polyline class=\"group\""), 1);
}

TEST(EpisodeFigure, TheSameEpisodeGivesTheSameSvgBytes) {
  const Scenario sc = ScriptedScenario();
  const EpisodeResult a = RunScripted(sc);
  const EpisodeResult b = RunScripted(sc);
  EXPECT_EQ(ToSvg(DrawEpisode(Figure(sc, a))), ToSvg(DrawEpisode(Figure(sc, b))));
}

TEST(EpisodeFigure, RobotPathFollowsTheTrajectoryInCanvasCoordinates) {
  const Scenario sc = ScriptedScenario();
  const EpisodeResult r = RunScripted(sc);
  const Drawing d = DrawEpisode(Figure(sc, r));
  const DrawItem* robot = nullptr;
  for (const DrawItem& it : d.items) {
    if (it.cls == "trajectory robot") robot = &it;
  }
  ASSERT_NE(robot, nullptr);
  ASSERT_EQ(robot->points.size(), r.trajectory.size());
  // Straight along +x in the world: left to right on one canvas row, inside the canvas.
  EXPECT_LT(robot->points.front().x(), robot->points.back().x());
  EXPECT_NEAR(robot->points.front().y(), robot->points.back().y(), 1e-9);
  for (const Vec2& p : robot->points) {
    EXPECT_GT(p.x(), 0.0);
    EXPECT_LT(p.x(), d.width);
    EXPECT_GT(p.y(), 0.0);
    EXPECT_LT(p.y(), d.height);
  }
}

TEST(EpisodeFigure, CompareDrawsTwoRobotsInTwoColours) {
  const Scenario sc = ScriptedScenario();
  const EpisodeResult a = RunScripted(sc);
  // A second robot that only gets half way before the time limit.
  ConstantVelocityPolicy slow(Vec2(0.15, 0.0));
  ConstantVelocityPolicy h1(Vec2(0.5, 0.0)), h2(Vec2(-0.5, 0.0));
  Episode ep(sc, SimConfig{}, EpisodeAgents{&slow, {&h1, &h2}, {}, {}}, true);
  const EpisodeResult b = ep.Run();
  ASSERT_EQ(b.status, EpisodeStatus::kTimeout);
  EpisodeFigure fig = Figure(sc, a);
  fig.robots.push_back(RobotTrack{"slow: timeout", &b, palette::kRobotCompare});
  const Drawing d = DrawEpisode(fig);
  EXPECT_EQ(d.Count("trajectory robot"), 2);
  EXPECT_EQ(d.Count("final robot"), 2);
  EXPECT_EQ(d.Count("legend"), 2);
  EXPECT_EQ(d.Count("trajectory human"), 2);  // the humans are drawn once
  // The humans come from the chosen track: the longer run shows them until its end.
  fig.humans_from = 1;
  const Drawing longer = DrawEpisode(fig);
  for (const DrawItem& it : longer.items) {
    if (it.cls == "trajectory human") {
      EXPECT_EQ(it.points.size(), b.trajectory.size());
    }
  }
  std::vector<Color> colours;
  for (const DrawItem& it : d.items) {
    if (it.cls == "trajectory robot") colours.push_back(*it.style.stroke);
  }
  ASSERT_EQ(colours.size(), 2u);
  EXPECT_FALSE(colours[0] == colours[1]);
}

// Three beams (the middle one hits nothing) and one person straight ahead.
class FakeSensor final : public Sensor {
 public:
  void Sense(const SenseInput& in, SensorReading* out) const override {
    out->max_range = 5.0;
    out->angles = {-0.5, 0.0, 0.5};
    out->ranges = {2.0, 5.0, 3.0};
    out->people = {PersonObservation{Vec2(1.0, 0.0), Vec2(0.0, 0.5), 0.3}};
    seen_robot_x = in.robot.position.x();
  }
  mutable double seen_robot_x = 0.0;
};

TEST(EpisodeFigure, SensorSnapshotDrawsBeamsHitsAndPeople) {
  const Scenario sc = ScriptedScenario();
  const EpisodeResult r = RunScripted(sc);
  FakeSensor sensor;
  const std::vector<MountedSensor> sensors = {{"fake", &sensor}};
  EpisodeFigure fig = Figure(sc, r);
  fig.sensors = TakeSensorSnapshot(sc, r, 8, sensors);
  EXPECT_DOUBLE_EQ(fig.sensors->time, 2.0);
  EXPECT_NEAR(sensor.seen_robot_x, -2.0, 1e-9);  // 2 s at 1 m/s from x = -4
  ASSERT_EQ(fig.sensors->readings.size(), 1u);
  EXPECT_EQ(fig.sensors->readings[0].sensor, "fake");
  const Drawing d = DrawEpisode(fig);
  EXPECT_EQ(d.Count("beam"), 3);
  EXPECT_EQ(d.Count("hit"), 2);
  EXPECT_EQ(d.Count("person-reading"), 1);
  EXPECT_EQ(d.Count("sensed robot"), 1);
  EXPECT_EQ(d.Count("sensed human"), 2);
  EXPECT_EQ(d.Count("sensor-caption"), 1);
  // Animation frames never show the snapshot.
  EXPECT_EQ(DrawEpisodeFrame(fig, 3).Count("beam"), 0);
}

// A person sensor that sees everybody (true positions) or nobody.
class AllOrNobody final : public Sensor {
 public:
  explicit AllOrNobody(bool all) : all_(all) {}
  void Sense(const SenseInput& in, SensorReading* out) const override {
    out->people.clear();
    if (!all_) return;
    for (const AgentState& h : in.humans)
      out->people.push_back({in.frame.PointToLocal(h.position), Vec2::Zero(), h.radius});
  }

 private:
  bool all_;
};

TEST(EpisodeFigure, APersonSensorsFieldOfViewIsDrawnAndUnseenPeopleAreGrey) {
  const Scenario sc = ScriptedScenario();
  const EpisodeResult r = RunScripted(sc);
  const auto grey_humans = [&](bool all, double fov) {
    AllOrNobody sensor(all);
    const std::vector<MountedSensor> sensors = {{"person", &sensor}};
    EpisodeFigure fig = Figure(sc, r);
    fig.sensors = TakeSensorSnapshot(sc, r, 8, sensors);
    fig.sensors->fov_deg = {fov};
    fig.sensors->range = {0.0};
    const Drawing d = DrawEpisode(fig);
    EXPECT_EQ(d.Count("field-of-view"), fov < 360.0 ? 1 : 0);
    int grey = 0;
    for (const DrawItem& it : d.items) {
      if (it.cls == "sensed human" && *it.style.stroke == palette::kUnseen) ++grey;
    }
    return grey;
  };
  EXPECT_EQ(grey_humans(false, 90.0), 2);  // nobody detected: both grey
  EXPECT_EQ(grey_humans(true, 360.0), 0);  // everybody detected
}

// A tracking person sensor: the first human with track id 3, and a false detection (id 4) 50 m
// ahead, far from everybody; it notes the past and time step it was handed.
class TrackingSensor final : public Sensor {
 public:
  void Sense(const SenseInput& in, SensorReading* out) const override {
    out->people = {
        PersonObservation{in.frame.PointToLocal(in.humans[0].position), Vec2::Zero(), 0.3, 3},
        PersonObservation{Vec2(50.0, 0.0), Vec2::Zero(), 0.3, 4}};
    past = in.past.size();
    time_step = in.time_step;
  }
  int HistorySteps() const override { return -1; }
  mutable std::size_t past = 0;
  mutable double time_step = 0.0;
};

TEST(EpisodeFigure, PhantomsAreHollowDiscsAndTrackIdsAreLabelled) {
  const Scenario sc = ScriptedScenario();
  const EpisodeResult r = RunScripted(sc);
  TrackingSensor sensor;
  const std::vector<MountedSensor> sensors = {{"person", &sensor}};
  EpisodeFigure fig = Figure(sc, r);
  fig.sensors = TakeSensorSnapshot(sc, r, 8, sensors);
  EXPECT_EQ(sensor.past, 8u);  // the frames of steps 0..7
  EXPECT_DOUBLE_EQ(sensor.time_step, r.trajectory[1].time);
  const Drawing d = DrawEpisode(fig);
  EXPECT_EQ(d.Count("person-reading"), 2);   // a ring for each
  EXPECT_EQ(d.Count("phantom-reading"), 1);  // and a hollow disc for the one near nobody
  std::vector<std::string> ids;
  for (const DrawItem& it : d.items) {
    if (it.cls == "track-id") ids.push_back(it.text);
  }
  EXPECT_EQ(ids, (std::vector<std::string>{"3", "4"}));
}

// A sensor reporting other features (as the route sensor does: distance, waypoint x, y).
struct ValuesSensor : Sensor {
  void Sense(const SenseInput&, SensorReading* out) const override {
    out->values = {7.4219, 0.7149, -0.7};
  }
};

TEST(EpisodeFigure, SensorCaptionListsEachSensorsReading) {
  const Scenario sc = ScriptedScenario();
  const EpisodeResult r = RunScripted(sc);
  FakeSensor lidar;
  ValuesSensor route;
  const std::vector<MountedSensor> sensors = {{"fake", &lidar}, {"route", &route}};
  const SensorSnapshot s = TakeSensorSnapshot(sc, r, 8, sensors);
  EXPECT_EQ(SensorList(s), "fake (3 beams) (1 people), route (7.42, 0.71, -0.70)");
}

TEST(EpisodeFigure, SensorStepOutsideTheEpisodeNamesTheValidSteps) {
  const Scenario sc = ScriptedScenario();
  const EpisodeResult r = RunScripted(sc);
  FakeSensor sensor;
  const std::vector<MountedSensor> sensors = {{"fake", &sensor}};
  try {
    TakeSensorSnapshot(sc, r, 500, sensors);
    FAIL() << "expected std::out_of_range";
  } catch (const std::out_of_range& e) {
    EXPECT_NE(std::string(e.what()).find("500"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("valid steps are 0..32"), std::string::npos) << e.what();
  }
}

TEST(EpisodeFigure, FloorPlanMaskIsDrawnUnderTheRectangles) {
  auto map = std::make_shared<StaticMap>(*MakeRoom());
  auto mask = std::make_shared<NavigableMask>();
  mask->width = 4;
  mask->height = 3;
  mask->resolution = 2.0;
  mask->origin = Vec2(-4, -3);
  mask->cells = {1, 1, 0, 1, 1, 1, 1, 1, 0, 1, 1, 1};
  map->mask = mask;
  const Scenario sc = MakeScenario(map, Vec2(-3, 0), Vec2(3, 0));
  GoStraightPolicy robot;
  Episode ep(sc, SimConfig{}, EpisodeAgents{&robot, {}, {}, {}}, true);
  const EpisodeResult r = ep.Run();
  const Drawing d = DrawEpisode(Figure(sc, r));
  ASSERT_EQ(d.Count("mask"), 1);
  EXPECT_EQ(d.items.front().cls, "mask");  // painted first, under everything
  EXPECT_EQ(d.items.front().image->width, 4);
  const std::string svg = ToSvg(d);
  EXPECT_NE(svg.find("<image class=\"mask\""), std::string::npos);
  EXPECT_NE(svg.find("href=\"data:image/png;base64,iVBORw0KGgo"), std::string::npos);
  // The key says what the mask's grey means (only the rectangles collide).
  EXPECT_TRUE(Has(TextsOf(d, "key-text"), "blocked in the plan (not collidable)"));
}

TEST(EpisodeFigure, KeyExplainsTheMarksDrawnAndTheScaleBarIsToScale) {
  const Scenario sc = ScriptedScenario();
  const EpisodeResult r = RunScripted(sc);
  const Drawing d = DrawEpisode(Figure(sc, r));
  const std::vector<std::string> key = TextsOf(d, "key-text");
  for (const char* t : {"robot start", "robot goal", "human start", "human goal", "obstacle",
                        "path, dot every 2 s", "final position (radius to scale)"}) {
    EXPECT_TRUE(Has(key, t)) << t;
  }
  // A success explains no collision marks, a figure without sensors no beams.
  EXPECT_FALSE(Has(key, "collision"));
  EXPECT_FALSE(Has(key, "lidar beam, hit"));

  // Scale bar: its label's metres at the figure's px per metre, measured on the scripted
  // obstacle 2 m wide (obstacles are drawn in the map's order, walls first).
  const std::vector<std::string> label = TextsOf(d, "scale-bar-label");
  ASSERT_EQ(label.size(), 1u);
  const double metres = std::stod(label[0]);
  EXPECT_TRUE(label[0] == "1 m" || label[0] == "2 m" || label[0] == "5 m") << label[0];
  size_t wide = 0;
  while (wide < sc.map->rectangles.size() && !(sc.map->rectangles[wide].min == Vec2(-1, 1.5) &&
                                               sc.map->rectangles[wide].max == Vec2(1, 2.5)))
    ++wide;
  ASSERT_LT(wide, sc.map->rectangles.size());
  const DrawItem* obstacle = nullptr;
  const DrawItem* bar = nullptr;
  size_t obstacles_seen = 0;
  for (const DrawItem& it : d.items) {
    if (it.cls == "obstacle" && obstacles_seen++ == wide) obstacle = &it;
    if (it.cls == "scale-bar" && bar == nullptr) bar = &it;
  }
  ASSERT_NE(obstacle, nullptr);
  ASSERT_NE(bar, nullptr);
  const double px_per_metre = std::abs(obstacle->points[1].x() - obstacle->points[0].x()) / 2.0;
  EXPECT_NEAR(std::abs(bar->points[1].x() - bar->points[0].x()), metres * px_per_metre, 1e-6);
  // The key sits below the map, inside the canvas.
  for (const DrawItem& it : d.items) {
    if (it.cls != "key-text") continue;
    EXPECT_GT(it.points[0].y(), obstacle->points[1].y());
    EXPECT_LT(it.points[0].y(), d.height);
  }

  FigureOptions no_key;
  no_key.key = false;
  const Drawing bare = DrawEpisode(Figure(sc, r), no_key);
  EXPECT_EQ(bare.Count("key-text"), 0);
  EXPECT_EQ(bare.Count("scale-bar"), 0);
  EXPECT_LT(bare.height, d.height);
}

TEST(EpisodeFigure, ACollisionFigureMarksWhatWasHit) {
  // The robot walks into the first scripted obstacle's east side.
  const Scenario sc = ScriptedScenario();
  ConstantVelocityPolicy robot(Vec2(0.0, 1.0));
  ConstantVelocityPolicy h1(Vec2(0.5, 0.0)), h2(Vec2(-0.5, 0.0));
  Scenario up = sc;
  up.robot_start = Vec2(0.5, 0.0);
  up.robot_goal = Vec2(0.5, 4.0);
  Episode ep(up, SimConfig{}, EpisodeAgents{&robot, {&h1, &h2}, {}, {}}, true);
  const EpisodeResult r = ep.Run();
  ASSERT_EQ(r.status, EpisodeStatus::kCollisionObstacle);
  ASSERT_GE(r.collided_rect, 0);
  const Drawing d = DrawEpisode(Figure(up, r));
  EXPECT_EQ(d.Count("collision-mark"), 1);
  ASSERT_EQ(d.Count("collision-partner"), 1);
  const Rect& hit = up.map->rectangles[r.collided_rect];
  EXPECT_DOUBLE_EQ(hit.min.y(), 1.5);  // the obstacle above the robot, not a wall
  const std::vector<std::string> key = TextsOf(d, "key-text");
  EXPECT_TRUE(Has(key, "collision"));
  EXPECT_TRUE(Has(key, "what was hit"));
  // An animation of it keeps one frame size (the key lists the collision from the first frame).
  const EpisodeFigure fig = Figure(up, r);
  const Drawing first = DrawEpisodeFrame(fig, 0);
  const Drawing last = DrawEpisodeFrame(fig, r.trajectory.size() - 1);
  EXPECT_EQ(first.height, last.height);
  EXPECT_EQ(first.width, last.width);
  EXPECT_EQ(last.Count("collision-partner"), 1);
  EXPECT_EQ(first.Count("collision-partner"), 0);
}

TEST(EpisodeFigure, AnimationFramesGrowTheTrails) {
  const Scenario sc = ScriptedScenario();
  const EpisodeResult r = RunScripted(sc);
  const EpisodeFigure fig = Figure(sc, r);
  EXPECT_EQ(FrameCount(fig), r.trajectory.size());
  const Drawing first = DrawEpisodeFrame(fig, 0);
  const Drawing later = DrawEpisodeFrame(fig, 10);
  EXPECT_EQ(first.width, later.width);  // every frame has the same size
  EXPECT_EQ(first.height, later.height);
  EXPECT_EQ(later.Count("agent robot"), 1);
  EXPECT_EQ(later.Count("agent human"), 2);
  EXPECT_EQ(later.Count("clock"), 1);
  for (const DrawItem& it : later.items) {
    if (it.cls == "trajectory robot") {
      EXPECT_EQ(it.points.size(), 11u);
    }
  }
}

// The real thing: quick.yaml episode 0 replayed with the built plugins, twice.
TEST(EpisodeFigure, ReplayedSuiteEpisodeIsDeterministicAndShowsTheLidar) {
  PluginRegistry registry;
  SuiteLoadResult loaded =
      LoadSuite(crowdsim::testing::SourceDir() / "suites/quick.yaml", registry);
  ASSERT_TRUE(loaded.suite) << (loaded.errors.empty() ? "" : loaded.errors[0].Format());
  const Suite& suite = *loaded.suite;
  const ReplayedEpisode a = ReplayForFigure(suite, 0, 0, registry, 4);
  const ReplayedEpisode b = ReplayForFigure(suite, 0, 0, registry, 4);
  const std::string svg_a = ToSvg(DrawEpisode(MakeFigure(suite, a)));
  EXPECT_EQ(svg_a, ToSvg(DrawEpisode(MakeFigure(suite, b))));
  EXPECT_EQ(CountOf(svg_a, "<polyline class=\"beam\""), 45);  // quick.yaml: 45 lidar beams
  EXPECT_EQ(CountOf(svg_a, "<polyline class=\"trajectory human\""), 5);
  EXPECT_EQ(CountOf(svg_a, "<rect class=\"obstacle\""),
            static_cast<int>(a.scenario.map->rectangles.size()));
  // Both rows share episode 0's scenario: the comparison figure has both robots.
  const ReplayedEpisode orca = ReplayForFigure(suite, 1, 0, registry);
  const Drawing both = DrawEpisode(MakeFigure(suite, a, &orca));
  EXPECT_EQ(both.Count("trajectory robot"), 2);
}

// A floor-plan episode (gibson_baselines.yaml, the easy world): its world file carries the
// navigable mask, and the figure paints it once, first (under the rectangles), over the world.
TEST(EpisodeFigure, ReplayedFloorPlanEpisodeShowsTheMaskLayer) {
  PluginRegistry registry;
  SuiteLoadResult loaded =
      LoadSuite(crowdsim::testing::SourceDir() / "suites/gibson_baselines.yaml", registry);
  ASSERT_TRUE(loaded.suite) << (loaded.errors.empty() ? "" : loaded.errors[0].Format());
  const ReplayedEpisode e = ReplayForFigure(*loaded.suite, 0, 0, registry);
  ASSERT_TRUE(e.scenario.map && e.scenario.map->mask);
  const NavigableMask& m = *e.scenario.map->mask;
  EXPECT_EQ(m.cells.size(), static_cast<size_t>(m.width) * m.height);
  EXPECT_NEAR(m.origin.x(), e.scenario.map->bounds.min.x(), 1e-9);
  EXPECT_NEAR(m.origin.y() + m.height * m.resolution, e.scenario.map->bounds.max.y(), 1e-9);
  const Drawing d = DrawEpisode(MakeFigure(*loaded.suite, e));
  ASSERT_EQ(d.Count("mask"), 1);
  EXPECT_EQ(d.items.front().cls, "mask");  // under the rectangles
  EXPECT_EQ(d.items.front().image->width, m.width);
  EXPECT_EQ(d.items.front().image->height, m.height);
  const std::string svg = ToSvg(d);
  EXPECT_EQ(CountOf(svg, "<image class=\"mask\""), 1);
  EXPECT_LT(svg.find("<image class=\"mask\""), svg.find("<rect class=\"obstacle\""));
  EXPECT_EQ(CountOf(svg, "<rect class=\"obstacle\""),
            static_cast<int>(e.scenario.map->rectangles.size()));
}

}  // namespace
}  // namespace crowdsim::render
