#include "image_io.h"

#include <png.h>

#include <cctype>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <iterator>
#include <vector>

#include "floorplan_error.h"

namespace crowdsim::floorplan {
namespace {

[[noreturn]] void Fail(const std::filesystem::path& path, const std::string& what) {
  throw FloorplanError(path.string() + ": " + what);
}

/// The largest image read: 100 million pixels (10,000 x 10,000, a 500 m building at 5 cm per
/// pixel). Checked from the header, before any pixel memory is allocated.
constexpr std::uint64_t kMaxPixels = 100'000'000;

void CheckSize(const std::filesystem::path& path, std::uint64_t width, std::uint64_t height) {
  if (width * height > kMaxPixels) {
    Fail(path, "the header claims " + std::to_string(width) + " x " + std::to_string(height) +
                   " pixels, more than the 100 million this importer reads; downscale the image");
  }
}

std::vector<unsigned char> ReadBytes(const std::filesystem::path& path) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) {
    Fail(path,
         "is a folder, not an image: give one PNG or PGM file of it (`floorplan dataset "
         "--source DIR` imports a folder of Gibson and HM3D plans)");
  }
  if (!std::filesystem::is_regular_file(path, ec)) {
    Fail(path, "no such image file (check the path)");
  }
  std::ifstream f(path, std::ios::binary);
  std::vector<unsigned char> bytes((std::istreambuf_iterator<char>(f)),
                                   std::istreambuf_iterator<char>());
  if (bytes.empty()) Fail(path, "the file is empty (give a PNG or PGM floor-plan image)");
  return bytes;
}

Grid DecodePng(const std::filesystem::path& path, const std::vector<unsigned char>& bytes) {
  png_image image;
  std::memset(&image, 0, sizeof(image));
  image.version = PNG_IMAGE_VERSION;
  if (!png_image_begin_read_from_memory(&image, bytes.data(), bytes.size())) {
    Fail(path, std::string("not a readable PNG (") + image.message + "); re-export it as PNG");
  }
  // RGBA 8 bit whatever the stored colour type: libpng expands palettes, gray and 16 bit.
  image.format = PNG_FORMAT_RGBA;
  if (image.width == 0 || image.height == 0) {
    png_image_free(&image);
    Fail(path, "the image has no pixels");
  }
  // Deflate compresses at most ~1032:1, and a stored row holds at least one byte per pixel
  // plus a filter byte: a header that claims more than the data can hold is a broken file.
  const std::uint64_t width = image.width, height = image.height;
  if (width * height > kMaxPixels ||
      height * (width + 1) > 1100 * static_cast<std::uint64_t>(bytes.size())) {
    png_image_free(&image);
    if (width * height > kMaxPixels) CheckSize(path, width, height);
    Fail(path, "the header claims " + std::to_string(width) + " x " + std::to_string(height) +
                   " pixels, more than its " + std::to_string(bytes.size()) +
                   " bytes of compressed data can hold (truncated or corrupt PNG)");
  }
  std::vector<unsigned char> rgba(PNG_IMAGE_SIZE(image));
  if (!png_image_finish_read(&image, nullptr, rgba.data(), 0, nullptr)) {
    Fail(path, std::string("corrupt PNG data (") + image.message + "); re-export it");
  }
  Grid g(static_cast<int>(image.width), static_cast<int>(image.height));
  for (size_t i = 0; i < g.cells.size(); ++i) {
    const unsigned char* p = &rgba[4 * i];
    // Rec. 601 luma in integers; alpha 0 is the page, which is free space.
    const int luma = (299 * p[0] + 587 * p[1] + 114 * p[2]) / 1000;
    g.cells[i] = (p[3] == 0 || luma >= 128) ? 1 : 0;
  }
  return g;
}

// Next whitespace-separated PGM header token, skipping '#' comments.
std::string NextToken(const std::vector<unsigned char>& b, size_t* pos) {
  while (*pos < b.size()) {
    if (b[*pos] == '#') {
      while (*pos < b.size() && b[*pos] != '\n') ++*pos;
    } else if (std::isspace(b[*pos])) {
      ++*pos;
    } else {
      break;
    }
  }
  std::string tok;
  while (*pos < b.size() && !std::isspace(b[*pos]) && b[*pos] != '#')
    tok += static_cast<char>(b[(*pos)++]);
  return tok;
}

int HeaderNumber(const std::filesystem::path& path, const std::vector<unsigned char>& b,
                 size_t* pos, const char* what) {
  const std::string tok = NextToken(b, pos);
  if (tok.empty() || tok.find_first_not_of("0123456789") != std::string::npos || tok.size() > 9) {
    Fail(path, std::string("bad PGM header: ") + what + " is not a positive number");
  }
  return std::stoi(tok);
}

Grid DecodePgm(const std::filesystem::path& path, const std::vector<unsigned char>& bytes) {
  size_t pos = 2;
  const bool binary = bytes[1] == '5';
  const int w = HeaderNumber(path, bytes, &pos, "width");
  const int h = HeaderNumber(path, bytes, &pos, "height");
  const int maxval = HeaderNumber(path, bytes, &pos, "maxval");
  if (w <= 0 || h <= 0) Fail(path, "the image has no pixels");
  if (maxval <= 0 || maxval > 65535) Fail(path, "bad PGM maxval (must be 1..65535)");
  CheckSize(path, static_cast<std::uint64_t>(w), static_cast<std::uint64_t>(h));
  const size_t n = static_cast<size_t>(w) * static_cast<size_t>(h);
  const size_t bpp = maxval > 255 ? 2 : 1;
  // The pixel data must be there before the grid is allocated (binary: bpp bytes a pixel;
  // ASCII: at least a digit and a separator a pixel).
  if (binary ? bytes.size() < pos + 1 + n * bpp : bytes.size() - pos < 2 * n - 1) {
    Fail(path, "truncated PGM pixel data: the header claims " + std::to_string(w) + " x " +
                   std::to_string(h) + " pixels, the file holds " + std::to_string(bytes.size()) +
                   " bytes");
  }
  Grid g(w, h);
  if (binary) {
    ++pos;  // exactly one whitespace byte ends the header
    for (size_t i = 0; i < n; ++i) {
      const unsigned char* p = &bytes[pos + i * bpp];
      const int v = bpp == 2 ? (p[0] << 8 | p[1]) : p[0];
      g.cells[i] = 2 * v >= maxval ? 1 : 0;
    }
  } else {
    for (size_t i = 0; i < n; ++i) {
      const std::string tok = NextToken(bytes, &pos);
      if (tok.empty()) Fail(path, "truncated ASCII PGM pixel data");
      g.cells[i] = 2 * std::stoi(tok) >= maxval ? 1 : 0;
    }
  }
  return g;
}

void AppendToString(png_structp png, png_bytep data, png_size_t length) {
  auto* out = static_cast<std::string*>(png_get_io_ptr(png));
  out->append(reinterpret_cast<const char*>(data), length);
}

}  // namespace

Grid ReadBinaryImage(const std::filesystem::path& path) {
  const std::vector<unsigned char> bytes = ReadBytes(path);
  static const unsigned char kPngSignature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  if (bytes.size() >= 8 && std::memcmp(bytes.data(), kPngSignature, 8) == 0) {
    return DecodePng(path, bytes);
  }
  if (bytes.size() >= 3 && bytes[0] == 'P' && (bytes[1] == '2' || bytes[1] == '5') &&
      std::isspace(bytes[2])) {
    return DecodePgm(path, bytes);
  }
  Fail(path,
       "not a PNG or PGM image (convert it to a gray or RGBA PNG: navigable white, "
       "blocked black)");
}

std::string EncodePng(const Grid& grid, unsigned char blocked_gray) {
  std::string out;
  std::vector<png_byte> row(grid.width);  // before setjmp: a longjmp must not skip a destructor
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
  png_infop info = png ? png_create_info_struct(png) : nullptr;
  if (!png || !info || setjmp(png_jmpbuf(png))) {
    png_destroy_write_struct(&png, &info);
    throw FloorplanError("PNG encoding failed (out of memory?)");
  }
  png_set_write_fn(png, &out, &AppendToString, nullptr);
  png_set_IHDR(png, info, grid.width, grid.height, 8, PNG_COLOR_TYPE_GRAY, PNG_INTERLACE_NONE,
               PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  png_write_info(png, info);
  for (int r = 0; r < grid.height; ++r) {
    for (int c = 0; c < grid.width; ++c) row[c] = grid.cells[grid.Index(r, c)] ? 255 : blocked_gray;
    png_write_row(png, row.data());
  }
  png_write_end(png, nullptr);
  png_destroy_write_struct(&png, &info);
  return out;
}

void WritePng(const Grid& grid, const std::filesystem::path& path) {
  const std::string bytes = EncodePng(grid);
  std::ofstream f(path, std::ios::binary);
  f.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  if (!f) throw FloorplanError(path.string() + ": cannot write (check the folder exists)");
}

}  // namespace crowdsim::floorplan
