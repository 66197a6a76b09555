#include "crowdsim/render/figure_key.h"

#include <cmath>
#include <cstdio>

#include "crowdsim/render/marks.h"
#include "crowdsim/render/palette.h"

namespace crowdsim::render {
namespace {

constexpr double kLine = 20.0;       // px per key line
constexpr double kFont = 11.0;       // px
constexpr double kMarkBox = 18.0;    // px reserved for an entry's mark
constexpr double kGap = 16.0;        // px between entries
constexpr double kCharWidth = 0.56;  // of the font size: a wide estimate for the sans fonts used

double TextWidth(const std::string& s) {
  // UTF-8 continuation bytes take no width of their own.
  int chars = 0;
  for (unsigned char c : s) chars += (c & 0xC0) != 0x80;
  return chars * kFont * kCharWidth;
}

// The mark of an entry centred at c.
void DrawMark(Drawing* d, KeyMark m, const Vec2& c) {
  const Color human = palette::Human(0);
  switch (m) {
    case KeyMark::kRobotStart:
      d->AddPolygon("key-mark", Square(c, 5.0), Filled({255, 255, 255, 1.0}, palette::kInk, 1.6));
      break;
    case KeyMark::kRobotGoal:
      d->AddPolygon("key-mark", Star(c, 8.0), Filled({255, 215, 0, 1.0}, palette::kInk, 1.2));
      break;
    case KeyMark::kHumanStart:
      d->AddCircle("key-mark", c, 3.0, Stroke(human, 1.4));
      break;
    case KeyMark::kHumanGoal:
      d->AddPolygon("key-mark", Diamond(c, 4.5), Stroke(human, 1.4));
      break;
    case KeyMark::kTimeDot:
      d->AddPolyline("key-mark", {c - Vec2(8.0, 0.0), c + Vec2(8.0, 0.0)},
                     Stroke(palette::kRobot, 2.0));
      d->AddCircle("key-mark", c, 3.0, Filled(palette::kRobot, palette::kRobot, 0.0));
      break;
    case KeyMark::kEndDisc:
      d->AddCircle("key-mark", c, 7.0, Filled(human.WithAlpha(0.3), human, 1.6));
      break;
    case KeyMark::kObstacle:
      d->AddRect("key-mark", c - Vec2(8.0, 6.0), c + Vec2(8.0, 6.0),
                 Filled(palette::kObstacleFill, palette::kObstacleEdge, 1.0));
      break;
    case KeyMark::kMask:
      d->AddRect("key-mark", c - Vec2(8.0, 6.0), c + Vec2(8.0, 6.0),
                 Filled(palette::kBlocked, palette::kBlocked, 0.0));
      break;
    case KeyMark::kLidar:
      d->AddPolyline("key-mark", {c - Vec2(8.0, -4.0), c + Vec2(6.0, -2.0)},
                     Stroke(palette::kBeam.WithAlpha(0.6), 1.0));
      d->AddCircle("key-mark", c + Vec2(6.0, -2.0), 2.6,
                   Filled(palette::kBeam, palette::kBeam, 0.0));
      break;
    case KeyMark::kPersonReading:
      d->AddCircle("key-mark", c, 7.0, Stroke(palette::kPersonReading, 1.6, true));
      break;
    case KeyMark::kCollision:
      d->AddCircle("key-mark", c, 7.0, Stroke(palette::kCollision, 2.2, true));
      break;
    case KeyMark::kCollisionPartner:
      d->AddCircle("key-mark", c, 7.0, Stroke(palette::kCollision, 2.6));
      break;
  }
}

// 1, 2 or 5 times a power of ten, in metres, drawn 50-150 px long.
double BarMetres(double px_per_metre) {
  if (!(px_per_metre > 0.0)) return 1.0;
  double best = 1.0;
  for (double decade = 0.01; decade <= 1000.0; decade *= 10.0) {
    for (double f : {1.0, 2.0, 5.0}) {
      const double m = f * decade;
      if (m * px_per_metre >= 50.0) return m * px_per_metre <= 150.0 ? m : best;
      best = m;
    }
  }
  return best;
}

std::string MetresText(double m) {
  char buf[32];
  std::snprintf(buf, sizeof(buf), m < 1.0 ? "%.2g m" : "%.0f m", m);
  return buf;
}

}  // namespace

FigureKey::FigureKey(std::vector<KeyEntry> entries, double px_per_metre, double width,
                     double margin)
    : margin_(margin) {
  bar_metres_ = BarMetres(px_per_metre);
  bar_px_ = bar_metres_ * px_per_metre;
  // The scale bar opens the first line; entries flow after it and wrap at the right margin.
  double x = margin + bar_px_ + 10.0 + TextWidth(MetresText(bar_metres_)) + kGap;
  int line = 0;
  for (KeyEntry& e : entries) {
    const double w = kMarkBox + 4.0 + TextWidth(e.text);
    if (x + w > width - margin && x > margin) {
      ++line;
      x = margin;
    }
    placed_.push_back(Placed{std::move(e), x, line});
    x += w + kGap;
  }
  height_ = (line + 1) * kLine + 6.0;
}

void FigureKey::Draw(Drawing* d, double top) const {
  const double mid = top + kLine / 2.0;
  // Scale bar: a bar with end ticks and its length.
  const Vec2 a(margin_, mid + 3.0), b(margin_ + bar_px_, mid + 3.0);
  d->AddPolyline("scale-bar", {a, b}, Stroke(palette::kInk, 2.0));
  d->AddPolyline("scale-bar", {a - Vec2(0.0, 5.0), a}, Stroke(palette::kInk, 1.4));
  d->AddPolyline("scale-bar", {b - Vec2(0.0, 5.0), b}, Stroke(palette::kInk, 1.4));
  d->AddText("scale-bar-label", Vec2(b.x() + 6.0, mid + 4.0), MetresText(bar_metres_), kFont,
             palette::kInk);
  for (const Placed& p : placed_) {
    const double y = mid + p.line * kLine;
    DrawMark(d, p.entry.mark, Vec2(p.x + kMarkBox / 2.0, y));
    d->AddText("key-text", Vec2(p.x + kMarkBox + 4.0, y + 4.0), p.entry.text, kFont,
               palette::kMutedInk);
  }
}

}  // namespace crowdsim::render
