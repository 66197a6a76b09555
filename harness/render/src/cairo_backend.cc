#include "crowdsim/render/cairo_backend.h"

#include <cairo-pdf.h>
#include <cairo.h>

#include <cmath>
#include <cstring>
#include <memory>
#include <stdexcept>

namespace crowdsim::render {
namespace {

struct SurfaceDeleter {
  void operator()(cairo_surface_t* s) const { cairo_surface_destroy(s); }
};
struct ContextDeleter {
  void operator()(cairo_t* c) const { cairo_destroy(c); }
};
using SurfacePtr = std::unique_ptr<cairo_surface_t, SurfaceDeleter>;
using ContextPtr = std::unique_ptr<cairo_t, ContextDeleter>;

void SetColor(cairo_t* cr, const Color& c) {
  cairo_set_source_rgba(cr, c.r / 255.0, c.g / 255.0, c.b / 255.0, c.a);
}

void FillAndStroke(cairo_t* cr, const Style& s) {
  if (s.fill) {
    SetColor(cr, *s.fill);
    if (s.stroke) {
      cairo_fill_preserve(cr);
    } else {
      cairo_fill(cr);
    }
  }
  if (s.stroke) {
    SetColor(cr, *s.stroke);
    cairo_set_line_width(cr, s.stroke_width);
    if (s.dashed) {
      const double dash[] = {3 * s.stroke_width, 2 * s.stroke_width};
      cairo_set_dash(cr, dash, 2, 0.0);
    } else {
      cairo_set_dash(cr, nullptr, 0, 0.0);
    }
    cairo_stroke(cr);
  }
  cairo_new_path(cr);
}

// A premultiplied ARGB32 surface holding an RGBA raster.
SurfacePtr ImageSurface(const RgbaImage& img) {
  SurfacePtr s(cairo_image_surface_create(CAIRO_FORMAT_ARGB32, img.width, img.height));
  cairo_surface_flush(s.get());
  unsigned char* data = cairo_image_surface_get_data(s.get());
  const int stride = cairo_image_surface_get_stride(s.get());
  for (int y = 0; y < img.height; ++y) {
    auto* row = reinterpret_cast<std::uint32_t*>(data + static_cast<size_t>(y) * stride);
    for (int x = 0; x < img.width; ++x) {
      const std::uint8_t* p = &img.pixels[(static_cast<size_t>(y) * img.width + x) * 4];
      const std::uint32_t a = p[3];
      const auto pm = [a](std::uint32_t c) { return (c * a + 127) / 255; };
      row[x] = (a << 24) | (pm(p[0]) << 16) | (pm(p[1]) << 8) | pm(p[2]);
    }
  }
  cairo_surface_mark_dirty(s.get());
  return s;
}

void PaintItem(cairo_t* cr, const DrawItem& it) {
  switch (it.kind) {
    case ItemKind::kRect: {
      const Vec2 a = it.points[0].cwiseMin(it.points[1]);
      const Vec2 b = it.points[0].cwiseMax(it.points[1]);
      cairo_rectangle(cr, a.x(), a.y(), b.x() - a.x(), b.y() - a.y());
      FillAndStroke(cr, it.style);
      break;
    }
    case ItemKind::kCircle:
      cairo_new_sub_path(cr);
      cairo_arc(cr, it.points[0].x(), it.points[0].y(), it.radius, 0.0, 2.0 * M_PI);
      FillAndStroke(cr, it.style);
      break;
    case ItemKind::kPolyline:
    case ItemKind::kPolygon: {
      if (it.points.empty()) break;
      cairo_move_to(cr, it.points[0].x(), it.points[0].y());
      for (size_t i = 1; i < it.points.size(); ++i)
        cairo_line_to(cr, it.points[i].x(), it.points[i].y());
      if (it.kind == ItemKind::kPolygon) cairo_close_path(cr);
      Style s = it.style;
      if (it.kind == ItemKind::kPolyline) s.fill.reset();
      FillAndStroke(cr, s);
      break;
    }
    case ItemKind::kText: {
      cairo_select_font_face(cr, "DejaVu Sans", CAIRO_FONT_SLANT_NORMAL,
                             it.bold ? CAIRO_FONT_WEIGHT_BOLD : CAIRO_FONT_WEIGHT_NORMAL);
      cairo_set_font_size(cr, it.font_size);
      cairo_text_extents_t ext;
      cairo_text_extents(cr, it.text.c_str(), &ext);
      double x = it.points[0].x();
      if (it.anchor == TextAnchor::kMiddle) x -= 0.5 * ext.x_advance;
      if (it.anchor == TextAnchor::kEnd) x -= ext.x_advance;
      cairo_move_to(cr, x, it.points[0].y());
      SetColor(cr, it.style.fill.value_or(Color{}));
      cairo_show_text(cr, it.text.c_str());
      cairo_new_path(cr);
      break;
    }
    case ItemKind::kImage: {
      if (!it.image || it.image->width <= 0 || it.image->height <= 0) break;
      const Vec2 a = it.points[0].cwiseMin(it.points[1]);
      const Vec2 b = it.points[0].cwiseMax(it.points[1]);
      SurfacePtr img = ImageSurface(*it.image);
      cairo_save(cr);
      cairo_translate(cr, a.x(), a.y());
      cairo_scale(cr, (b.x() - a.x()) / it.image->width, (b.y() - a.y()) / it.image->height);
      cairo_set_source_surface(cr, img.get(), 0, 0);
      cairo_pattern_set_filter(cairo_get_source(cr), CAIRO_FILTER_NEAREST);
      cairo_paint(cr);
      cairo_restore(cr);
      break;
    }
  }
}

void PaintDrawing(cairo_t* cr, const Drawing& d, double scale) {
  cairo_scale(cr, scale, scale);
  cairo_set_line_cap(cr, CAIRO_LINE_CAP_ROUND);
  cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
  SetColor(cr, d.background);
  cairo_paint(cr);
  for (const DrawItem& it : d.items) PaintItem(cr, it);
}

SurfacePtr RasterSurface(const Drawing& d, double scale) {
  const int w = std::max(1, static_cast<int>(std::ceil(d.width * scale)));
  const int h = std::max(1, static_cast<int>(std::ceil(d.height * scale)));
  SurfacePtr s(cairo_image_surface_create(CAIRO_FORMAT_ARGB32, w, h));
  ContextPtr cr(cairo_create(s.get()));
  PaintDrawing(cr.get(), d, scale);
  if (cairo_status(cr.get()) != CAIRO_STATUS_SUCCESS) {
    throw std::runtime_error(std::string("cairo: ") +
                             cairo_status_to_string(cairo_status(cr.get())));
  }
  cairo_surface_flush(s.get());
  return s;
}

cairo_status_t AppendToString(void* closure, const unsigned char* data, unsigned int length) {
  static_cast<std::string*>(closure)->append(reinterpret_cast<const char*>(data), length);
  return CAIRO_STATUS_SUCCESS;
}

std::string SurfacePng(cairo_surface_t* s) {
  std::string out;
  const cairo_status_t st = cairo_surface_write_to_png_stream(s, AppendToString, &out);
  if (st != CAIRO_STATUS_SUCCESS)
    throw std::runtime_error(std::string("cairo PNG: ") + cairo_status_to_string(st));
  return out;
}

}  // namespace

void WritePng(const Drawing& drawing, const std::filesystem::path& path, double scale) {
  SurfacePtr s = RasterSurface(drawing, scale);
  const cairo_status_t st = cairo_surface_write_to_png(s.get(), path.c_str());
  if (st != CAIRO_STATUS_SUCCESS) {
    throw std::runtime_error("cannot write " + path.string() + ": " + cairo_status_to_string(st));
  }
}

void WritePdf(const Drawing& drawing, const std::filesystem::path& path) {
  SurfacePtr s(cairo_pdf_surface_create(path.c_str(), drawing.width, drawing.height));
  {
    ContextPtr cr(cairo_create(s.get()));
    PaintDrawing(cr.get(), drawing, 1.0);
    cairo_show_page(cr.get());
  }
  cairo_surface_finish(s.get());
  if (cairo_surface_status(s.get()) != CAIRO_STATUS_SUCCESS) {
    throw std::runtime_error("cannot write " + path.string() + ": " +
                             cairo_status_to_string(cairo_surface_status(s.get())));
  }
}

std::string PngBytes(const Drawing& drawing, double scale) {
  SurfacePtr s = RasterSurface(drawing, scale);
  return SurfacePng(s.get());
}

std::string EncodePng(const RgbaImage& image) {
  SurfacePtr s = ImageSurface(image);
  return SurfacePng(s.get());
}

RgbImage Rasterize(const Drawing& drawing, double scale) {
  SurfacePtr s = RasterSurface(drawing, scale);
  RgbImage out;
  out.width = cairo_image_surface_get_width(s.get());
  out.height = cairo_image_surface_get_height(s.get());
  out.pixels.resize(static_cast<size_t>(out.width) * out.height * 3);
  const unsigned char* data = cairo_image_surface_get_data(s.get());
  const int stride = cairo_image_surface_get_stride(s.get());
  for (int y = 0; y < out.height; ++y) {
    const auto* row =
        reinterpret_cast<const std::uint32_t*>(data + static_cast<size_t>(y) * stride);
    for (int x = 0; x < out.width; ++x) {
      // The background is opaque, so the premultiplied values are the colour itself.
      std::uint8_t* p = &out.pixels[(static_cast<size_t>(y) * out.width + x) * 3];
      p[0] = (row[x] >> 16) & 0xff;
      p[1] = (row[x] >> 8) & 0xff;
      p[2] = row[x] & 0xff;
    }
  }
  return out;
}

}  // namespace crowdsim::render
