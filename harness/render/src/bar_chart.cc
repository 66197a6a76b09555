#include "crowdsim/render/bar_chart.h"

#include <algorithm>
#include <cctype>
#include <cstdio>

#include "crowdsim/render/palette.h"
#include "crowdsim/render/svg_writer.h"

namespace crowdsim::render {
namespace {

// A class name from a legend name: "nav. time" -> "nav-time".
std::string Slug(const std::string& name) {
  std::string out;
  for (char c : name) {
    if (std::isalnum(static_cast<unsigned char>(c))) {
      out += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    } else if (!out.empty() && out.back() != '-') {
      out += '-';
    }
  }
  while (!out.empty() && out.back() == '-') out.pop_back();
  return out;
}

std::string Fixed(double x, int decimals) {
  char buf[64];
  std::snprintf(buf, sizeof(buf), "%.*f", decimals, x);
  return buf;
}

}  // namespace

std::string BarChartSvg(const std::vector<Bar>& bars, const BarChartOptions& o) {
  constexpr double kLabelWidth = 170.0, kBarArea = 330.0, kValueWidth = 90.0, kBarHeight = 18.0,
                   kGap = 8.0;
  const double top = 30.0 + (o.legend ? 20.0 : 0.0);
  double max_value = o.max_value;
  if (max_value <= 0.0) {
    for (const Bar& b : bars) {
      double total = 0.0;
      for (const BarSegment& s : b.segments) total += std::max(0.0, s.value);
      max_value = std::max(max_value, total);
    }
  }
  if (max_value <= 0.0) max_value = 1.0;

  Drawing d;
  d.width = kLabelWidth + kBarArea + kValueWidth;
  d.height = top + bars.size() * (kBarHeight + kGap) + 6.0;
  d.AddText("chart-title", Vec2(4.0, 18.0), o.title, 14.0, palette::kInk, TextAnchor::kStart, true);
  if (o.legend && !bars.empty()) {
    double x = 4.0;
    for (const BarSegment& s : bars.front().segments) {
      Style sw;
      sw.fill = s.color;
      d.AddRect("legend-swatch", Vec2(x, 31.0), Vec2(x + 12.0, 43.0), sw);
      d.AddText("legend", Vec2(x + 16.0, 41.0), s.name, 11.0, palette::kInk);
      x += 24.0 + 7.0 * s.name.size();
    }
  }
  Style axis;
  axis.stroke = palette::kMutedInk;
  d.AddPolyline("axis", {Vec2(kLabelWidth, top - 4.0), Vec2(kLabelWidth, d.height - 4.0)}, axis);
  for (size_t i = 0; i < bars.size(); ++i) {
    const Bar& b = bars[i];
    const double y = top + i * (kBarHeight + kGap);
    d.AddText("bar-label", Vec2(kLabelWidth - 8.0, y + 13.0), b.label, 12.0, palette::kInk,
              TextAnchor::kEnd);
    double x = kLabelWidth;
    for (const BarSegment& s : b.segments) {
      const double w = std::max(0.0, s.value) / max_value * kBarArea;
      Style st;
      st.fill = s.color;
      if (w > 0.0) d.AddRect("bar " + Slug(s.name), Vec2(x, y), Vec2(x + w, y + kBarHeight), st);
      x += w;
    }
    const std::string value =
        b.segments.size() == 1
            ? Fixed(b.segments[0].value, o.decimals) + o.unit
            : Fixed(b.segments[0].value, o.decimals) + o.unit + " " + b.segments[0].name;
    d.AddText("bar-value", Vec2(x + 6.0, y + 13.0), value, 11.0, palette::kMutedInk);
  }
  return ToSvg(d, SvgOptions{.standalone = false});
}

}  // namespace crowdsim::render
