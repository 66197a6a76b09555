// MP4 (H.264 or MPEG-4 Part 2, whichever libavcodec offers) through libav, when this build
// found it at configure time.
#pragma once

#include <filesystem>
#include <memory>

#include "crowdsim/render/cairo_backend.h"

namespace crowdsim::render {

/// Writes one constant-frame-rate MP4; frames go in order, Finish() ends the file.
class Mp4Writer {
 public:
  /// Opens `path` for `width` x `height` video at `fps` frames per second. Throws
  /// std::runtime_error, also when this build has no MP4 support (Mp4Supported()).
  Mp4Writer(const std::filesystem::path& path, int width, int height, int fps);
  ~Mp4Writer();
  Mp4Writer(const Mp4Writer&) = delete;
  Mp4Writer& operator=(const Mp4Writer&) = delete;

  /// Appends one frame of the video's size.
  void AddFrame(const RgbImage& frame);
  /// Flushes the encoder, writes the trailer and puts the whole file at `path` (written beside it
  /// until then). A writer destroyed without Finish leaves `path` as it was.
  void Finish();

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace crowdsim::render
