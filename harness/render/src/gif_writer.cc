#include "crowdsim/render/gif_writer.h"

#include <fcntl.h>
#include <gif_lib.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <map>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <vector>

#include "atomic_file.h"

namespace crowdsim::render {
namespace {

std::uint32_t Pack(const std::uint8_t* p) {
  return (std::uint32_t(p[0]) << 16) | (std::uint32_t(p[1]) << 8) | p[2];
}

std::string GifErrorText(int code) {
  const char* s = GifErrorString(code);
  return s ? s : ("giflib error " + std::to_string(code));
}

}  // namespace

struct GifWriter::Impl {
  GifFileType* gif = nullptr;
  int width = 0;
  int height = 0;
  std::filesystem::path path;
  std::string temp;  // the file written, renamed to `path` by Finish; removed if never finished
  std::vector<std::uint32_t> palette;                      // packed RGB, 256 entries
  std::unordered_map<std::uint32_t, std::uint8_t> lookup;  // colour -> nearest palette index
  std::vector<std::uint8_t> previous;                      // last frame's indices
  bool has_previous = false;

  std::uint8_t Index(std::uint32_t c) {
    auto it = lookup.find(c);
    if (it != lookup.end()) return it->second;
    int best = 0;
    long best_d = -1;
    for (size_t i = 0; i < palette.size(); ++i) {
      const long dr = long((c >> 16) & 255) - long((palette[i] >> 16) & 255);
      const long dg = long((c >> 8) & 255) - long((palette[i] >> 8) & 255);
      const long db = long(c & 255) - long(palette[i] & 255);
      // Green weighs most to the eye.
      const long d = 3 * dr * dr + 4 * dg * dg + 2 * db * db;
      if (best_d < 0 || d < best_d) {
        best_d = d;
        best = static_cast<int>(i);
      }
    }
    lookup.emplace(c, static_cast<std::uint8_t>(best));
    return static_cast<std::uint8_t>(best);
  }

  void Check(int status, const char* what) const {
    if (status != GIF_ERROR) return;
    throw std::runtime_error("cannot write " + path.string() + " (" + what +
                             "): " + GifErrorText(gif ? gif->Error : 0));
  }
};

GifWriter::GifWriter(const std::filesystem::path& path, int width, int height,
                     std::span<const RgbImage> palette_samples)
    : impl_(std::make_unique<Impl>()) {
  Impl& m = *impl_;
  m.width = width;
  m.height = height;
  m.path = path;

  // Palette: a 3x3x3 cube keeps far-off colours close; the rest are the most frequent colours
  // (ties broken by value, so the palette and the file are deterministic).
  constexpr int kCube = 27;
  std::map<std::uint32_t, long> histogram;
  for (const RgbImage& img : palette_samples) {
    for (size_t i = 0; i + 2 < img.pixels.size(); i += 3) ++histogram[Pack(&img.pixels[i])];
  }
  std::vector<std::pair<long, std::uint32_t>> by_count;
  for (const auto& [c, n] : histogram) by_count.emplace_back(-n, c);
  std::sort(by_count.begin(), by_count.end());
  for (const auto& [n, c] : by_count) {
    if (m.palette.size() >= 256 - kCube) break;
    m.palette.push_back(c);
  }
  for (int r = 0; r < 3; ++r) {
    for (int g = 0; g < 3; ++g) {
      for (int b = 0; b < 3; ++b) {
        const std::uint32_t c = (std::uint32_t(std::min(255, r * 128)) << 16) |
                                (std::uint32_t(std::min(255, g * 128)) << 8) |
                                std::uint32_t(std::min(255, b * 128));
        if (std::find(m.palette.begin(), m.palette.end(), c) == m.palette.end())
          m.palette.push_back(c);
      }
    }
  }
  while (m.palette.size() < 256) m.palette.push_back(0);
  m.palette.resize(256);

  // A new file beside `path`, renamed over it when whole: an interrupted render leaves the
  // previous animation as it was.
  const int fd = common::CreateBeside(path, &m.temp);
  int error = 0;
  m.gif = EGifOpenFileHandle(fd, &error);
  if (m.gif == nullptr) {
    close(fd);
    unlink(m.temp.c_str());
    throw std::runtime_error("cannot create " + path.string() + ": " + GifErrorText(error));
  }
  EGifSetGifVersion(m.gif, true);
  std::vector<GifColorType> colors(256);
  for (int i = 0; i < 256; ++i) {
    colors[i].Red = static_cast<GifByteType>((m.palette[i] >> 16) & 255);
    colors[i].Green = static_cast<GifByteType>((m.palette[i] >> 8) & 255);
    colors[i].Blue = static_cast<GifByteType>(m.palette[i] & 255);
  }
  ColorMapObject* cmap = GifMakeMapObject(256, colors.data());
  const int st = EGifPutScreenDesc(m.gif, width, height, 8, 0, cmap);
  GifFreeMapObject(cmap);
  m.Check(st, "screen descriptor");
  // NETSCAPE2.0 application extension: loop forever.
  m.Check(EGifPutExtensionLeader(m.gif, APPLICATION_EXT_FUNC_CODE), "loop extension");
  m.Check(EGifPutExtensionBlock(m.gif, 11, "NETSCAPE2.0"), "loop extension");
  const unsigned char loop[3] = {1, 0, 0};
  m.Check(EGifPutExtensionBlock(m.gif, 3, loop), "loop extension");
  m.Check(EGifPutExtensionTrailer(m.gif), "loop extension");
}

GifWriter::~GifWriter() {
  if (impl_ && impl_->gif) {  // never finished: the animation is not whole
    int error = 0;
    EGifCloseFile(impl_->gif, &error);
    unlink(impl_->temp.c_str());
  }
}

void GifWriter::AddFrame(const RgbImage& frame, int delay_cs) {
  Impl& m = *impl_;
  if (m.gif == nullptr) throw std::logic_error("GifWriter::AddFrame after Finish");
  if (frame.width != m.width || frame.height != m.height) {
    throw std::invalid_argument("GIF frame is " + std::to_string(frame.width) + "x" +
                                std::to_string(frame.height) + ", the animation is " +
                                std::to_string(m.width) + "x" + std::to_string(m.height));
  }
  std::vector<std::uint8_t> indices(static_cast<size_t>(m.width) * m.height);
  for (size_t i = 0; i < indices.size(); ++i) indices[i] = m.Index(Pack(&frame.pixels[i * 3]));

  // Only the rectangle that changed since the previous frame (disposal: keep the previous one).
  int x0 = 0, y0 = 0, x1 = m.width - 1, y1 = m.height - 1;
  if (m.has_previous) {
    x0 = m.width;
    y0 = m.height;
    x1 = -1;
    y1 = -1;
    for (int y = 0; y < m.height; ++y) {
      for (int x = 0; x < m.width; ++x) {
        const size_t i = static_cast<size_t>(y) * m.width + x;
        if (indices[i] == m.previous[i]) continue;
        x0 = std::min(x0, x);
        x1 = std::max(x1, x);
        y0 = std::min(y0, y);
        y1 = std::max(y1, y);
      }
    }
    if (x1 < 0) x0 = y0 = x1 = y1 = 0;  // nothing changed: a 1-pixel frame carries the delay
  }
  GraphicsControlBlock gcb;
  gcb.DisposalMode = DISPOSE_DO_NOT;
  gcb.UserInputFlag = false;
  gcb.DelayTime = std::max(2, delay_cs);
  gcb.TransparentColor = NO_TRANSPARENT_COLOR;
  GifByteType ext[4];
  EGifGCBToExtension(&gcb, ext);
  m.Check(EGifPutExtension(m.gif, GRAPHICS_EXT_FUNC_CODE, 4, ext), "frame delay");
  const int w = x1 - x0 + 1;
  m.Check(EGifPutImageDesc(m.gif, x0, y0, w, y1 - y0 + 1, false, nullptr), "image descriptor");
  for (int y = y0; y <= y1; ++y) {
    m.Check(EGifPutLine(m.gif, &indices[static_cast<size_t>(y) * m.width + x0], w), "pixels");
  }
  m.previous = std::move(indices);
  m.has_previous = true;
}

void GifWriter::Finish() {
  Impl& m = *impl_;
  if (m.gif == nullptr) return;
  int error = 0;
  const int st = EGifCloseFile(m.gif, &error);
  m.gif = nullptr;
  if (st == GIF_ERROR) {
    unlink(m.temp.c_str());
    throw std::runtime_error("cannot finish " + m.path.string() + ": " + GifErrorText(error));
  }
  if (std::rename(m.temp.c_str(), m.path.c_str()) != 0) {
    const int err = errno;
    unlink(m.temp.c_str());
    throw std::runtime_error("cannot replace " + m.path.string() + ": " + std::strerror(err));
  }
}

}  // namespace crowdsim::render
