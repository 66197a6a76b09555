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

}  // namespace
}  // namespace crowdsim::floorplan
