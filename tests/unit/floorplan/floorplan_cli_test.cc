// `crowdsim-bench floorplan` end to end: exit codes, and nothing written on an error.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "crowdsim/world_file.h"
#include "floorplan_test_util.h"
#include "shell.h"
#include "temp_dir.h"
#include "test_paths.h"

namespace crowdsim::floorplan {
namespace {

using crowdsim::testing::ReadText;
using crowdsim::testing::Shell;
using crowdsim::testing::TempDir;

int Floorplan(const std::string& args) {
  const auto bin = crowdsim::testing::BinaryDir() / "bin" / "crowdsim-bench";
  return Shell(bin.string() + " floorplan " + args).first;
}

TEST(FloorplanCliTest, WritesNothingOnError) {
  TempDir dir;
  const auto out = dir.path() / "w.yaml";
  const auto bad = dir.Write("bad.png", "not an image");
  EXPECT_EQ(Floorplan("import " + bad.string() + " --out " + out.string()), 1);
  EXPECT_FALSE(std::filesystem::exists(out));
  EXPECT_EQ(Floorplan("import " + bad.string()), 2);  // --out missing
  EXPECT_EQ(Floorplan("import " + testing::WriteRoomPlan(dir.path()).string() +
                      " --resolution 0.1 --test-pairs 10 --train-pairs 10 --out " + out.string()),
            0);
  EXPECT_EQ(ReadWorldFile(out).test_pairs.size(), 10u);
  const auto svg = dir.path() / "w.svg";
  EXPECT_EQ(Floorplan("preview " + out.string() + " --out " + svg.string()), 0);
  EXPECT_NE(ReadText(svg).find("<svg"), std::string::npos);
  // The preview draws the world's own mask; no source image needed.
  EXPECT_NE(ReadText(svg).find("<image "), std::string::npos);
  // It writes SVG only: another extension is a usage error, and nothing is written.
  const auto png = dir.path() / "w.png";
  EXPECT_EQ(Floorplan("preview " + out.string() + " --out " + png.string()), 2);
  EXPECT_FALSE(std::filesystem::exists(png));
}

TEST(FloorplanCliTest, OptionsOutOfRangeAndOutputsAreUsageErrorsThatWriteNothing) {
  TempDir dir;
  const std::string plan = testing::WriteRoomPlan(dir.path()).string() + " --resolution 0.1";
  const auto out = dir.path() / "w.yaml";
  for (const char* option : {"--max-rectangles 0", "--test-pairs 0", "--free-points 0",
                             "--min-distance -1", "--agent-radius 0"}) {
    EXPECT_EQ(Floorplan("import " + plan + " " + option + " --out " + out.string()), 2) << option;
  }
  // A plain image needs its scale: without --resolution (and no maps_metadata, no _0.1m name)
  // a usage error as the help says, with what to pass (it exited 1, as a failed import).
  const auto bin = crowdsim::testing::BinaryDir() / "bin" / "crowdsim-bench";
  auto [rc, text] = Shell(bin.string() + " floorplan import " +
                          testing::WriteRoomPlan(dir.path()).string() + " --out " + out.string());
  EXPECT_EQ(rc, 2) << text;
  EXPECT_NE(text.find("room.pgm: unknown resolution: pass --resolution M_PER_PX"),
            std::string::npos)
      << text;
  EXPECT_NE(text.find("usage:"), std::string::npos) << text;
  EXPECT_FALSE(std::filesystem::exists(out));
  // A --resolution out of range, or one that contradicts a *_0.1m name: the option is
  // wrong, a usage error too (both exited 1).
  EXPECT_EQ(Floorplan("import " + testing::WriteRoomPlan(dir.path()).string() +
                      " --resolution 50 --out " + out.string()),
            2);
  const auto decimetre = dir.path() / "flat_0.1m.pgm";
  std::filesystem::copy_file(testing::WriteRoomPlan(dir.path()), decimetre);
  auto [drc, dtext] = Shell(bin.string() + " floorplan import " + decimetre.string() +
                            " --resolution 0.05 --out " + out.string());
  EXPECT_EQ(drc, 2) << dtext;
  EXPECT_NE(dtext.find("the file name says 0.1 m per pixel but --resolution is 0.05"),
            std::string::npos)
      << dtext;
  EXPECT_FALSE(std::filesystem::exists(out));
  // --out naming a folder: a usage error, no stray temporary file beside it.
  std::filesystem::create_directories(dir.path() / "folder");
  EXPECT_EQ(Floorplan("import " + plan + " --out " + (dir.path() / "folder").string()), 2);
  EXPECT_FALSE(std::filesystem::exists(dir.path() / "folder.tmp"));
  EXPECT_FALSE(std::filesystem::exists(out));
  // Both outputs' folders are made (the mask's was not, and its failure came after the world
  // had been written).
  const auto nested = dir.path() / "a" / "w.yaml";
  const auto mask = dir.path() / "b" / "m.png";
  EXPECT_EQ(Floorplan("import " + plan + " --test-pairs 5 --train-pairs 5 --out " +
                      nested.string() + " --mask-png " + mask.string()),
            0);
  EXPECT_TRUE(std::filesystem::exists(nested));
  EXPECT_TRUE(std::filesystem::exists(mask));
  // preview: an image where the world file belongs is a usage error; its --out folder is made.
  EXPECT_EQ(Floorplan("preview " + mask.string() + " --out " + (dir.path() / "p.svg").string()), 2);
  const auto svg = dir.path() / "c" / "p.svg";
  EXPECT_EQ(Floorplan("preview " + nested.string() + " --out " + svg.string()), 0);
  EXPECT_TRUE(std::filesystem::exists(svg));
}

// The input image is never an output: --out or --mask-png naming it (or a link to it) is a
// usage error and the image is left as it was; both outputs naming one file are refused too.
TEST(FloorplanCliTest, TheInputImageIsNeverOverwritten) {
  TempDir dir;
  const auto image = testing::WriteRoomPlan(dir.path());
  const std::string before = ReadText(image);
  std::filesystem::create_symlink(image, dir.path() / "link.png");
  const std::string plan = image.string() + " --resolution 0.1 --test-pairs 5 --train-pairs 5";
  const std::string link = (dir.path() / "link.png").string();
  EXPECT_EQ(Floorplan("import " + plan + " --out " + image.string()), 2);
  EXPECT_EQ(Floorplan("import " + plan + " --out " + link), 2);
  EXPECT_EQ(Floorplan("import " + plan + " --out " + (dir.path() / "w.yaml").string() +
                      " --mask-png " + image.string()),
            2);
  EXPECT_EQ(ReadText(image), before);
  const auto same = (dir.path() / "same.yaml").string();
  EXPECT_EQ(Floorplan("import " + plan + " --out " + same + " --mask-png " + same), 2);
  EXPECT_FALSE(std::filesystem::exists(same));
}

}  // namespace
}  // namespace crowdsim::floorplan
