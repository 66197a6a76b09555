#include "crowdsim/render/drawing.h"

#include <algorithm>
#include <utility>

namespace crowdsim::render {

DrawItem& Drawing::AddRect(std::string cls, const Vec2& min, const Vec2& max, const Style& style) {
  DrawItem& it = items.emplace_back();
  it.kind = ItemKind::kRect;
  it.cls = std::move(cls);
  it.style = style;
  it.points = {min, max};
  return it;
}

DrawItem& Drawing::AddCircle(std::string cls, const Vec2& center, double radius,
                             const Style& style) {
  DrawItem& it = items.emplace_back();
  it.kind = ItemKind::kCircle;
  it.cls = std::move(cls);
  it.style = style;
  it.points = {center};
  it.radius = radius;
  return it;
}

DrawItem& Drawing::AddPolyline(std::string cls, std::vector<Vec2> points, const Style& style) {
  DrawItem& it = items.emplace_back();
  it.kind = ItemKind::kPolyline;
  it.cls = std::move(cls);
  it.style = style;
  it.points = std::move(points);
  return it;
}

DrawItem& Drawing::AddPolygon(std::string cls, std::vector<Vec2> points, const Style& style) {
  DrawItem& it = AddPolyline(std::move(cls), std::move(points), style);
  it.kind = ItemKind::kPolygon;
  return it;
}

DrawItem& Drawing::AddText(std::string cls, const Vec2& anchor_point, std::string text,
                           double font_size, const Color& color, TextAnchor anchor, bool bold) {
  DrawItem& it = items.emplace_back();
  it.kind = ItemKind::kText;
  it.cls = std::move(cls);
  it.style.fill = color;
  it.points = {anchor_point};
  it.text = std::move(text);
  it.font_size = font_size;
  it.anchor = anchor;
  it.bold = bold;
  return it;
}

DrawItem& Drawing::AddImage(std::string cls, const Vec2& top_left, const Vec2& bottom_right,
                            std::shared_ptr<const RgbaImage> image) {
  DrawItem& it = items.emplace_back();
  it.kind = ItemKind::kImage;
  it.cls = std::move(cls);
  it.points = {top_left, bottom_right};
  it.image = std::move(image);
  return it;
}

int Drawing::Count(const std::string& cls) const {
  return static_cast<int>(
      std::count_if(items.begin(), items.end(), [&](const DrawItem& it) { return it.cls == cls; }));
}

}  // namespace crowdsim::render
