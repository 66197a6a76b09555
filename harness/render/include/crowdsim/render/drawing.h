// A figure as a flat list of vector items in canvas pixels (y down). Every output format is a
// backend of this list, so SVG, PNG, PDF and animation frames always show the same picture.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "crowdsim/geometry.h"

namespace crowdsim::render {

/// An sRGB colour with opacity.
struct Color {
  std::uint8_t r = 0;
  std::uint8_t g = 0;
  std::uint8_t b = 0;
  double a = 1.0;  ///< opacity in [0, 1]
  /// The same colour with opacity `alpha`.
  Color WithAlpha(double alpha) const { return Color{r, g, b, alpha}; }
  /// Exact equality, opacity included.
  bool operator==(const Color&) const = default;
};

/// How an item is filled and outlined; an absent colour is not painted.
struct Style {
  std::optional<Color> fill;
  std::optional<Color> stroke;
  double stroke_width = 1.0;  ///< px
  bool dashed = false;
};

/// An outline of `width` px (dashed or solid), no fill.
inline Style Stroke(const Color& c, double width, bool dashed = false) {
  Style s;
  s.stroke = c;
  s.stroke_width = width;
  s.dashed = dashed;
  return s;
}

/// A filled shape, optionally outlined.
inline Style Filled(const Color& fill, std::optional<Color> stroke = std::nullopt,
                    double width = 1.0) {
  Style s;
  s.fill = fill;
  s.stroke = stroke;
  s.stroke_width = width;
  return s;
}

/// An 8-bit RGBA raster (row 0 at the top), e.g. a floor plan's navigable mask.
struct RgbaImage {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> pixels;  ///< row-major, 4 bytes per pixel, not premultiplied
};

/// The shape of a DrawItem; what its `points` mean is listed per kind.
enum class ItemKind {
  kRect,      ///< points: {min corner, max corner}
  kCircle,    ///< points: {centre}; radius
  kPolyline,  ///< open path through points
  kPolygon,   ///< closed path through points
  kText,      ///< points: {anchor}; text, font_size, anchor
  kImage,     ///< points: {top-left, bottom-right}; image
};

/// Which point of a text line its anchor is (SVG text-anchor).
enum class TextAnchor { kStart, kMiddle, kEnd };

/// One thing drawn. `cls` names what it shows (e.g. "obstacle", "trajectory robot"): SVG
/// writes it as the element's class, which makes the figures countable in tests.
struct DrawItem {
  ItemKind kind = ItemKind::kRect;
  std::string cls;
  Style style;
  std::vector<Vec2> points;
  double radius = 0.0;  ///< px, circles
  std::string text;
  double font_size = 12.0;  ///< px
  bool bold = false;
  TextAnchor anchor = TextAnchor::kStart;
  std::shared_ptr<const RgbaImage> image;
};

/// A complete picture: canvas size, background and the items in paint order.
struct Drawing {
  double width = 0.0;   ///< px
  double height = 0.0;  ///< px
  Color background{255, 255, 255, 1.0};
  std::vector<DrawItem> items;

  /// Appends an axis-aligned rectangle.
  DrawItem& AddRect(std::string cls, const Vec2& min, const Vec2& max, const Style& style);
  /// Appends a circle of `radius` px.
  DrawItem& AddCircle(std::string cls, const Vec2& center, double radius, const Style& style);
  /// Appends an open path (needs at least 2 points to show).
  DrawItem& AddPolyline(std::string cls, std::vector<Vec2> points, const Style& style);
  /// Appends a closed path.
  DrawItem& AddPolygon(std::string cls, std::vector<Vec2> points, const Style& style);
  /// Appends a text line with its baseline at `anchor_point`.
  DrawItem& AddText(std::string cls, const Vec2& anchor_point, std::string text, double font_size,
                    const Color& color, TextAnchor anchor = TextAnchor::kStart, bool bold = false);
  /// Appends a raster stretched over [top_left, bottom_right] (nearest-neighbour).
  DrawItem& AddImage(std::string cls, const Vec2& top_left, const Vec2& bottom_right,
                     std::shared_ptr<const RgbaImage> image);
  /// Number of items whose class is exactly `cls`.
  int Count(const std::string& cls) const;
};

}  // namespace crowdsim::render
