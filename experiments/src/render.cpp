#include "render.h"

#include <coverkit/datasets/path_io.h>
#include <coverkit/geometry/error.h>

#include <cairo-svg.h>
#include <cairo.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <map>

namespace coverkit::experiments {

namespace {
/// Cairo names an SVG's surfaces (id="surfaceN", href="#surfaceN") from a counter shared by the
/// whole process, so the same picture drawn after another one, or on another thread, would come out
/// with other bytes. The ids are renumbered 1, 2, ... in order of first appearance.
std::string renumberSurfaces(const std::string& svg) {
  static const std::string kWord = "surface";
  std::map<std::string, std::string> ids;
  std::string out;
  out.reserve(svg.size());
  std::size_t i = 0;
  while (i < svg.size()) {
    const std::size_t k = svg.find(kWord, i);
    std::size_t end = k == std::string::npos ? svg.size() : k + kWord.size();
    while (k != std::string::npos && end < svg.size() && std::isdigit(static_cast<unsigned char>(svg[end]))) ++end;
    if (k == std::string::npos || end == k + kWord.size()) {   // no number after it: copied as it is
      out.append(svg, i, end - i);
      i = end;
      continue;
    }
    out.append(svg, i, k - i);
    const std::string number = svg.substr(k + kWord.size(), end - k - kWord.size());
    const auto it = ids.emplace(number, std::to_string(ids.size() + 1)).first;
    out += kWord + it->second;
    i = end;
  }
  return out;
}
}  // namespace

namespace {

cairo_status_t appendBytes(void* closure, const unsigned char* data, unsigned int length) {
  static_cast<std::string*>(closure)->append(reinterpret_cast<const char*>(data), length);
  return CAIRO_STATUS_SUCCESS;
}
}  // namespace

void checkPictureName(const std::string& file, const std::string& option) {
  const std::string e = datasets::extensionOf(file);
  if (e != ".png" && e != ".svg") throw InputError(file, option, "unknown picture format '" + e + "' (expected .png or .svg)");
}

void checkPictureOutput(const std::string& file, const std::string& option) {
  checkPictureName(file, option);
  datasets::checkOutputFile(file, option, {".png", ".svg"});
}

void renderPicture(const std::string& file, const PictureContent& c) { datasets::writeFileAtomically(file, pictureBytes(file, c)); }

std::string pictureBytes(const std::string& file, const PictureContent& c) {
  checkPictureName(file);
  const Box b = c.workspace->bbox();
  const double x0 = b.xmin.get_d(), y0 = b.ymin.get_d(), w = b.xmax.get_d() - x0, h = b.ymax.get_d() - y0;
  if (!(std::isfinite(x0) && std::isfinite(y0) && std::isfinite(w) && std::isfinite(h) && w > 0 && h > 0))
    throw InputError(c.workspace->name, "coordinates", "the extent [" + b.xmin.get_str().substr(0, 30) + ", " + b.xmax.get_str().substr(0, 30) + "] × [" +
                                                          b.ymin.get_str().substr(0, 30) + ", " + b.ymax.get_str().substr(0, 30) +
                                                          "] does not fit a double: the picture " + file + " cannot be drawn");
  const double scale = 1000.0 / std::max(w, h);
  const int margin = 10, titleH = c.title.empty() ? 0 : 22;
  const int W = static_cast<int>(std::ceil(w * scale)) + 2 * margin, H = static_cast<int>(std::ceil(h * scale)) + 2 * margin + titleH;
  std::string bytes;
  const bool svg = datasets::extensionOf(file) == ".svg";
  cairo_surface_t* surface = svg ? cairo_svg_surface_create_for_stream(appendBytes, &bytes, W, H) : cairo_image_surface_create(CAIRO_FORMAT_ARGB32, W, H);
  cairo_t* cr = cairo_create(surface);
  cairo_set_source_rgb(cr, 1, 1, 1);
  cairo_paint(cr);
  auto X = [&](double x) { return margin + (x - x0) * scale; };
  auto Y = [&](double y) { return titleH + margin + (h - (y - y0)) * scale; };
  // obstacles: bounding box grey, free regions white (even-odd fill of all rings)
  cairo_set_source_rgb(cr, 0.25, 0.25, 0.28);
  cairo_rectangle(cr, X(x0), Y(y0 + h), w * scale, h * scale);
  cairo_fill(cr);
  cairo_set_fill_rule(cr, CAIRO_FILL_RULE_EVEN_ODD);
  for (const Ring* ring : c.workspace->rings()) {
    for (std::size_t i = 0; i < ring->size(); ++i) {
      const Point& p = (*ring)[i];
      if (i == 0) cairo_move_to(cr, X(p.x.get_d()), Y(p.y.get_d()));
      else cairo_line_to(cr, X(p.x.get_d()), Y(p.y.get_d()));
    }
    cairo_close_path(cr);
  }
  cairo_set_source_rgb(cr, 1, 1, 1);
  cairo_fill(cr);
  // C-space: C-obstacles translucent red, C-free components in light colours, boundaries with arcs
  auto loopPath = [&](const CurveLoop& loop) {
    bool first = true;
    for (const PathSegment& p : loop.pieces) {
      if (first) cairo_move_to(cr, X(p.from.x), Y(p.from.y));
      first = false;
      if (p.kind == PathSegment::Kind::kLine) {
        cairo_line_to(cr, X(p.to.x), Y(p.to.y));
        continue;
      }
      const double rad = std::hypot(p.from.x - p.center.x, p.from.y - p.center.y);
      const double a0 = std::atan2(p.from.y - p.center.y, p.from.x - p.center.x), a1 = std::atan2(p.to.y - p.center.y, p.to.x - p.center.x);
      // the y axis points down on the page: a counter-clockwise arc is drawn clockwise
      if (p.ccw) cairo_arc_negative(cr, X(p.center.x), Y(p.center.y), rad * scale, -a0, -a1);
      else cairo_arc(cr, X(p.center.x), Y(p.center.y), rad * scale, -a0, -a1);
    }
    cairo_close_path(cr);
  };
  auto regionPath = [&](const CurveRegion& r) {
    loopPath(r.outer);
    for (const CurveLoop& h : r.holes) loopPath(h);
  };
  if (c.cobstacles) {  // clipped to the workspace's box: the band outside it is not informative
    cairo_save(cr);
    cairo_rectangle(cr, X(x0), Y(y0 + h), w * scale, h * scale);
    cairo_clip(cr);
    for (const CurveRegion& r : *c.cobstacles) regionPath(r);
    cairo_set_source_rgba(cr, 0.85, 0.2, 0.2, 0.25);
    cairo_fill(cr);
    cairo_restore(cr);
  }
  if (c.cfree) {
    const double tints[5][3] = {{0.55, 0.75, 0.95}, {0.6, 0.9, 0.6}, {0.95, 0.8, 0.5}, {0.8, 0.65, 0.95}, {0.6, 0.9, 0.9}};
    for (std::size_t i = 0; i < c.cfree->size(); ++i) {
      regionPath((*c.cfree)[i]);
      const auto& t = tints[i % 5];
      cairo_set_source_rgba(cr, t[0], t[1], t[2], 0.55);
      cairo_fill_preserve(cr);
      cairo_set_source_rgb(cr, 0.1, 0.2, 0.5);
      cairo_set_line_width(cr, 1.2);
      cairo_stroke(cr);
    }
  }
  if (c.cells) {
    const double D = c.cells->subSizeD();
    const double ox = c.cells->originX().get_d(), oy = c.cells->originY().get_d();
    for (int r = 0; r < c.cells->subRows(); ++r)
      for (int col = 0; col < c.cells->subCols(); ++col) {
        const CellState s = c.cells->sub(col, r);
        if (s == CellState::kFree) cairo_set_source_rgba(cr, 0.55, 0.85, 0.55, 0.35);
        else if (s == CellState::kPartial) cairo_set_source_rgba(cr, 0.95, 0.75, 0.3, 0.45);
        else continue;
        cairo_rectangle(cr, X(ox + col * D), Y(oy + (r + 1) * D), D * scale, D * scale);
        cairo_fill(cr);
      }
    cairo_set_line_width(cr, 0.6);
    cairo_set_source_rgba(cr, 0.3, 0.3, 0.3, 0.35);
    for (int col = 0; col <= c.cells->megaCols(); ++col) {
      cairo_move_to(cr, X(ox + 2 * col * D), Y(oy));
      cairo_line_to(cr, X(ox + 2 * col * D), Y(oy + c.cells->subRows() * D));
    }
    for (int r = 0; r <= c.cells->megaRows(); ++r) {
      cairo_move_to(cr, X(ox), Y(oy + 2 * r * D));
      cairo_line_to(cr, X(ox + c.cells->subCols() * D), Y(oy + 2 * r * D));
    }
    cairo_stroke(cr);
  }
  if (c.tree) {
    cairo_set_source_rgba(cr, 0.1, 0.3, 0.9, 0.6);
    cairo_set_line_width(cr, 1.5);
    for (const auto& [a, bb] : *c.tree) {
      cairo_move_to(cr, X(a.x), Y(a.y));
      cairo_line_to(cr, X(bb.x), Y(bb.y));
    }
    cairo_stroke(cr);
  }
  if (c.paths) {
    const double colors[4][3] = {{0.85, 0.1, 0.1}, {0.1, 0.5, 0.1}, {0.5, 0.1, 0.6}, {0.9, 0.5, 0.0}};
    // only the part of a path near the map is drawn (a path from another tool may run far outside)
    const double pad = c.radius + 10 / scale;
    const BoxD view{x0 - pad, y0 - pad, x0 + w + pad, y0 + h + pad};
    for (std::size_t i = 0; i < c.paths->size(); ++i) {
      const auto runs = (*c.paths)[i].polylineWithin(0.5 / scale, view);
      if (runs.empty()) continue;
      const auto& col = colors[i % 4];
      cairo_set_line_cap(cr, CAIRO_LINE_CAP_ROUND);
      cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
      for (const auto& pts : runs) {
        if (c.radius > 0) {  // swept area, faint
          cairo_set_source_rgba(cr, col[0], col[1], col[2], 0.12);
          cairo_set_line_width(cr, 2 * c.radius * scale);
          cairo_move_to(cr, X(pts[0].x), Y(pts[0].y));
          for (const PointD& p : pts) cairo_line_to(cr, X(p.x), Y(p.y));
          cairo_stroke(cr);
        }
        cairo_set_source_rgb(cr, col[0], col[1], col[2]);
        cairo_set_line_width(cr, 1.6);
        cairo_move_to(cr, X(pts[0].x), Y(pts[0].y));
        for (const PointD& p : pts) cairo_line_to(cr, X(p.x), Y(p.y));
        cairo_stroke(cr);
      }
      const PointD s0 = (*c.paths)[i].start;
      if (s0.x >= view.xmin && s0.x <= view.xmax && s0.y >= view.ymin && s0.y <= view.ymax) {
        cairo_set_source_rgb(cr, col[0], col[1], col[2]);
        cairo_arc(cr, X(s0.x), Y(s0.y), 5, 0, 2 * M_PI);
        cairo_fill(cr);
      }
    }
  }
  if (!c.title.empty()) {
    cairo_set_source_rgb(cr, 0, 0, 0);
    cairo_select_font_face(cr, "sans-serif", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
    cairo_set_font_size(cr, 14);
    cairo_move_to(cr, margin, 16);
    cairo_show_text(cr, c.title.c_str());
  }
  cairo_destroy(cr);
  cairo_status_t st = CAIRO_STATUS_SUCCESS;
  if (!svg) st = cairo_surface_write_to_png_stream(surface, appendBytes, &bytes);
  cairo_surface_finish(surface);
  if (st == CAIRO_STATUS_SUCCESS) st = cairo_surface_status(surface);
  cairo_surface_destroy(surface);
  if (st != CAIRO_STATUS_SUCCESS) throw InputError(file, "", std::string("the picture cannot be drawn: ") + cairo_status_to_string(st));
  return svg ? renumberSurfaces(bytes) : bytes;
}

}  // namespace coverkit::experiments
