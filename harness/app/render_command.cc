// render: one episode as a figure (svg, png, pdf) or an animation (gif, mp4).
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <iostream>
#include <optional>

#include "commands.h"
#include "crowdsim/bench/input_files.h"
#include "crowdsim/bench/plugin_registry.h"
#include "crowdsim/bench/suite.h"
#include "crowdsim/cli/args.h"
#include "crowdsim/render/animation.h"
#include "crowdsim/render/episode_replay.h"
#include "crowdsim/render/figure_output.h"
#include "crowdsim/render/output_format.h"

namespace crowdsim::cli {

namespace {

// An animation's frames on stderr once it has taken 2 s: in place on a terminal, else every 10%.
class FrameProgress {
 public:
  explicit FrameProgress(std::string out) : out_(std::move(out)) {}
  void Frame(size_t done, size_t total) {
    const auto now = Clock::now();
    if (now - start_ < std::chrono::seconds(2)) return;
    const size_t decile = total > 0 ? done * 10 / total : 10;
    if (tty_ ? now - last_ < std::chrono::milliseconds(200) && done != total
             : decile == last_decile_) {
      return;
    }
    last_ = now;
    last_decile_ = decile;
    const double secs = std::chrono::duration<double>(now - start_).count();
    const double eta = done > 0 ? secs * static_cast<double>(total - done) / done : 0.0;
    std::fprintf(stderr, "%s[render] %s: frame %zu/%zu  ETA %.0fs%s", tty_ ? "\r" : "",
                 out_.c_str(), done, total, eta, tty_ ? "   " : "\n");
    std::fflush(stderr);
    printed_ = true;
  }
  void Finish() const {
    if (printed_ && tty_) std::fprintf(stderr, "\n");
  }

 private:
  using Clock = std::chrono::steady_clock;
  std::string out_;
  bool tty_ = isatty(STDERR_FILENO);
  bool printed_ = false;
  Clock::time_point start_ = Clock::now(), last_{};
  size_t last_decile_ = 11;
};

}  // namespace

int RenderCommand(const std::vector<std::string>& args) {
  const Args a = Args::Parse(
      args,
      {"--row", "--episode", "--compare", "--sensors-at", "--speed", "--scale", "--out", "--set"},
      {"--animate"});
  if (a.positional.size() != 1) throw UsageError("render needs exactly one suite file");
  const auto out = a.Get("--out");
  if (!out)
    throw UsageError("render needs --out FILE.{svg,png,pdf} (or FILE.{gif,mp4} with --animate)");
  if (!a.Get("--row"))
    throw UsageError("render needs --row R (1-based as in the table, or a row label)");
  if (!a.Get("--episode"))
    throw UsageError("render needs --episode K (0-based, as in episodes.csv)");

  // Every argument is checked before the (slow) replay.
  render::OutputFormat format;
  try {
    format = render::FormatFromPath(*out);
  } catch (const std::invalid_argument& e) {
    throw UsageError(e.what());
  }
  const bool animate = a.Has("--animate");
  if (animate && !render::IsAnimation(format)) {
    throw UsageError("--animate writes .gif or .mp4, not '" + *out + "'");
  }
  if (!animate && render::IsAnimation(format)) {
    throw UsageError("'" + *out +
                     "' is an animation: add --animate (still figures: .svg, .png, .pdf)");
  }
  if (format == render::OutputFormat::kMp4 && !render::Mp4Supported()) {
    throw UsageError(
        "mp4 support was not built (libavcodec/libavformat were not found at configure time): "
        "use --out FILE.gif, or install libavcodec-dev libavformat-dev libswscale-dev and rebuild");
  }
  if (animate && a.Has("--sensors-at"))
    throw UsageError("--sensors-at draws still figures only (drop --animate)");
  if (!animate && a.Has("--speed")) throw UsageError("--speed needs --animate");
  double speed = 1.0;
  if (auto s = a.Get("--speed")) {
    try {
      size_t used = 0;
      speed = std::stod(*s, &used);
      if (used != s->size()) throw std::invalid_argument("");
    } catch (const std::exception&) {
      speed = -1.0;
    }
    if (!(speed > 0.0 && speed <= 100.0))
      throw UsageError("--speed must be a number in (0, 100] (x real time), got '" + *s + "'");
  }
  double png_scale = render::kDefaultPngScale;
  if (auto s = a.Get("--scale")) {
    if (format != render::OutputFormat::kPng) throw UsageError("--scale applies to .png only");
    try {
      size_t used = 0;
      png_scale = std::stod(*s, &used);
      if (used != s->size()) png_scale = -1.0;
    } catch (const std::exception&) {
      png_scale = -1.0;
    }
    if (!(png_scale > 0.0 && png_scale <= 8.0)) {
      throw UsageError("--scale must be a number in (0, 8] (PNG px per figure px), got '" + *s +
                       "'");
    }
  }
  std::optional<int> sensors_at;
  if (a.Has("--sensors-at")) sensors_at = a.GetInt("--sensors-at", 0, 0, 1'000'000);

  PluginRegistry registry;
  const std::optional<Suite> loaded =
      LoadOrReport(a.positional[0], registry, a.All("--set"), "render");
  if (!loaded) return 2;
  const Suite& suite = *loaded;
  size_t row = 0, compare_row = 0;
  int episode = 0;
  try {
    row = render::ResolveRow(suite, *a.Get("--row"));
    if (auto c = a.Get("--compare")) compare_row = render::ResolveRow(suite, *c);
    episode = render::ResolveEpisode(suite, *a.Get("--episode"));
  } catch (const std::invalid_argument& e) {
    throw UsageError(e.what());
  }

  render::ReplayedEpisode replay;
  auto named = [&](size_t r, const PluginError& e) {
    return PluginError("row '" + suite.rows[r].label + "' (rows[" + std::to_string(r) +
                       "]): " + e.what());
  };
  try {
    replay = render::ReplayForFigure(suite, row, episode, registry, sensors_at);
  } catch (const std::out_of_range& e) {
    throw UsageError(e.what());  // --sensors-at past the end: the message names the valid steps
  } catch (const PluginError& e) {
    throw named(row, e);  // a missing weights file: which row's
  }
  std::optional<render::ReplayedEpisode> compare;
  try {
    if (a.Get("--compare"))
      compare = render::ReplayForFigure(suite, compare_row, episode, registry);
  } catch (const PluginError& e) {
    throw named(compare_row, e);
  }
  if (const std::string over = OutputOverAnInput({*out}, SuiteInputFiles(suite)); !over.empty())
    throw UsageError(over);
  CreateFolderOf("--out", *out);  // every argument checked, the episodes replayed
  const render::EpisodeFigure figure =
      render::MakeFigure(suite, replay, compare ? &*compare : nullptr);
  if (animate) {
    render::AnimationOptions options;
    options.speed = speed;
    FrameProgress progress(*out);
    options.on_frame = [&](size_t done, size_t total) { progress.Frame(done, total); };
    render::WriteAnimation(figure, suite.sim.time_step, *out, options);
    progress.Finish();
  } else {
    render::WriteFigure(render::DrawEpisode(figure), *out, png_scale);
  }
  std::cerr << "wrote " << *out << " (" << figure.robots[0].label;
  if (compare) std::cerr << "; " << figure.robots[1].label;
  std::cerr << ")\n";
  return 0;
}

}  // namespace crowdsim::cli
