// The import pipeline end to end on synthetic plans, its errors, and the committed worlds.
#include <gtest/gtest.h>

#include <set>
#include <tuple>

#include "crowdsim/world_file.h"
#include "floorplan/floorplan_error.h"
#include "floorplan/floorplan_import.h"
#include "floorplan_test_util.h"
#include "temp_dir.h"
#include "test_paths.h"

namespace crowdsim::floorplan {
namespace {

using crowdsim::testing::ReadText;
using crowdsim::testing::SharedDir;
using crowdsim::testing::SourceDir;
using crowdsim::testing::TempDir;
using testing::OutlineRoom;
using testing::WritePgm;
using testing::WriteRoomPlan;

ImportOptions Small() {
  ImportOptions o;
  o.kind = PlanKind::kOutline;
  o.source_resolution = 0.1;
  o.test_pairs = 30;
  o.train_pairs = 40;
  o.free_points = 25;
  return o;
}

// Expects ImportFloorplan to throw a FloorplanError naming the file and containing `hint`.
void ExpectImportError(const std::filesystem::path& image, const ImportOptions& o,
                       const std::string& hint) {
  try {
    ImportFloorplan(image, o);
    ADD_FAILURE() << "no error for " << image;
  } catch (const FloorplanError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find(image.string()), std::string::npos) << what;
    EXPECT_NE(what.find(hint), std::string::npos) << what;
  }
}

TEST(ImportTest, OutlineRoomInteriorOnlyAndDoorDoesNotLeak) {
  TempDir dir;
  const ImportResult r = ImportFloorplan(WriteRoomPlan(dir.path()), Small());
  // Inside of the walls: 78 x 78 cells minus the 2 m2 table; the 1.6 km2 page outside is gone.
  EXPECT_NEAR(StatValue(r.world, "interior_free_area_m2"), 7.8 * 7.8 - 2.0, 0.5);
  EXPECT_LT(StatValue(r.world, "free_area_m2"), 7.8 * 7.8);
  EXPECT_GT(StatValue(r.world, "component_share"), 0.8);
  // The world is the room plus the margin, centred on the origin.
  EXPECT_NEAR(r.world.bounds.Size().x(), 7.8 + 2 * 0.5, 0.25);
  EXPECT_NEAR(r.world.bounds.Center().norm(), 0.0, 0.1);
  // Without door-gap closing the flood from the border runs through the door into the room.
  ImportOptions leaky = Small();
  leaky.door_gap = 0.2;
  ExpectImportError(WriteRoomPlan(dir.path()), leaky, "no interior");
}

TEST(ImportTest, KeepsTheLargestRectanglesOnly) {
  TempDir dir;
  ImportOptions o = Small();
  o.max_rectangles = 3;
  const ImportResult r = ImportFloorplan(WriteRoomPlan(dir.path()), o);
  ASSERT_EQ(r.world.rectangles.size(), 3u);
  EXPECT_GT(StatValue(r.world, "rectangles_total"), 3.0);
  EXPECT_EQ(StatValue(r.world, "rectangles_kept"), 3.0);
  for (size_t k = 1; k < r.world.rectangles.size(); ++k) {
    EXPECT_LE(r.world.rectangles[k].Area(), r.world.rectangles[k - 1].Area() + 1e-9);
  }
  o.max_rectangles = 1000;
  const ImportResult all = ImportFloorplan(WriteRoomPlan(dir.path()), o);
  EXPECT_EQ(all.world.rectangles.size(), StatValue(all.world, "rectangles_total"));
  EXPECT_NEAR(StatValue(all.world, "kept_coverage_pct"), 100.0, 1e-9);
  for (size_t k = 0; k < 3; ++k) EXPECT_EQ(all.world.rectangles[k], r.world.rectangles[k]);
}

TEST(ImportTest, PairsAreFreeFarApartReachableAndDisjoint) {
  TempDir dir;
  ImportOptions o = Small();
  o.max_rectangles = 1000;  // every blocked cell is a rectangle: the mask check is visible
  const ImportResult r = ImportFloorplan(WriteRoomPlan(dir.path()), o);
  const double min_d = StatValue(r.world, "min_pair_distance_m");
  EXPECT_GT(min_d, 2.0);
  ASSERT_EQ(r.world.test_pairs.size(), 30u);
  ASSERT_EQ(r.world.train_pairs.size(), 40u);
  auto clear = [&](const Vec2& p) {
    for (const Rect& rect : r.world.rectangles) {
      if (PointToRectDistance(p, rect) < o.clearance - 1e-9) return false;
    }
    return r.world.bounds.Inflated(-o.clearance).Contains(p);
  };
  std::set<std::tuple<double, double, double, double>> test;
  for (const auto& p : r.world.test_pairs) {
    EXPECT_TRUE(clear(p.start) && clear(p.goal));
    EXPECT_GE((p.goal - p.start).norm(), min_d);
    test.insert({p.start.x(), p.start.y(), p.goal.x(), p.goal.y()});
  }
  for (const auto& p : r.world.train_pairs) {
    EXPECT_TRUE(clear(p.start) && clear(p.goal));
    EXPECT_EQ(test.count({p.start.x(), p.start.y(), p.goal.x(), p.goal.y()}), 0u);
  }
  for (const auto& p : r.world.free_points) EXPECT_TRUE(clear(p));
  EXPECT_GE(StatValue(r.world, "tortuosity_mean"), 1.0);
}

// The world file carries the mask the samples were drawn in, at the world's position.
TEST(ImportTest, WorldCarriesTheNavigableMask) {
  TempDir dir;
  const ImportResult r = ImportFloorplan(WriteRoomPlan(dir.path()), Small());
  ASSERT_TRUE(r.world.mask);
  const NavigableMask& m = *r.world.mask;
  ASSERT_EQ(m.width, r.mask.width);
  ASSERT_EQ(m.height, r.mask.height);
  EXPECT_EQ(m.origin, r.frame.origin);
  EXPECT_DOUBLE_EQ(m.resolution, r.frame.cell_size);
  for (size_t i = 0; i < m.cells.size(); ++i) ASSERT_EQ(m.cells[i] != 0, r.mask.cells[i] != 0) << i;
  EXPECT_NEAR(r.mask.Count() * 0.01, StatValue(r.world, "free_area_m2"), 1e-9);
  // Through the file and back: the same cells.
  WriteWorldFile(r.world, dir.path() / "w.yaml");
  const WorldFile back = ReadWorldFile(dir.path() / "w.yaml");
  ASSERT_TRUE(back.mask);
  EXPECT_EQ(back.mask->cells, m.cells);
  EXPECT_EQ(back.mask->origin, m.origin);
  // Every free point lies on a navigable cell.
  for (const Vec2& p : back.free_points) {
    const int col = static_cast<int>((p.x() - m.origin.x()) / m.resolution);
    const int row = m.height - 1 - static_cast<int>((p.y() - m.origin.y()) / m.resolution);
    EXPECT_TRUE(m.Navigable(row, col)) << p.transpose();
  }
}

TEST(ImportTest, SameInputSameFile) {
  TempDir dir;
  const auto plan = WriteRoomPlan(dir.path());
  WriteWorldFile(ImportFloorplan(plan, Small()).world, dir.path() / "a.yaml");
  WriteWorldFile(ImportFloorplan(plan, Small()).world, dir.path() / "b.yaml");
  EXPECT_EQ(ReadText(dir.path() / "a.yaml"), ReadText(dir.path() / "b.yaml"));
  ImportOptions other = Small();
  other.seed = 2;
  WriteWorldFile(ImportFloorplan(plan, other).world, dir.path() / "c.yaml");
  EXPECT_NE(ReadText(dir.path() / "a.yaml"), ReadText(dir.path() / "c.yaml"));
}

TEST(ImportTest, ResolutionFromGibsonMetadata) {
  TempDir dir;
  std::filesystem::create_directories(dir.path() / "maps");
  std::filesystem::create_directories(dir.path() / "maps_metadata");
  // The room drawn at 0.05 m/px: twice the pixels, the same building.
  const Grid small = OutlineRoom(120, 20, 20, 80, 8);
  Grid big(240, 240, 1);
  for (int r = 0; r < 240; ++r) {
    for (int c = 0; c < 240; ++c) big(r, c) = small.cells[small.Index(r / 2, c / 2)];
  }
  WritePgm(big, dir.path() / "maps" / "room.pgm");
  dir.Write("maps_metadata/room.yaml", "origin: {x: 0, y: 0}\nscale: 0.05\n");
  EXPECT_DOUBLE_EQ(MetadataResolution(dir.path() / "maps" / "room.pgm"), 0.05);
  ImportOptions o = Small();
  o.source_resolution = 0.0;
  const ImportResult r = ImportFloorplan(dir.path() / "maps" / "room.pgm", o);
  EXPECT_DOUBLE_EQ(r.source_resolution, 0.05);
  EXPECT_NEAR(StatValue(r.world, "interior_free_area_m2"), 7.8 * 7.8, 1.0);
  dir.Write("maps_metadata/room.yaml", "scale: lots\n");
  EXPECT_THROW(MetadataResolution(dir.path() / "maps" / "room.pgm"), FloorplanError);
}

TEST(ImportTest, BadInputsSayWhatToFix) {
  TempDir dir;
  ImportOptions o = Small();
  ExpectImportError(dir.path() / "missing.png", o, "no such image");
  // A folder exists: "no such image file" sent the user looking for a typo in its path.
  ExpectImportError(dir.path(), o, "is a folder, not an image");
  ExpectImportError(dir.Write("text.png", "hello, not an image\n"), o, "not a PNG or PGM");
  ExpectImportError(dir.Write("empty.png", ""), o, "empty");
  ExpectImportError(dir.Write("trunc.pgm", "P5\n10 10\n255\n\x01\x02"), o, "truncated");
  const auto black = dir.path() / "black.pgm";
  WritePgm(Grid(50, 50, 0), black);
  ExpectImportError(black, o, "every pixel is blocked");
  const auto tiny = dir.path() / "tiny.pgm";
  WritePgm(OutlineRoom(40, 10, 10, 6, 0), tiny);  // 0.4 m inside: no 0.3 m disc fits
  ExpectImportError(tiny, o, "no place where a disc of radius 0.3 m fits");  // not 0.300000
  ImportOptions unknown = o;
  unknown.source_resolution = 0.0;
  ExpectImportError(WriteRoomPlan(dir.path()), unknown, "--resolution");
  ImportOptions coarse = o;
  coarse.source_resolution = 5.0;
  ExpectImportError(WriteRoomPlan(dir.path()), coarse, "resolution 5 m/px is out of range [0.005,");
  const auto named = dir.path() / "scene_0.1m.png";
  std::filesystem::copy_file(WriteRoomPlan(dir.path()), named);
  ImportOptions wrong = o;
  wrong.source_resolution = 0.05;
  ExpectImportError(named, wrong, "file name says 0.1 m");
}

// The committed easy/medium/hard worlds are exactly what the importer makes from the source.
TEST(CommittedWorldsTest, ReimportGivesIdenticalFiles) {
  const auto maps = SharedDir() / "floorplans" / "gibson" / "maps";
  if (!std::filesystem::exists(maps)) {
    GTEST_SKIP() << "source floor plans not found at " << maps << " (../shared/floorplans)";
  }
  TempDir dir;
  for (const char* level : {"easy", "medium", "hard"}) {
    const auto committed = SourceDir() / "worlds" / "gibson" / (std::string(level) + ".yaml");
    const WorldFile world = ReadWorldFile(committed);
    ImportOptions o;
    o.seed = static_cast<std::uint64_t>(StatValue(world, "seed"));
    o.test_pairs = static_cast<int>(StatValue(world, "test_pairs"));
    o.train_pairs = static_cast<int>(StatValue(world, "train_pairs"));
    o.free_points = static_cast<int>(StatValue(world, "free_points"));
    EXPECT_EQ(o.test_pairs, 500);
    EXPECT_FALSE(world.attribution.empty());
    const ImportResult r = ImportFloorplan(maps / (world.name + ".png"), o);
    WriteWorldFile(r.world, dir.path() / "again.yaml");
    EXPECT_EQ(ReadText(dir.path() / "again.yaml"), ReadText(committed)) << level;
    EXPECT_TRUE(world.mask) << level;  // renders draw it
  }
}

}  // namespace
}  // namespace crowdsim::floorplan
