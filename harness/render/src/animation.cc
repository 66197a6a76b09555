#include "crowdsim/render/animation.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include "crowdsim/render/cairo_backend.h"
#include "crowdsim/render/gif_writer.h"
#include "crowdsim/render/mp4_writer.h"
#include "crowdsim/render/output_format.h"

namespace crowdsim::render {
namespace {

// Browsers show GIF frames shorter than 2 cs at 10 cs; 4 cs (25 fps) is safely honoured.
constexpr double kMinGifFrameCs = 4.0;
constexpr int kMp4Fps = 25;

FigureOptions FrameOptions(const AnimationOptions& options) {
  FigureOptions f;
  f.max_side = options.max_side;
  f.time_labels = false;
  return f;
}

void WriteGif(const EpisodeFigure& figure, double time_step, const std::filesystem::path& path,
              const AnimationOptions& options) {
  const FigureOptions fopt = FrameOptions(options);
  const size_t n = FrameCount(figure);
  const std::vector<RgbImage> samples = {Rasterize(DrawEpisodeFrame(figure, 0, fopt)),
                                         Rasterize(DrawEpisodeFrame(figure, n - 1, fopt))};
  GifWriter gif(path, samples[0].width, samples[0].height, samples);
  const std::vector<TimedFrame> timeline =
      GifTimeline(n, time_step, options.speed, options.hold_end_s);
  for (size_t k = 0; k < timeline.size(); ++k) {
    gif.AddFrame(Rasterize(DrawEpisodeFrame(figure, timeline[k].frame, fopt)),
                 timeline[k].delay_cs);
    if (options.on_frame) options.on_frame(k + 1, timeline.size());
  }
  gif.Finish();
}

void WriteMp4(const EpisodeFigure& figure, double time_step, const std::filesystem::path& path,
              const AnimationOptions& options) {
  const FigureOptions fopt = FrameOptions(options);
  const size_t n = FrameCount(figure);
  RgbImage first = Rasterize(DrawEpisodeFrame(figure, 0, fopt));
  Mp4Writer mp4(path, first.width, first.height, kMp4Fps);
  // Constant frame rate: each video frame shows the trajectory frame of its playback time.
  const double episode_s = (n - 1) * time_step / options.speed;
  const int video_frames =
      static_cast<int>(std::ceil((episode_s + options.hold_end_s) * kMp4Fps)) + 1;
  size_t shown = 0;
  RgbImage image = std::move(first);
  for (int k = 0; k < video_frames; ++k) {
    const double sim_time = k * options.speed / kMp4Fps;
    const size_t f = std::min(n - 1, static_cast<size_t>(std::floor(sim_time / time_step + 1e-9)));
    if (f != shown) {
      image = Rasterize(DrawEpisodeFrame(figure, f, fopt));
      shown = f;
    }
    mp4.AddFrame(image);
    if (options.on_frame)
      options.on_frame(static_cast<size_t>(k) + 1, static_cast<size_t>(video_frames));
  }
  mp4.Finish();
}

}  // namespace

std::vector<TimedFrame> GifTimeline(size_t frames, double time_step, double speed,
                                    double hold_end_s) {
  std::vector<TimedFrame> out;
  if (frames == 0) return out;
  const double step_cs = time_step * 100.0 / speed;
  const size_t stride =
      std::max<size_t>(1, static_cast<size_t>(std::ceil(kMinGifFrameCs / step_cs - 1e-9)));
  std::vector<size_t> shown;
  for (size_t i = 0; i < frames; i += stride) shown.push_back(i);
  if (shown.back() != frames - 1) shown.push_back(frames - 1);  // always end on the outcome
  // Delays from rounded ideal start times, so rounding never accumulates.
  for (size_t k = 0; k + 1 < shown.size(); ++k) {
    const long start = std::lround(shown[k] * step_cs);
    const long end = std::lround(shown[k + 1] * step_cs);
    out.push_back({shown[k], static_cast<int>(std::max(2L, end - start))});
  }
  out.push_back(
      {shown.back(), static_cast<int>(std::max(2L, std::lround(step_cs + hold_end_s * 100.0)))});
  return out;
}

void WriteAnimation(const EpisodeFigure& figure, double time_step,
                    const std::filesystem::path& path, const AnimationOptions& options) {
  if (!(options.speed > 0.0 && options.speed <= 100.0)) {
    throw std::invalid_argument("--speed must be in (0, 100] (x real time), got " +
                                std::to_string(options.speed));
  }
  if (!(time_step > 0.0)) throw std::invalid_argument("the animation needs a positive time step");
  if (FrameCount(figure) == 0)
    throw std::invalid_argument("the episode has no recorded frames to animate");
  const OutputFormat format = FormatFromPath(path);
  switch (format) {
    case OutputFormat::kGif:
      WriteGif(figure, time_step, path, options);
      return;
    case OutputFormat::kMp4:
      if (!Mp4Supported()) {
        throw std::invalid_argument(
            "cannot write '" + path.string() +
            "': mp4 support was not built (libavcodec/libavformat were not found when "
            "configuring; install libavcodec-dev libavformat-dev libswscale-dev and "
            "reconfigure), use .gif instead");
      }
      WriteMp4(figure, time_step, path, options);
      return;
    default:
      break;
  }
  throw std::invalid_argument("--animate writes .gif or .mp4, not '" + path.string() +
                              "' (still figures: .svg, .png, .pdf without --animate)");
}

}  // namespace crowdsim::render
