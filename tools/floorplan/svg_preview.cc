#include "svg_preview.h"

#include <algorithm>
#include <cstdio>
#include <sstream>

#include "crowdsim/render/base64.h"
#include "crowdsim/render/xml_escape.h"
#include "image_io.h"

namespace crowdsim::floorplan {
namespace {

constexpr double kPixelsPerMetre = 24.0;
constexpr double kHeader = 44.0;  // px of text above the map

std::string Num(double x) {
  char buf[32];
  std::snprintf(buf, sizeof(buf), "%.2f", x);
  return buf;
}

double Stat(const WorldFile& w, const std::string& key, double fallback) {
  for (const auto& [k, v] : w.stats) {
    if (k == key) return v;
  }
  return fallback;
}

}  // namespace

std::string RenderPreviewSvg(const WorldFile& world, const PreviewMask& mask, int pairs_shown) {
  const Rect& b = world.bounds;
  const double width = b.Size().x() * kPixelsPerMetre;
  const double height = b.Size().y() * kPixelsPerMetre;
  auto X = [&](double x) { return Num((x - b.min.x()) * kPixelsPerMetre); };
  auto Y = [&](double y) { return Num(kHeader + (b.max.y() - y) * kPixelsPerMetre); };
  auto L = [&](double metres) { return Num(metres * kPixelsPerMetre); };

  std::ostringstream os;
  os << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << Num(std::max(width, 360.0))
     << "\" height=\"" << Num(height + kHeader) << "\" font-family=\"sans-serif\">\n";
  os << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  char line[256];
  std::snprintf(line, sizeof(line), "%.1f x %.1f m, free %.1f m2, %zu rectangles covering %.1f%%",
                b.Size().x(), b.Size().y(), Stat(world, "free_area_m2", 0.0),
                world.rectangles.size(), Stat(world, "kept_coverage_pct", 0.0));
  os << "<text x=\"4\" y=\"17\" font-size=\"15\">" << render::XmlEscape(world.name) << "</text>\n";
  os << "<text x=\"4\" y=\"36\" font-size=\"12\">" << line << "</text>\n";
  // Grey: blocked in the plan; white: navigable (the mask), or everything when it is unknown.
  os << "<rect x=\"0\" y=\"" << Num(kHeader) << "\" width=\"" << Num(width) << "\" height=\""
     << Num(height) << "\" fill=\"" << (mask.mask ? "#bbbbbb" : "#f4f4f4") << "\"/>\n";
  if (mask.mask) {
    const Grid& m = *mask.mask;
    const Vec2 o = mask.frame.origin;
    const double cs = mask.frame.cell_size;
    os << "<image x=\"" << X(o.x()) << "\" y=\"" << Y(o.y() + m.height * cs) << "\" width=\""
       << L(m.width * cs) << "\" height=\"" << L(m.height * cs)
       << "\" preserveAspectRatio=\"none\" style=\"image-rendering:pixelated\" "
          "href=\"data:image/png;base64,"
       << render::Base64(EncodePng(m, 187)) << "\"/>\n";
  }
  for (const Rect& r : world.rectangles) {
    os << "<rect x=\"" << X(r.min.x()) << "\" y=\"" << Y(r.max.y()) << "\" width=\""
       << L(r.Size().x()) << "\" height=\"" << L(r.Size().y())
       << "\" fill=\"#203040\" fill-opacity=\"0.8\" stroke=\"#e04020\" stroke-width=\"1\"/>\n";
  }
  for (const Vec2& p : world.free_points) {
    os << "<circle cx=\"" << X(p.x()) << "\" cy=\"" << Y(p.y())
       << "\" r=\"1.5\" fill=\"#3070e0\"/>\n";
  }
  const int shown = std::min<int>(pairs_shown, world.test_pairs.size());
  for (int k = 0; k < shown; ++k) {
    const StartGoal& p = world.test_pairs[k];
    os << "<line x1=\"" << X(p.start.x()) << "\" y1=\"" << Y(p.start.y()) << "\" x2=\""
       << X(p.goal.x()) << "\" y2=\"" << Y(p.goal.y())
       << "\" stroke=\"#20a040\" stroke-opacity=\"0.5\" stroke-width=\"1\"/>\n";
    os << "<circle cx=\"" << X(p.start.x()) << "\" cy=\"" << Y(p.start.y()) << "\" r=\"" << L(0.3)
       << "\" fill=\"none\" stroke=\"#20a040\"/>\n";
    os << "<circle cx=\"" << X(p.goal.x()) << "\" cy=\"" << Y(p.goal.y()) << "\" r=\"" << L(0.3)
       << "\" fill=\"none\" stroke=\"#d02060\"/>\n";
  }
  os << "</svg>\n";
  return os.str();
}

}  // namespace crowdsim::floorplan
