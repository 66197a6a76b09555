// Output formats chosen by file extension, with the error that lists the valid ones.
#pragma once

#include <filesystem>
#include <string>

namespace crowdsim::render {

/// The file formats render writes (stills: svg, png, pdf; animations: gif, mp4).
enum class OutputFormat { kSvg, kPng, kPdf, kGif, kMp4 };

/// The format of `path` from its extension (case-insensitive). Throws std::invalid_argument
/// naming the extension and the valid choices.
OutputFormat FormatFromPath(const std::filesystem::path& path);

/// ".svg", ".png", ...
const char* Extension(OutputFormat format);

/// True for the animation formats (gif, mp4).
bool IsAnimation(OutputFormat format);

/// True when this build can write MP4 (libav found at configure time).
bool Mp4Supported();

}  // namespace crowdsim::render
