// The world file: the optional run-length `mask:` section round-trips byte-stably, reaches the
// static map, and malformed masks are rejected with file:line and the key.
#include "crowdsim/world_file.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <memory>
#include <string>
#include <tuple>

#include "temp_dir.h"

namespace crowdsim {
namespace {

using testing::ReadText;
using testing::TempDir;

// 5 x 3 cells, row 0 at the top: a row that starts navigable, a fully blocked one, a mixed one.
std::shared_ptr<const NavigableMask> SmallMask() {
  auto m = std::make_shared<NavigableMask>();
  m->width = 5;
  m->height = 3;
  m->resolution = 0.1;
  m->origin = Vec2(-0.2, -0.1);
  m->cells = {1, 1, 0, 1, 1,  //
              0, 0, 0, 0, 0,  //
              0, 1, 0, 0, 1};
  return m;
}

WorldFile SmallWorld() {
  WorldFile w;
  w.name = "masked";
  w.bounds = Rect::FromCorners(-0.2, -0.1, 0.3, 0.2);
  w.rectangles = {Rect::FromCorners(-0.2, 0.0, 0.3, 0.1)};
  w.free_points = {Vec2(-0.15, 0.15)};
  w.stats = {{"free_area_m2", 0.07}};
  w.mask = SmallMask();
  return w;
}

// A world file whose mask section is `mask` (YAML text, indented under "mask:").
std::string WithMask(const std::string& mask) {
  return "format: crowdsim-world/1\nname: \"m\"\nbounds: [0, 0, 1, 1]\nrectangles: []\nmask:\n" +
         mask;
}

constexpr const char* kGoodMask =
    "  resolution: 0.5\n  origin: [0, 0]\n  width: 2\n  height: 2\n  rows:\n    - \"0 2\"\n"
    "    - \"1 1\"\n";

TEST(WorldFileMask, RoundTripKeepsEveryCellAndTheBytes) {
  TempDir dir;
  WriteWorldFile(SmallWorld(), dir.path() / "a.yaml");
  const std::string text = ReadText(dir.path() / "a.yaml");
  EXPECT_NE(text.find("mask:\n  resolution: 0.1000\n  origin: [-0.2000, -0.1000]\n  width: 5\n"
                      "  height: 3\n  rows:\n    - \"0 2 1 2\"\n    - \"5\"\n    - \"1 1 2 1\"\n"),
            std::string::npos)
      << text;
  const WorldFile back = ReadWorldFile(dir.path() / "a.yaml");
  ASSERT_TRUE(back.mask);
  EXPECT_EQ(back.mask->width, 5);
  EXPECT_EQ(back.mask->height, 3);
  EXPECT_DOUBLE_EQ(back.mask->resolution, 0.1);
  EXPECT_EQ(back.mask->origin, Vec2(-0.2, -0.1));
  EXPECT_EQ(back.mask->cells, SmallMask()->cells);
  EXPECT_EQ(back.free_points.size(), 1u);
  WriteWorldFile(back, dir.path() / "b.yaml");
  EXPECT_EQ(ReadText(dir.path() / "b.yaml"), text);  // byte-stable
}

TEST(WorldFileMask, LargeRandomMaskRoundTrips) {
  auto m = std::make_shared<NavigableMask>();
  m->width = 97;
  m->height = 41;
  m->origin = Vec2(-4.8, -2.0);
  std::uint32_t state = 12345;
  for (int i = 0; i < m->width * m->height; ++i) {
    state = state * 1664525u + 1013904223u;
    m->cells.push_back((state >> 28) < 9 ? 1 : 0);  // runs of every length, both ends
  }
  WorldFile w = SmallWorld();
  w.mask = m;
  TempDir dir;
  WriteWorldFile(w, dir.path() / "w.yaml");
  EXPECT_EQ(ReadWorldFile(dir.path() / "w.yaml").mask->cells, m->cells);
}

TEST(WorldFileMask, StaticMapCarriesTheMaskAndWorldsWithoutOneStayWithout) {
  const StaticMap map = SmallWorld().ToStaticMap();
  ASSERT_TRUE(map.mask);
  EXPECT_TRUE(map.mask->Navigable(0, 0));
  EXPECT_FALSE(map.mask->Navigable(1, 4));
  WorldFile plain = SmallWorld();
  plain.mask.reset();
  TempDir dir;
  WriteWorldFile(plain, dir.path() / "p.yaml");
  EXPECT_EQ(ReadText(dir.path() / "p.yaml").find("\nmask:"), std::string::npos);
  EXPECT_FALSE(ReadWorldFile(dir.path() / "p.yaml").mask);
  EXPECT_FALSE(plain.ToStaticMap().mask);
}

TEST(WorldFileMask, WorldSetsCarryMasksToo) {
  WorldFile other = SmallWorld();
  other.name = "plain";
  other.mask.reset();
  TempDir dir;
  WriteWorldSet({SmallWorld(), other}, "two worlds", dir.path() / "set.yaml");
  const auto worlds = ReadWorldSet(dir.path() / "set.yaml");
  ASSERT_EQ(worlds.size(), 2u);
  ASSERT_TRUE(worlds[0].mask);
  EXPECT_EQ(worlds[0].mask->cells, SmallMask()->cells);
  EXPECT_FALSE(worlds[1].mask);
}

TEST(WorldFileMask, WriterRejectsAMaskOfTheWrongSize) {
  WorldFile w = SmallWorld();
  auto bad = std::make_shared<NavigableMask>(*SmallMask());
  bad->cells.pop_back();
  w.mask = bad;
  TempDir dir;
  EXPECT_THROW(WriteWorldFile(w, dir.path() / "bad.yaml"), WorldFileError);
}

TEST(WorldFileValues, NonFiniteCoordinatesAreRejected) {
  TempDir dir;
  for (const char* bad : {"[-.inf, -1, 1, 1]", "[0, 0, .nan, 1]", "[0, 0, 1, .Inf]"}) {
    const auto file = dir.Write(
        "w.yaml", std::string("format: crowdsim-world/1\nname: \"w\"\nbounds: [-5, -5, 5, 5]\n"
                              "rectangles:\n  - ") +
                      bad + "\n");
    try {
      ReadWorldFile(file);
      ADD_FAILURE() << "accepted " << bad;
    } catch (const WorldFileError& e) {
      EXPECT_NE(std::string(e.what()).find("not a finite number"), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find("w.yaml:5:"), std::string::npos) << e.what();
    }
  }
}

TEST(WorldFileMask, MalformedMasksNameTheFileLineAndKey) {
  TempDir dir;
  ASSERT_TRUE(ReadWorldFile(dir.Write("good.yaml", WithMask(kGoodMask))).mask);
  // {mask section, line of the error, text the message must hold}
  const std::tuple<std::string, int, std::string> cases[] = {
      {"  resolution: 0.5\n  origin: [0, 0]\n  width: 2\n  height: 2\n  rows:\n    - \"0 2\"\n"
       "    - \"1 2\"\n",
       12, "'mask.rows[1]': the runs add up to more than the mask width 2"},
      {"  resolution: 0.5\n  origin: [0, 0]\n  width: 3\n  height: 2\n  rows:\n    - \"0 2\"\n"
       "    - \"3\"\n",
       11, "'mask.rows[0]': the runs add up to 2 cells, not the mask width 3"},
      {"  resolution: 0.5\n  origin: [0, 0]\n  width: 2\n  height: 3\n  rows:\n    - \"0 2\"\n"
       "    - \"1 1\"\n",
       11, "'mask.rows' must be a list of 3 run-length strings (one per row, mask.height), got 2"},
      {"  resolution: 0.5\n  origin: [0, 0]\n  width: 2\n  height: 2\n  rows:\n    - \"0 2\"\n"
       "    - \"1 0 1\"\n",
       12, "'mask.rows[1]': run 2 is 0"},
      {"  resolution: 0.5\n  origin: [0, 0]\n  width: 2\n  height: 2\n  rows:\n    - \"0,2\"\n"
       "    - \"2\"\n",
       11, "'mask.rows[0]' must be whole numbers separated by single spaces"},
      {"  resolution: 0.5\n  origin: [0, 0]\n  width: 2\n  height: 2\n  rows:\n    - \"0  2\"\n"
       "    - \"2\"\n",
       11, "single spaces"},
      {"  resolution: 0.5\n  origin: [0, 0]\n  width: 2\n  height: 2\n  rows:\n    - [0, 2]\n"
       "    - \"2\"\n",
       11, "'mask.rows[0]' must be a string of run lengths"},
      {"  resolution: 0\n  origin: [0, 0]\n  width: 2\n  height: 1\n  rows: [\"2\"]\n", 6,
       "'mask.resolution' must be a number > 0"},
      {"  resolution: 0.5\n  origin: [0]\n  width: 2\n  height: 1\n  rows: [\"2\"]\n", 7,
       "'mask.origin' must be a list of 2 numbers"},
      {"  resolution: 0.5\n  origin: [0, 0]\n  width: -2\n  height: 1\n  rows: [\"2\"]\n", 8,
       "'mask.width' must be a whole number >= 1, got -2"},
      {"  resolution: 0.5\n  origin: [0, 0]\n  width: 2\n  rows: [\"2\"]\n", 6,
       "missing key 'mask.height'"},
      {"  resolution: 0.5\n  origin: [0, 0]\n  width: 2\n  height: 1\n  rows: [\"2\"]\n"
       "  colour: red\n",
       11, "unknown key 'mask.colour' (valid: resolution, origin, width, height, rows)"},
      {"  [1, 2]\n", 6, "'mask' must be a map"},
  };
  int k = 0;
  for (const auto& [mask, line, hint] : cases) {
    const auto path = dir.Write("bad" + std::to_string(k++) + ".yaml", WithMask(mask));
    try {
      ReadWorldFile(path);
      ADD_FAILURE() << "no error for\n" << mask;
    } catch (const WorldFileError& e) {
      const std::string what = e.what();
      EXPECT_NE(what.find(path.string() + ":" + std::to_string(line) + ":"), std::string::npos)
          << what;
      EXPECT_NE(what.find(hint), std::string::npos) << what;
    }
  }
}

// Found by the world_reader fuzz target (tests/fuzz): a list or map where a name, key or number
// belongs made yaml-cpp's own exception escape (no file, no key) and ended the CLI; a mask of
// absurd width allocated gigabytes. Each is now a WorldFileError at the offending line.
TEST(WorldFileValues, WrongKindsOfValuesAreLocatedErrors) {
  TempDir dir;
  const std::string head = "format: crowdsim-world/1\nbounds: [0, 0, 1, 1]\n";
  // {file text, line of the error, text the message must hold}
  const std::tuple<std::string, int, std::string> cases[] = {
      {head + "stats: {free_area_m2: [1]}\n", 3,
       "'stats.free_area_m2' holds a value that is not a number"},
      {head + "stats: {free_area_m2: .nan}\n", 3,
       "'stats.free_area_m2' holds '.nan', not a finite number"},
      {head + "stats: [1, 2]\n", 3, "'stats' must be a map of names to numbers"},
      {head + "stats: {[a]: 1}\n", 3, "'stats key' must be a single text value"},
      {head + "name: [a, b]\n", 3, "'name' must be a single text value"},
      {head + "attribution: {by: me}\n", 3, "'attribution' must be a single text value"},
      {head + "? [bounds]\n: 1\n", 3, "'key' must be a single text value"},
      {head + "robot_pairs: 5\n", 3, "'robot_pairs' must be a map"},
      {head + "free_points: {a: 1}\n", 3, "'free_points' must be a list of [x, y]"},
      {"format: [crowdsim-world/1]\nbounds: [0, 0, 1, 1]\n", 1,
       "'format' must be a single text value"},
      {"just text\n", 1, "a world must be a map"},
      {head + "mask: {resolution: 1, origin: [0, 0], width: 2000000000, height: 1, rows: "
              "[\"2000000000\"]}\n",
       3, "'mask' of 2000000000 x 1 cells is larger than 100000000 cells"},
  };
  int k = 0;
  for (const auto& [text, line, hint] : cases) {
    const auto path = dir.Write("bad" + std::to_string(k++) + ".yaml", text);
    try {
      ReadWorldFile(path);
      ADD_FAILURE() << "no error for\n" << text;
    } catch (const WorldFileError& e) {
      const std::string what = e.what();
      EXPECT_NE(what.find(path.string() + ":" + std::to_string(line) + ":"), std::string::npos)
          << what;
      EXPECT_NE(what.find(hint), std::string::npos) << what;
    }
  }
}

// A robot pair whose start or goal is outside the bounds or inside a rectangle (a pair written
// by hand): its episode could not be made, and a run stopped when it came to it, after the
// episodes before it had run (validate tries episode 0 alone). Now the file is refused where it
// is read, naming the line and the pair.
TEST(WorldFileValues, ARobotPairOutsideTheFreeSpaceIsALocatedError) {
  TempDir dir;
  const std::string head =
      "format: crowdsim-world/1\nbounds: [-5, -5, 5, 5]\nrectangles:\n  - [-1, -1, 1, 1]\n"
      "robot_pairs:\n";
  // {pairs, line of the error, text the message must hold}
  const std::tuple<std::string, int, std::string> cases[] = {
      {"  test:\n    - [-3, -3, 3, 3]\n    - [-3, -3, 0, 0.5]\n", 8,
       "'robot_pairs.test[1]': its goal (0.0000, 0.5000) lies inside rectangles[0]"},
      {"  train:\n    - [-6, 0, 3, 3]\n", 7,
       "'robot_pairs.train[0]': its start (-6.0000, 0.0000) lies outside 'bounds'"},
  };
  int k = 0;
  for (const auto& [pairs, line, hint] : cases) {
    const auto path = dir.Write("pairs" + std::to_string(k++) + ".yaml", head + pairs);
    try {
      ReadWorldFile(path);
      ADD_FAILURE() << "no error for\n" << pairs;
    } catch (const WorldFileError& e) {
      const std::string what = e.what();
      EXPECT_NE(what.find(path.string() + ":" + std::to_string(line) + ":"), std::string::npos)
          << what;
      EXPECT_NE(what.find(hint), std::string::npos) << what;
    }
  }
  // On an edge of a rectangle is free space, as for the scenario's own check.
  const WorldFile ok =
      ReadWorldFile(dir.Write("ok.yaml", head + "  test:\n    - [-3, -3, 1, 0]\n"));
  EXPECT_EQ(ok.test_pairs.size(), 1u);
}

// A floor-plan image given as the world (file: plan.png, before importing it) was read as YAML:
// "not valid YAML: unknown escape character" and a stray byte. It is named as an image, with
// the import command.
TEST(WorldFileValues, AnImageGivenAsAWorldIsToldToBeImportedFirst) {
  TempDir dir;
  const auto png = dir.Write("plan.png", std::string("\x89PNG\r\n\x1a\n\0\0\0\rIHDR", 16));
  const auto pgm = dir.Write("plan.pgm", "P5\n4 4\n255\n");
  for (const auto& [path, kind] : {std::pair{png, "PNG"}, std::pair{pgm, "PGM"}}) {
    for (const bool set : {false, true}) {
      try {
        set ? static_cast<void>(ReadWorldSet(path)) : static_cast<void>(ReadWorldFile(path));
        ADD_FAILURE() << "read " << path;
      } catch (const WorldFileError& e) {
        EXPECT_NE(std::string(e.what()).find(path.string() + ": is a " + kind +
                                             " image, not a world file: import the floor plan "
                                             "first (`crowdsim-bench floorplan import " +
                                             path.string()),
                  std::string::npos)
            << e.what();
      }
    }
  }
}

}  // namespace
}  // namespace crowdsim
