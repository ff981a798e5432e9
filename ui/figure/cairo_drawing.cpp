// Drawings through cairo: PDF (text as text, in DejaVu Sans, so a reader can search and copy
// it) and PNG.
#include <algorithm>
#include <cairo-pdf.h>
#include <cairo.h>
#include <cmath>
#include <cstring>

#include "ui/figure/drawing_files.hpp"
#include "ui/image/png_writer.hpp"

namespace isoparm::ui {

namespace {

void set_color(cairo_t* cr, const DrawColor& c) {
    cairo_set_source_rgba(cr, c.r, c.g, c.b, c.a);
}

void stroke_style(cairo_t* cr, const DrawStroke& s) {
    set_color(cr, s.color);
    cairo_set_line_width(cr, s.width);
    cairo_set_dash(cr, s.dash.empty() ? nullptr : s.dash.data(), static_cast<int>(s.dash.size()),
                   0);
}

// Fills then strokes the current path as the item asks.
void paint_path(cairo_t* cr, const std::optional<DrawColor>& fill,
                const std::optional<DrawStroke>& stroke) {
    if (fill) {
        set_color(cr, *fill);
        if (stroke)
            cairo_fill_preserve(cr);
        else
            cairo_fill(cr);
    }
    if (stroke) {
        stroke_style(cr, *stroke);
        cairo_stroke(cr);
    }
    cairo_new_path(cr);
}

double run_size(const TextRun& r, double size) {
    return r.kind == TextRun::plain ? size : 0.7 * size;
}

void draw_text(cairo_t* cr, const DrawText& t) {
    cairo_select_font_face(cr, "DejaVu Sans",
                           t.italic ? CAIRO_FONT_SLANT_ITALIC : CAIRO_FONT_SLANT_NORMAL,
                           CAIRO_FONT_WEIGHT_NORMAL);
    const std::vector<TextRun> runs = text_runs(t.text);
    double width = 0;
    for (const TextRun& r : runs) {
        cairo_set_font_size(cr, run_size(r, t.size));
        cairo_text_extents_t e;
        cairo_text_extents(cr, r.text.c_str(), &e);
        width += e.x_advance;
    }
    double x = t.anchor.x - (t.h == HAlign::center ? width / 2 : t.h == HAlign::right ? width : 0);
    cairo_font_extents_t fe;
    cairo_set_font_size(cr, t.size);
    cairo_font_extents(cr, &fe);
    const double em_ascent = fe.ascent, em_descent = fe.descent;
    double y = t.anchor.y;
    switch (t.v) {
    case VAlign::baseline:
        break;
    case VAlign::middle:
        y += (em_ascent - em_descent) / 2;
        break;
    case VAlign::top:
        y += em_ascent;
        break;
    case VAlign::bottom:
        y -= em_descent;
        break;
    }
    set_color(cr, t.color);
    for (const TextRun& r : runs) {
        cairo_set_font_size(cr, run_size(r, t.size));
        const double shift = r.kind == TextRun::sub   ? 0.25 * t.size
                             : r.kind == TextRun::sup ? -0.4 * t.size
                                                      : 0.0;
        cairo_move_to(cr, x, y + shift);
        cairo_show_text(cr, r.text.c_str());
        cairo_text_extents_t e;
        cairo_text_extents(cr, r.text.c_str(), &e);
        x += e.x_advance;
    }
    cairo_new_path(cr);
}

void draw_image(cairo_t* cr, const DrawImage& im) {
    if (im.pixels_w <= 0 || im.pixels_h <= 0) return;
    cairo_surface_t* s = cairo_image_surface_create(CAIRO_FORMAT_ARGB32, im.pixels_w, im.pixels_h);
    if (cairo_surface_status(s) != CAIRO_STATUS_SUCCESS) {
        cairo_surface_destroy(s);
        return;
    }
    cairo_surface_flush(s);
    unsigned char* data = cairo_image_surface_get_data(s);
    const int stride = cairo_image_surface_get_stride(s);
    // cairo keeps premultiplied ARGB in native-endian 32-bit words.
    for (int y = 0; y < im.pixels_h; ++y)
        for (int x = 0; x < im.pixels_w; ++x) {
            const std::uint8_t* p = &im.rgba[(static_cast<std::size_t>(y) * im.pixels_w + x) * 4];
            const unsigned a = p[3];
            const std::uint32_t word =
                (a << 24) | ((p[0] * a / 255) << 16) | ((p[1] * a / 255) << 8) | (p[2] * a / 255);
            std::memcpy(data + static_cast<std::ptrdiff_t>(y) * stride + x * 4, &word, 4);
        }
    cairo_surface_mark_dirty(s);
    cairo_save(cr);
    cairo_translate(cr, im.origin.x, im.origin.y);
    cairo_scale(cr, im.size.x / im.pixels_w, im.size.y / im.pixels_h);
    cairo_set_source_surface(cr, s, 0, 0);
    cairo_pattern_set_filter(cairo_get_source(cr), CAIRO_FILTER_GOOD);
    cairo_paint(cr);
    cairo_restore(cr);
    cairo_surface_destroy(s);
}

void draw(cairo_t* cr, const Drawing& d) {
    cairo_set_line_cap(cr, CAIRO_LINE_CAP_ROUND);
    cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
    if (d.background) {
        set_color(cr, *d.background);
        cairo_paint(cr);
    }
    bool clipped = false;
    for (const DrawItem& item : d.items) {
        if (const auto* c = std::get_if<DrawClip>(&item)) {
            if (clipped) cairo_restore(cr);
            clipped = c->active();
            if (clipped) {
                cairo_save(cr);
                cairo_rectangle(cr, c->origin.x, c->origin.y, c->size.x, c->size.y);
                cairo_clip(cr);
            }
        } else if (const auto* p = std::get_if<DrawPath>(&item)) {
            if (p->points.empty()) continue;
            cairo_move_to(cr, p->points[0].x, p->points[0].y);
            for (std::size_t k = 1; k < p->points.size(); ++k)
                cairo_line_to(cr, p->points[k].x, p->points[k].y);
            if (p->closed) cairo_close_path(cr);
            paint_path(cr, p->fill, p->stroke);
        } else if (const auto* c = std::get_if<DrawCircle>(&item)) {
            cairo_new_sub_path(cr);
            cairo_arc(cr, c->center.x, c->center.y, c->radius, 0, 2 * M_PI);
            paint_path(cr, c->fill, c->stroke);
        } else if (const auto* t = std::get_if<DrawText>(&item)) {
            draw_text(cr, *t);
        } else if (const auto* im = std::get_if<DrawImage>(&item)) {
            draw_image(cr, *im);
        }
    }
    if (clipped) cairo_restore(cr);
}

cairo_status_t append(void* closure, const unsigned char* data, unsigned int length) {
    static_cast<std::string*>(closure)->append(reinterpret_cast<const char*>(data), length);
    return CAIRO_STATUS_SUCCESS;
}

} // namespace

std::optional<std::string> cairo_pdf(const Drawing& d, std::string& error) {
    std::string bytes;
    cairo_surface_t* surface =
        cairo_pdf_surface_create_for_stream(append, &bytes, d.width, d.height);
    if (!d.title.empty())
        cairo_pdf_surface_set_metadata(surface, CAIRO_PDF_METADATA_TITLE, d.title.c_str());
    cairo_pdf_surface_set_metadata(surface, CAIRO_PDF_METADATA_CREATOR, "isoparm");
    cairo_t* cr = cairo_create(surface);
    draw(cr, d);
    cairo_show_page(cr);
    const cairo_status_t status = cairo_status(cr);
    cairo_destroy(cr);
    cairo_surface_finish(surface);
    const cairo_status_t finished = cairo_surface_status(surface);
    cairo_surface_destroy(surface);
    if (status != CAIRO_STATUS_SUCCESS || finished != CAIRO_STATUS_SUCCESS) {
        error = std::string("cairo could not draw the PDF: ") +
                cairo_status_to_string(status != CAIRO_STATUS_SUCCESS ? status : finished);
        return std::nullopt;
    }
    return bytes;
}

std::optional<std::string> cairo_png(const Drawing& d, double scale, std::string& error) {
    scale = std::clamp(scale, 1.0, 8.0);
    const int w = std::max(1, static_cast<int>(std::lround(d.width * scale)));
    const int h = std::max(1, static_cast<int>(std::lround(d.height * scale)));
    if (w > 16384 || h > 16384) {
        error = "the picture would be " + std::to_string(w) + "x" + std::to_string(h) +
                " pixels, more than 16384 a side";
        return std::nullopt;
    }
    cairo_surface_t* surface = cairo_image_surface_create(CAIRO_FORMAT_ARGB32, w, h);
    cairo_t* cr = cairo_create(surface);
    cairo_scale(cr, scale, scale);
    draw(cr, d);
    const cairo_status_t status = cairo_status(cr);
    cairo_destroy(cr);
    cairo_surface_flush(surface);
    if (status != CAIRO_STATUS_SUCCESS) {
        cairo_surface_destroy(surface);
        error = std::string("cairo could not draw the PNG: ") + cairo_status_to_string(status);
        return std::nullopt;
    }
    // Premultiplied native-endian ARGB -> straight RGBA.
    std::vector<std::uint8_t> rgba(static_cast<std::size_t>(w) * h * 4);
    const unsigned char* data = cairo_image_surface_get_data(surface);
    const int stride = cairo_image_surface_get_stride(surface);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            std::uint32_t word;
            std::memcpy(&word, data + static_cast<std::ptrdiff_t>(y) * stride + x * 4, 4);
            const unsigned a = word >> 24;
            std::uint8_t* out = &rgba[(static_cast<std::size_t>(y) * w + x) * 4];
            auto un = [a](unsigned c) {
                return static_cast<std::uint8_t>(a ? std::min(255u, (c * 255 + a / 2) / a) : 0);
            };
            out[0] = un((word >> 16) & 255);
            out[1] = un((word >> 8) & 255);
            out[2] = un(word & 255);
            out[3] = static_cast<std::uint8_t>(a);
        }
    cairo_surface_destroy(surface);
    std::optional<std::string> png = encode_png(w, h, rgba);
    if (!png) error = "out of memory encoding the PNG";
    return png;
}

} // namespace isoparm::ui
