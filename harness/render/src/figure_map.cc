#include "crowdsim/render/figure_map.h"

#include <cstdint>
#include <memory>

#include "crowdsim/render/palette.h"

namespace crowdsim::render {
namespace {

// A navigable mask as an overlay: blocked cells grey, navigable cells transparent.
std::shared_ptr<const RgbaImage> MaskImage(const NavigableMask& m) {
  auto img = std::make_shared<RgbaImage>();
  img->width = m.width;
  img->height = m.height;
  img->pixels.assign(static_cast<size_t>(m.width) * m.height * 4, 0);
  for (int row = 0; row < m.height; ++row) {
    for (int col = 0; col < m.width; ++col) {
      if (m.Navigable(row, col)) continue;
      std::uint8_t* p = &img->pixels[(static_cast<size_t>(row) * m.width + col) * 4];
      p[0] = palette::kBlocked.r;
      p[1] = palette::kBlocked.g;
      p[2] = palette::kBlocked.b;
      p[3] = 255;
    }
  }
  return img;
}

}  // namespace

void AddWorldRect(Drawing* d, const View& v, const std::string& cls, const Rect& r,
                  const Style& style) {
  d->AddRect(cls, v.ToCanvas(Vec2(r.min.x(), r.max.y())), v.ToCanvas(Vec2(r.max.x(), r.min.y())),
             style);
}

void DrawMap(Drawing* d, const View& v, const StaticMap& map) {
  if (map.mask && map.mask->width > 0 && map.mask->height > 0) {
    const NavigableMask& m = *map.mask;
    const Vec2 top_left = v.ToCanvas(Vec2(m.origin.x(), m.origin.y() + m.height * m.resolution));
    const Vec2 bottom_right = v.ToCanvas(Vec2(m.origin.x() + m.width * m.resolution, m.origin.y()));
    d->AddImage("mask", top_left, bottom_right, MaskImage(m));
  }
  if (map.bounds.Area() > 0.0) {
    AddWorldRect(d, v, "bounds", map.bounds, Stroke(palette::kMutedInk, 1.0, true));
  }
  for (const Rect& o : map.rectangles) {
    AddWorldRect(d, v, "obstacle", o, Filled(palette::kObstacleFill, palette::kObstacleEdge, 1.0));
  }
}

}  // namespace crowdsim::render
