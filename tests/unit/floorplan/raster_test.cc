// Image reading, resampling, morphology and the rectangle decomposition.
#include <gtest/gtest.h>
#include <png.h>

#include <cstring>
#include <numeric>

#include "floorplan/floorplan_error.h"
#include "floorplan/image_io.h"
#include "floorplan/morphology.h"
#include "floorplan/navigable_component.h"
#include "floorplan/rect_decomposition.h"
#include "floorplan/resample.h"
#include "floorplan_test_util.h"
#include "temp_dir.h"

namespace crowdsim::floorplan {
namespace {

using crowdsim::testing::TempDir;
using testing::Fill;
using testing::WritePgm;

TEST(ImageIoTest, PngRoundTripAndPgmAgree) {
  TempDir dir;
  Grid g(7, 5, 1);
  Fill(g, 1, 2, 3, 4, 0);
  WritePng(g, dir.path() / "g.png");
  WritePgm(g, dir.path() / "g.pgm");
  EXPECT_EQ(ReadBinaryImage(dir.path() / "g.png"), g);
  EXPECT_EQ(ReadBinaryImage(dir.path() / "g.pgm"), g);
}

TEST(ImageIoTest, AsciiPgm) {
  TempDir dir;
  const auto p = dir.Write("a.pgm", "P2\n# comment\n3 2\n15\n0 15 8\n7 0 15\n");
  Grid want(3, 2, 1);
  want(0, 0) = 0, want(1, 0) = 0, want(1, 1) = 0;
  EXPECT_EQ(ReadBinaryImage(p), want);
}

TEST(ImageIoTest, RgbaTransparentIsFreeAndDarkOpaqueIsBlocked) {
  TempDir dir;
  // Pixels: transparent black, opaque black, opaque white, opaque dark red.
  const unsigned char rgba[16] = {0, 0, 0, 0, 0, 0, 0, 255, 255, 255, 255, 255, 90, 10, 10, 255};
  png_image image;
  std::memset(&image, 0, sizeof(image));
  image.version = PNG_IMAGE_VERSION;
  image.width = 4;
  image.height = 1;
  image.format = PNG_FORMAT_RGBA;
  const auto path = dir.path() / "rgba.png";
  ASSERT_TRUE(png_image_write_to_file(&image, path.c_str(), 0, rgba, 0, nullptr));
  const Grid g = ReadBinaryImage(path);
  ASSERT_EQ(g.width, 4);
  EXPECT_EQ(g.cells, (std::vector<std::uint8_t>{1, 0, 1, 0}));
}

/// CRC-32 (PNG's chunk checksum), bit by bit.
std::uint32_t Crc32(const std::string& bytes) {
  std::uint32_t c = 0xFFFFFFFFu;
  for (unsigned char b : bytes) {
    c ^= b;
    for (int k = 0; k < 8; ++k) c = (c >> 1) ^ (0xEDB88320u & (0u - (c & 1u)));
  }
  return ~c;
}

std::string BigEndian(std::uint32_t x) {
  return {static_cast<char>(x >> 24), static_cast<char>(x >> 16), static_cast<char>(x >> 8),
          static_cast<char>(x)};
}

/// A PNG whose header claims width x height (8-bit gray) and whose data is a few bytes.
std::string LyingPng(std::uint32_t width, std::uint32_t height) {
  auto chunk = [](const std::string& type, const std::string& data) {
    return BigEndian(static_cast<std::uint32_t>(data.size())) + type + data +
           BigEndian(Crc32(type + data));
  };
  const std::string ihdr =
      BigEndian(width) + BigEndian(height) + std::string("\x08\x00\x00\x00\x00", 5);
  const std::string idat("\x78\x9c\x63\x00\x00\x00\x01\x00\x01", 9);  // zlib of one zero byte
  return std::string("\x89PNG\r\n\x1a\n", 8) + chunk("IHDR", ihdr) + chunk("IDAT", idat) +
         chunk("IEND", "");
}

TEST(ImageIoTest, HeadersClaimingMorePixelsThanAllowedOrStoredAreRefusedBeforeAllocating) {
  TempDir dir;
  auto error = [](const std::filesystem::path& p) -> std::string {
    try {
      ReadBinaryImage(p);
    } catch (const FloorplanError& e) {
      return e.what();
    }
    return "";
  };
  // 23 bytes claiming 10^10 pixels (once ~10 GB and 44 s before failing).
  EXPECT_NE(
      error(dir.Write("huge.pgm", "P5\n100000 100000\n255\nab")).find("more than the 100 million"),
      std::string::npos);
  EXPECT_NE(error(dir.Write("lie.pgm", "P5\n9000 9000\n255\nab")).find("truncated PGM pixel data"),
            std::string::npos);
  EXPECT_NE(error(dir.Write("lie_ascii.pgm", "P2\n9000 9000\n255\n0 1 0\n"))
                .find("truncated PGM pixel data"),
            std::string::npos);
  EXPECT_NE(error(dir.Write("huge.png", LyingPng(30000, 30000))).find("more than the 100 million"),
            std::string::npos);
  EXPECT_NE(error(dir.Write("lie.png", LyingPng(9000, 9000))).find("more than its"),
            std::string::npos)
      << error(dir.path() / "lie.png");
}

TEST(ResampleTest, MajorityAndThinStrokes) {
  // 0.05 m/px -> 0.1 m: each cell is 2x2 pixels.
  Grid src(4, 2, 1);
  Fill(src, 0, 0, 1, 1, 0);  // cell 0 fully blocked
  src(0, 2) = 0;             // cell 1: a quarter blocked
  const Grid majority = Resample(src, 0.05, 0.1, 0.5);
  EXPECT_EQ(majority.cells, (std::vector<std::uint8_t>{0, 1}));
  const Grid thin = Resample(src, 0.05, 0.1, 0.25);
  EXPECT_EQ(thin.cells, (std::vector<std::uint8_t>{0, 0}));
  EXPECT_EQ(Resample(src, 0.1, 0.1, 0.5), src);
}

TEST(MorphologyTest, ClosingFillsOnePixelGapsAndKeepsWalls) {
  Grid g(20, 20, 1);
  g(5, 5) = 0;                // a speck
  Fill(g, 10, 2, 10, 8, 0);   // a one-cell crack
  Fill(g, 2, 12, 17, 14, 0);  // a three-cell wall
  const Grid closed = CloseNavigable(g, 1);
  EXPECT_EQ(closed(5, 5), 1);
  for (int c = 2; c <= 8; ++c) EXPECT_EQ(closed(10, c), 1) << c;
  for (int r = 2; r <= 17; ++r) {
    for (int c = 12; c <= 14; ++c) EXPECT_EQ(closed(r, c), 0) << r << "," << c;
  }
  EXPECT_EQ(CloseNavigable(closed, 1), closed);  // idempotent: the paper's 2nd pass is a no-op
}

TEST(MorphologyTest, StrokePreservingClosingKeepsThinWallsDropsSpecks) {
  Grid g(20, 20, 1);
  g(5, 5) = 0;
  Fill(g, 2, 10, 17, 10, 0);  // a one-cell wall of 16 cells
  const Grid closed = CloseNavigableKeepingStrokes(g, 1, 4);
  EXPECT_EQ(closed(5, 5), 1);
  for (int r = 2; r <= 17; ++r) EXPECT_EQ(closed(r, 10), 0);
}

TEST(MorphologyTest, DistanceTransformIsExact) {
  Grid g(9, 9, 1);
  g(4, 4) = 0;
  const auto d = SquaredDistanceToZero(g, /*outside_is_zero=*/false);
  for (int r = 0; r < 9; ++r) {
    for (int c = 0; c < 9; ++c) {
      EXPECT_DOUBLE_EQ(d[g.Index(r, c)], double((r - 4) * (r - 4) + (c - 4) * (c - 4)));
    }
  }
  const auto border = SquaredDistanceToZero(Grid(5, 5, 1), true);
  EXPECT_DOUBLE_EQ(border[Grid(5, 5).Index(2, 2)], 9.0);  // three cells to the padding
}

TEST(ComponentTest, NarrowDoorSplitsComponents) {
  // Two 3 x 3 m rooms joined by a 0.4 m gap: too narrow for a 0.3 m disc.
  Grid g(65, 32, 0);
  Fill(g, 1, 1, 30, 30, 1);
  Fill(g, 1, 34, 30, 63, 1);
  Fill(g, 14, 31, 17, 33, 1);
  const DiscComponent comp = LargestDiscComponent(g, 3.0);
  EXPECT_EQ(comp.components, 2);
  EXPECT_EQ(comp.reach(15, 10), 1);
  EXPECT_EQ(comp.reach(15, 50), 0);
  // Widen the door to 1 m: one component.
  Fill(g, 10, 31, 19, 33, 1);
  EXPECT_EQ(LargestDiscComponent(g, 3.0).components, 1);
}

TEST(DecompositionTest, KnownRectanglesComeBackExactly) {
  Grid g(40, 30, 1);
  const std::vector<CellRect> want = {
      {2, 3, 21, 12}, {5, 20, 14, 35}, {24, 1, 27, 30}, {0, 38, 1, 39}};
  for (const auto& r : want) Fill(g, r.row0, r.col0, r.row1, r.col1, 0);
  std::vector<CellRect> got = DecomposeBlocked(g);
  ASSERT_EQ(got.size(), want.size());
  // Largest first: 200 (20x10), 160, 120, 4.
  EXPECT_EQ(got, want);
}

TEST(DecompositionTest, CoversExactlyTheBlockedCellsLargestFirst) {
  Grid g(50, 40, 1);
  // An L, a ring and scattered specks: overlapping candidates.
  Fill(g, 5, 5, 30, 9, 0);
  Fill(g, 26, 5, 30, 40, 0);
  Fill(g, 2, 20, 20, 40, 0);
  Fill(g, 6, 24, 16, 36, 1);
  for (int k = 0; k < 30; ++k) g((k * 7) % 40, (k * 13) % 50) = 0;
  const auto rects = DecomposeBlocked(g);
  Grid cover(g.width, g.height, 0);
  long total = 0;
  for (size_t k = 0; k < rects.size(); ++k) {
    if (k > 0) {
      EXPECT_LE(rects[k].Area(), rects[k - 1].Area());
    }
    for (int r = rects[k].row0; r <= rects[k].row1; ++r) {
      for (int c = rects[k].col0; c <= rects[k].col1; ++c) {
        EXPECT_EQ(g(r, c), 0);
        EXPECT_EQ(cover(r, c), 0) << "overlap";
        cover(r, c) = 1;
      }
    }
    total += rects[k].Area();
  }
  EXPECT_EQ(total, long(g.cells.size()) - g.Count());
  EXPECT_EQ(RectanglesForCoverage(rects, total, 1.0), static_cast<int>(rects.size()));
  // The capped run is a prefix of the full one.
  const auto first5 = DecomposeBlocked(g, 5);
  EXPECT_EQ(first5, std::vector<CellRect>(rects.begin(), rects.begin() + 5));
}

TEST(DecompositionTest, AllBlockedIsOneRectangle) {
  const auto rects = DecomposeBlocked(Grid(13, 7, 0));
  ASSERT_EQ(rects.size(), 1u);
  EXPECT_EQ(rects[0], (CellRect{0, 0, 6, 12}));
}

}  // namespace
}  // namespace crowdsim::floorplan
