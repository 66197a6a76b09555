#include "crowdsim/render/output_format.h"

#include <algorithm>
#include <cctype>
#include <stdexcept>

namespace crowdsim::render {

OutputFormat FormatFromPath(const std::filesystem::path& path) {
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return std::tolower(c); });
  if (ext == ".svg") return OutputFormat::kSvg;
  if (ext == ".png") return OutputFormat::kPng;
  if (ext == ".pdf") return OutputFormat::kPdf;
  if (ext == ".gif") return OutputFormat::kGif;
  if (ext == ".mp4") return OutputFormat::kMp4;
  throw std::invalid_argument(
      "unknown output format '" + (ext.empty() ? std::string("(no extension)") : ext) + "' of '" +
      path.string() + "' (valid: .svg, .png, .pdf for figures; .gif, .mp4 with --animate)");
}

const char* Extension(OutputFormat format) {
  switch (format) {
    case OutputFormat::kSvg:
      return ".svg";
    case OutputFormat::kPng:
      return ".png";
    case OutputFormat::kPdf:
      return ".pdf";
    case OutputFormat::kGif:
      return ".gif";
    case OutputFormat::kMp4:
      return ".mp4";
  }
  return "";
}

bool IsAnimation(OutputFormat format) {
  return format == OutputFormat::kGif || format == OutputFormat::kMp4;
}

bool Mp4Supported() {
#ifdef CROWDSIM_RENDER_WITH_MP4
  return true;
#else
  return false;
#endif
}

}  // namespace crowdsim::render
