// An animated GIF written frame by frame through giflib: one global palette (the most frequent
// colours of sample frames, so flat fills stay exact, plus a coarse colour cube for the rest)
// and only the changed rectangle of each frame.
#pragma once

#include <filesystem>
#include <memory>
#include <span>

#include "crowdsim/render/cairo_backend.h"

namespace crowdsim::render {

/// Writes one looping GIF; frames go in order, Finish() ends the file.
class GifWriter {
 public:
  /// Starts a looping animation for `path` of `width` x `height` px whose 256-colour palette is
  /// taken from `palette_samples` (e.g. the first and last frames: every flat colour shows
  /// there). Throws std::runtime_error.
  GifWriter(const std::filesystem::path& path, int width, int height,
            std::span<const RgbImage> palette_samples);
  ~GifWriter();
  GifWriter(const GifWriter&) = delete;
  GifWriter& operator=(const GifWriter&) = delete;

  /// Adds a frame shown for `delay_cs` hundredths of a second (>= 2; browsers slow faster
  /// frames down). The frame must have the animation's size.
  void AddFrame(const RgbImage& frame, int delay_cs);
  /// Writes the trailer and puts the whole file at `path` (written beside it until then). A
  /// writer destroyed without Finish leaves `path` as it was.
  void Finish();

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace crowdsim::render
