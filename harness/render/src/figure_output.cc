#include "crowdsim/render/figure_output.h"

#include <fstream>
#include <stdexcept>

#include "crowdsim/render/cairo_backend.h"
#include "crowdsim/render/output_format.h"
#include "crowdsim/render/svg_writer.h"

namespace crowdsim::render {

void WriteFigure(const Drawing& drawing, const std::filesystem::path& path, double png_scale) {
  const OutputFormat format = FormatFromPath(path);
  switch (format) {
    case OutputFormat::kSvg: {
      std::ofstream out(path, std::ios::binary);
      out << ToSvg(drawing);
      if (!out) throw std::runtime_error("cannot write " + path.string());
      return;
    }
    case OutputFormat::kPng:
      WritePng(drawing, path, png_scale);
      return;
    case OutputFormat::kPdf:
      WritePdf(drawing, path);
      return;
    case OutputFormat::kGif:
    case OutputFormat::kMp4:
      break;
  }
  throw std::invalid_argument(
      "'" + path.string() +
      "' is an animation format: use --animate (still figures: .svg, .png, .pdf)");
}

}  // namespace crowdsim::render
