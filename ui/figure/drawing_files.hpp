// Drawings (ui/view/drawing.hpp) as files. SVG and TikZ are text this code writes (SVG with
// <text> elements, which cairo's SVG surface cannot make: it draws glyph outlines); PDF and
// PNG are drawn by cairo (PDF with real, searchable text in DejaVu Sans). Every file goes
// through the one atomic writer.
#pragma once

#include <optional>
#include <string>

#include "ui/view/drawing.hpp"

namespace isoparm::ui {

enum class DrawingFormat { svg, pdf, tikz, png };

// By extension: .svg, .pdf, .tex (TikZ), .png; nothing for any other.
std::optional<DrawingFormat> drawing_format_of(const std::string& path);

// The file's bytes. png_scale: pixels per point for PNG (1..8). Nothing when memory ran out
// or cairo failed, with `error` saying why.
std::optional<std::string> drawing_bytes(const Drawing& d, DrawingFormat format, double png_scale,
                                         std::string& error);

// Writes `d` in the format of `path`'s extension. "" or why it failed (nothing is left then).
// A TikZ picture with raster images writes each beside it as NAME-imageK.png.
std::string write_drawing(const Drawing& d, const std::string& path, double png_scale = 2);

// The parts (tests and other writers use them).
std::string svg_document(const Drawing& d);
std::string tikz_picture(const Drawing& d, const std::vector<std::string>& image_files);
std::optional<std::string> cairo_pdf(const Drawing& d, std::string& error);
std::optional<std::string> cairo_png(const Drawing& d, double scale, std::string& error);

} // namespace isoparm::ui
