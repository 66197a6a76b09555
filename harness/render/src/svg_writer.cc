#include "crowdsim/render/svg_writer.h"

#include <cstdio>

#include "crowdsim/render/base64.h"
#include "crowdsim/render/cairo_backend.h"
#include "crowdsim/render/xml_escape.h"

namespace crowdsim::render {
namespace {

// Two decimals: sub-pixel precision, short files, and the same text on every machine.
std::string Num(double x) {
  char buf[32];
  std::snprintf(buf, sizeof(buf), "%.2f", x);
  std::string s = buf;
  if (s == "-0.00") s = "0.00";
  return s;
}

std::string Rgb(const Color& c) {
  char buf[16];
  std::snprintf(buf, sizeof(buf), "#%02x%02x%02x", c.r, c.g, c.b);
  return buf;
}

std::string Paint(const Style& s) {
  std::string out;
  if (s.fill) {
    out += " fill=\"" + Rgb(*s.fill) + "\"";
    if (s.fill->a < 1.0) out += " fill-opacity=\"" + Num(s.fill->a) + "\"";
  } else {
    out += " fill=\"none\"";
  }
  if (s.stroke) {
    out += " stroke=\"" + Rgb(*s.stroke) + "\" stroke-width=\"" + Num(s.stroke_width) + "\"";
    if (s.stroke->a < 1.0) out += " stroke-opacity=\"" + Num(s.stroke->a) + "\"";
    if (s.dashed)
      out +=
          " stroke-dasharray=\"" + Num(3 * s.stroke_width) + " " + Num(2 * s.stroke_width) + "\"";
  }
  return out;
}

std::string Points(const std::vector<Vec2>& pts) {
  std::string out;
  for (size_t i = 0; i < pts.size(); ++i) {
    if (i) out += ' ';
    out += Num(pts[i].x()) + "," + Num(pts[i].y());
  }
  return out;
}

}  // namespace

std::string ToSvg(const Drawing& d, const SvgOptions& options) {
  std::string out;
  if (options.standalone) out += "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
  out += "<svg xmlns=\"http://www.w3.org/2000/svg\" version=\"1.1\" width=\"" + Num(d.width) +
         "\" height=\"" + Num(d.height) + "\" viewBox=\"0 0 " + Num(d.width) + " " + Num(d.height) +
         "\" font-family=\"DejaVu Sans, Helvetica, Arial, sans-serif\" stroke-linecap=\"round\" "
         "stroke-linejoin=\"round\">\n";
  out += "<rect class=\"background\" x=\"0\" y=\"0\" width=\"" + Num(d.width) + "\" height=\"" +
         Num(d.height) + "\" fill=\"" + Rgb(d.background) + "\"/>\n";
  for (const DrawItem& it : d.items) {
    const std::string cls = "class=\"" + XmlEscape(it.cls) + "\"";
    switch (it.kind) {
      case ItemKind::kRect: {
        const Vec2 a = it.points[0].cwiseMin(it.points[1]);
        const Vec2 b = it.points[0].cwiseMax(it.points[1]);
        out += "<rect " + cls + " x=\"" + Num(a.x()) + "\" y=\"" + Num(a.y()) + "\" width=\"" +
               Num(b.x() - a.x()) + "\" height=\"" + Num(b.y() - a.y()) + "\"" + Paint(it.style) +
               "/>\n";
        break;
      }
      case ItemKind::kCircle:
        out += "<circle " + cls + " cx=\"" + Num(it.points[0].x()) + "\" cy=\"" +
               Num(it.points[0].y()) + "\" r=\"" + Num(it.radius) + "\"" + Paint(it.style) + "/>\n";
        break;
      case ItemKind::kPolyline:
        out +=
            "<polyline " + cls + " points=\"" + Points(it.points) + "\"" + Paint(it.style) + "/>\n";
        break;
      case ItemKind::kPolygon:
        out +=
            "<polygon " + cls + " points=\"" + Points(it.points) + "\"" + Paint(it.style) + "/>\n";
        break;
      case ItemKind::kText: {
        const char* anchor = it.anchor == TextAnchor::kStart    ? "start"
                             : it.anchor == TextAnchor::kMiddle ? "middle"
                                                                : "end";
        out += "<text " + cls + " x=\"" + Num(it.points[0].x()) + "\" y=\"" +
               Num(it.points[0].y()) + "\" font-size=\"" + Num(it.font_size) + "\" text-anchor=\"" +
               anchor + "\"";
        if (it.bold) out += " font-weight=\"bold\"";
        out += Paint(it.style) + ">" + XmlEscape(it.text) + "</text>\n";
        break;
      }
      case ItemKind::kImage: {
        if (!it.image) break;
        const Vec2 a = it.points[0].cwiseMin(it.points[1]);
        const Vec2 b = it.points[0].cwiseMax(it.points[1]);
        out += "<image " + cls + " x=\"" + Num(a.x()) + "\" y=\"" + Num(a.y()) + "\" width=\"" +
               Num(b.x() - a.x()) + "\" height=\"" + Num(b.y() - a.y()) +
               "\" preserveAspectRatio=\"none\" style=\"image-rendering:pixelated\" "
               "href=\"data:image/png;base64," +
               Base64(EncodePng(*it.image)) + "\"/>\n";
        break;
      }
    }
  }
  out += "</svg>\n";
  return out;
}

}  // namespace crowdsim::render
