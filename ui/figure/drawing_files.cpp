// SVG and TikZ writers, the format dispatch and the atomic write.
#include "ui/figure/drawing_files.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <span>

#include "core/scene/atomic_file.hpp"
#include "ui/image/png_writer.hpp"

namespace isoparm::ui {

namespace {

// Numbers as short as they can be at a hundredth of a point.
std::string num(double x) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.2f", std::abs(x) < 0.005 ? 0.0 : x);
    std::string s = buf;
    while (!s.empty() && s.back() == '0') s.pop_back();
    if (!s.empty() && s.back() == '.') s.pop_back();
    return s;
}

int byte(float c) {
    return static_cast<int>(std::lround(std::clamp(c, 0.f, 1.f) * 255));
}

std::string hex(const DrawColor& c) {
    char buf[8];
    std::snprintf(buf, sizeof buf, "#%02x%02x%02x", byte(c.r), byte(c.g), byte(c.b));
    return buf;
}

// A character and what a format writes for it.
struct Escape {
    char c;
    const char* as;
};

// `s` with each character of `table` replaced by its escape.
std::string escaped(const std::string& s, std::span<const Escape> table) {
    std::string out;
    out.reserve(s.size());
    for (char c : s) {
        const auto e =
            std::find_if(table.begin(), table.end(), [c](const Escape& x) { return x.c == c; });
        if (e != table.end())
            out += e->as;
        else
            out += c;
    }
    return out;
}

constexpr Escape xml_escapes[] = {
    {'&', "&amp;"}, {'<', "&lt;"}, {'>', "&gt;"}, {'"', "&quot;"}, {'\'', "&apos;"},
};

std::string xml_escape(const std::string& s) {
    return escaped(s, xml_escapes);
}

std::string base64(const std::string& bytes) {
    static constexpr char table[] =
        "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    out.reserve((bytes.size() + 2) / 3 * 4);
    for (std::size_t k = 0; k < bytes.size(); k += 3) {
        const auto b0 = static_cast<unsigned char>(bytes[k]);
        const auto b1 = k + 1 < bytes.size() ? static_cast<unsigned char>(bytes[k + 1]) : 0u;
        const auto b2 = k + 2 < bytes.size() ? static_cast<unsigned char>(bytes[k + 2]) : 0u;
        const unsigned v = (b0 << 16) | (b1 << 8) | b2;
        out += table[(v >> 18) & 63];
        out += table[(v >> 12) & 63];
        out += k + 1 < bytes.size() ? table[(v >> 6) & 63] : '=';
        out += k + 2 < bytes.size() ? table[v & 63] : '=';
    }
    return out;
}

// How far the baseline lies below the anchor for a vertical alignment (DejaVu Sans: ascent
// about 0.76 em, descent 0.24 em).
double baseline_shift(VAlign v, double size) {
    switch (v) {
    case VAlign::baseline:
        return 0;
    case VAlign::middle:
        return 0.36 * size;
    case VAlign::top:
        return 0.76 * size;
    case VAlign::bottom:
        return -0.24 * size;
    }
    return 0;
}

std::string svg_stroke(const std::optional<DrawStroke>& s) {
    if (!s) return " stroke=\"none\"";
    std::string out = " stroke=\"" + hex(s->color) + "\" stroke-width=\"" + num(s->width) + "\"";
    if (s->color.a < 1) out += " stroke-opacity=\"" + num(s->color.a) + "\"";
    if (!s->dash.empty()) {
        out += " stroke-dasharray=\"";
        for (std::size_t k = 0; k < s->dash.size(); ++k) out += (k ? " " : "") + num(s->dash[k]);
        out += "\"";
    }
    return out;
}

std::string svg_fill(const std::optional<DrawColor>& f) {
    if (!f) return " fill=\"none\"";
    std::string out = " fill=\"" + hex(*f) + "\"";
    if (f->a < 1) out += " fill-opacity=\"" + num(f->a) + "\"";
    return out;
}

std::string svg_class(const std::string& role) {
    return role.empty() ? "" : " class=\"" + xml_escape(role) + "\"";
}

// TeX's special characters in text mode.
constexpr Escape tex_escapes[] = {
    {'\\', "\\textbackslash{}"},
    {'{', "\\{"},
    {'}', "\\}"},
    {'#', "\\#"},
    {'$', "\\$"},
    {'%', "\\%"},
    {'&', "\\&"},
    {'_', "\\_"},
    {'^', "\\^{}"},
    {'~', "\\~{}"},
};

std::string tex_escape(const std::string& s) {
    return escaped(s, tex_escapes);
}

std::string tex_label(const std::string& marked_up) {
    std::string out;
    for (const TextRun& r : text_runs(marked_up)) {
        if (r.kind == TextRun::plain)
            out += tex_escape(r.text);
        else
            out += std::string(r.kind == TextRun::sub ? "\\textsubscript{" : "\\textsuperscript{") +
                   tex_escape(r.text) + "}";
    }
    return out;
}

class TikzColors {
public:
    std::string name(const DrawColor& c) {
        const std::string key = hex(c);
        auto it = names_.find(key);
        if (it != names_.end()) return it->second;
        const std::string n = "isoc" + std::to_string(names_.size());
        names_[key] = n;
        defs_ += "\\definecolor{" + n + "}{RGB}{" + std::to_string(byte(c.r)) + "," +
                 std::to_string(byte(c.g)) + "," + std::to_string(byte(c.b)) + "}\n";
        return n;
    }
    const std::string& definitions() const { return defs_; }

private:
    std::map<std::string, std::string> names_;
    std::string defs_;
};

std::string tikz_stroke(TikzColors& colors, const DrawStroke& s) {
    std::string o = "draw=" + colors.name(s.color) + ", line width=" + num(s.width) +
                    "pt, line cap=round, line join=round";
    if (s.color.a < 1) o += ", draw opacity=" + num(s.color.a);
    if (!s.dash.empty()) {
        o += ", dash pattern=";
        for (std::size_t k = 0; k < s.dash.size(); ++k)
            o += std::string(k % 2 ? " off " : (k ? " on " : "on ")) + num(s.dash[k]) + "pt";
    }
    return o;
}

std::string tikz_fill(TikzColors& colors, const DrawColor& f) {
    std::string o = "fill=" + colors.name(f);
    if (f.a < 1) o += ", fill opacity=" + num(f.a);
    return o;
}

std::string point(const glm::dvec2& p) {
    return "(" + num(p.x) + "," + num(p.y) + ")";
}

} // namespace

std::optional<DrawingFormat> drawing_format_of(const std::string& path) {
    std::string ext = std::filesystem::path(path).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    if (ext == ".svg") return DrawingFormat::svg;
    if (ext == ".pdf") return DrawingFormat::pdf;
    if (ext == ".tex") return DrawingFormat::tikz;
    if (ext == ".png") return DrawingFormat::png;
    return std::nullopt;
}

std::string svg_document(const Drawing& d) {
    std::string s = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
    s += "<svg xmlns=\"http://www.w3.org/2000/svg\" version=\"1.1\" width=\"" + num(d.width) +
         "pt\" height=\"" + num(d.height) + "pt\" viewBox=\"0 0 " + num(d.width) + " " +
         num(d.height) + "\">\n";
    if (!d.title.empty()) s += "<title>" + xml_escape(d.title) + "</title>\n";
    if (d.background)
        s += "<rect class=\"background\" width=\"100%\" height=\"100%\"" + svg_fill(d.background) +
             "/>\n";
    s += "<g stroke-linecap=\"round\" stroke-linejoin=\"round\" "
         "font-family=\"DejaVu Sans, Helvetica, Arial, sans-serif\">\n";
    bool clipped = false;
    int clips = 0;
    for (const DrawItem& item : d.items) {
        if (const auto* c = std::get_if<DrawClip>(&item)) {
            if (clipped) s += "</g>\n";
            clipped = c->active();
            if (clipped) {
                const std::string id = "clip" + std::to_string(++clips);
                s += "<clipPath id=\"" + id + "\"><rect x=\"" + num(c->origin.x) + "\" y=\"" +
                     num(c->origin.y) + "\" width=\"" + num(c->size.x) + "\" height=\"" +
                     num(c->size.y) + "\"/></clipPath>\n<g clip-path=\"url(#" + id + ")\">\n";
            }
        } else if (const auto* p = std::get_if<DrawPath>(&item)) {
            if (p->points.empty()) continue;
            std::string path;
            for (std::size_t k = 0; k < p->points.size(); ++k)
                path += (k ? " L" : "M") + num(p->points[k].x) + " " + num(p->points[k].y);
            if (p->closed) path += " Z";
            s += "<path" + svg_class(p->role) + " d=\"" + path + "\"" + svg_fill(p->fill) +
                 svg_stroke(p->stroke) + "/>\n";
        } else if (const auto* c = std::get_if<DrawCircle>(&item)) {
            s += "<circle" + svg_class(c->role) + " cx=\"" + num(c->center.x) + "\" cy=\"" +
                 num(c->center.y) + "\" r=\"" + num(c->radius) + "\"" + svg_fill(c->fill) +
                 svg_stroke(c->stroke) + "/>\n";
        } else if (const auto* t = std::get_if<DrawText>(&item)) {
            const char* anchor = t->h == HAlign::left     ? "start"
                                 : t->h == HAlign::center ? "middle"
                                                          : "end";
            s += "<text" + svg_class(t->role) + " x=\"" + num(t->anchor.x) + "\" y=\"" +
                 num(t->anchor.y + baseline_shift(t->v, t->size)) + "\" font-size=\"" +
                 num(t->size) + "\" text-anchor=\"" + anchor + "\"" + svg_fill(t->color) +
                 (t->italic ? " font-style=\"italic\"" : "") + ">";
            // Scripts as tspans shifted by dy (baseline-shift is not read everywhere), each
            // shift taken back by the next run.
            double shifted = 0;
            for (const TextRun& r : text_runs(t->text)) {
                const double want = r.kind == TextRun::sub   ? 0.25 * t->size
                                    : r.kind == TextRun::sup ? -0.4 * t->size
                                                             : 0.0;
                const std::string dy = want != shifted ? " dy=\"" + num(want - shifted) + "\"" : "";
                shifted = want;
                if (r.kind == TextRun::plain)
                    s += dy.empty() ? xml_escape(r.text)
                                    : "<tspan" + dy + ">" + xml_escape(r.text) + "</tspan>";
                else
                    s += "<tspan" + dy + " font-size=\"" + num(0.7 * t->size) + "\">" +
                         xml_escape(r.text) + "</tspan>";
            }
            s += "</text>\n";
        } else if (const auto* im = std::get_if<DrawImage>(&item)) {
            const std::optional<std::string> png = encode_png(im->pixels_w, im->pixels_h, im->rgba);
            if (!png) continue;
            s += "<image" + svg_class(im->role) + " x=\"" + num(im->origin.x) + "\" y=\"" +
                 num(im->origin.y) + "\" width=\"" + num(im->size.x) + "\" height=\"" +
                 num(im->size.y) + "\" preserveAspectRatio=\"none\" href=\"data:image/png;base64," +
                 base64(*png) + "\"/>\n";
        }
    }
    if (clipped) s += "</g>\n";
    s += "</g>\n</svg>\n";
    return s;
}

std::string tikz_picture(const Drawing& d, const std::vector<std::string>& image_files) {
    TikzColors colors;
    std::string body;
    std::size_t image = 0;
    if (d.background)
        body += "\\fill[" + tikz_fill(colors, *d.background) + "] (0,0) rectangle " +
                point({d.width, d.height}) + ";\n";
    bool scoped = false;
    for (const DrawItem& item : d.items) {
        if (const auto* c = std::get_if<DrawClip>(&item)) {
            if (scoped) body += "\\end{scope}\n";
            scoped = c->active();
            if (scoped)
                body += "\\begin{scope}\n\\clip " + point(c->origin) + " rectangle " +
                        point(c->origin + c->size) + ";\n";
        } else if (const auto* p = std::get_if<DrawPath>(&item)) {
            if (p->points.size() < 2 || (!p->stroke && !p->fill)) continue;
            std::string opts;
            if (p->fill) opts += tikz_fill(colors, *p->fill);
            if (p->stroke) opts += (opts.empty() ? "" : ", ") + tikz_stroke(colors, *p->stroke);
            body += "\\path[" + opts + "] ";
            for (std::size_t k = 0; k < p->points.size(); ++k)
                body += (k ? " -- " : "") + point(p->points[k]);
            body += p->closed ? " -- cycle;\n" : ";\n";
        } else if (const auto* c = std::get_if<DrawCircle>(&item)) {
            std::string opts;
            if (c->fill) opts += tikz_fill(colors, *c->fill);
            if (c->stroke) opts += (opts.empty() ? "" : ", ") + tikz_stroke(colors, *c->stroke);
            if (opts.empty()) continue;
            body += "\\path[" + opts + "] " + point(c->center) +
                    " circle[radius=" + num(c->radius) + "pt];\n";
        } else if (const auto* t = std::get_if<DrawText>(&item)) {
            // The anchor names the text box's point at the label's anchor; "base" is the
            // baseline, as the other writers place it.
            const char* v = t->v == VAlign::baseline ? "base"
                            : t->v == VAlign::top    ? "north"
                            : t->v == VAlign::bottom ? "south"
                                                     : "";
            const char* h = t->h == HAlign::left ? "west" : t->h == HAlign::right ? "east" : "";
            std::string anchor = std::string(v) + (*v && *h ? " " : "") + h;
            if (anchor.empty()) anchor = "center";
            body += "\\node[anchor=" + anchor + ", inner sep=0pt, text=" + colors.name(t->color) +
                    ", font=\\fontsize{" + num(t->size) + "}{" + num(1.2 * t->size) +
                    "}\\selectfont" + (t->italic ? "\\itshape" : "") + "] at " + point(t->anchor) +
                    " {" + tex_label(t->text) + "};\n";
        } else if (const auto* im = std::get_if<DrawImage>(&item)) {
            if (image >= image_files.size()) continue;
            body += "\\node[anchor=north west, inner sep=0pt] at " + point(im->origin) +
                    " {\\includegraphics[width=" + num(im->size.x) +
                    "pt, height=" + num(im->size.y) + "pt]{" + image_files[image++] + "}};\n";
        }
    }
    if (scoped) body += "\\end{scope}\n";
    std::string s = "% " + (d.title.empty() ? std::string("isoparm figure") : d.title) + "\n";
    s += "% Written by isoparm. Needs \\usepackage{tikz} (and graphicx for raster images);\n"
         "% coordinates are points with y downward, as the picture was drawn.\n";
    s += "\\begin{tikzpicture}[x=1pt, y=-1pt]\n";
    s += colors.definitions();
    s += "\\useasboundingbox (0,0) rectangle " + point({d.width, d.height}) + ";\n";
    s += "\\clip (0,0) rectangle " + point({d.width, d.height}) + ";\n";
    s += body;
    s += "\\end{tikzpicture}\n";
    return s;
}

std::optional<std::string> drawing_bytes(const Drawing& d, DrawingFormat format, double png_scale,
                                         std::string& error) {
    switch (format) {
    case DrawingFormat::svg:
        return svg_document(d);
    case DrawingFormat::tikz:
        return tikz_picture(d, {});
    case DrawingFormat::pdf:
        return cairo_pdf(d, error);
    case DrawingFormat::png:
        return cairo_png(d, png_scale, error);
    }
    return std::nullopt;
}

std::string write_drawing(const Drawing& d, const std::string& path, double png_scale) {
    const std::optional<DrawingFormat> format = drawing_format_of(path);
    if (!format) return "'" + path + "' does not end in .svg, .pdf, .tex or .png";
    std::string error;
    std::optional<std::string> bytes;
    if (*format == DrawingFormat::tikz) {
        // Raster images go beside the picture, named after it.
        std::vector<std::string> files;
        const std::filesystem::path p(path);
        for (const DrawItem& item : d.items) {
            const auto* im = std::get_if<DrawImage>(&item);
            if (!im) continue;
            const std::string name =
                p.stem().string() + "-image" + std::to_string(files.size() + 1) + ".png";
            const std::string full = (p.parent_path() / name).string();
            if (std::string problem = write_png(full, im->pixels_w, im->pixels_h, im->rgba);
                !problem.empty())
                return problem;
            files.push_back(name);
        }
        bytes = tikz_picture(d, files);
    } else {
        bytes = drawing_bytes(d, *format, png_scale, error);
    }
    if (!bytes) return error.empty() ? "out of memory drawing '" + path + "'" : error;
    const geom::Status written = scene::write_file_atomically(path, *bytes);
    return written ? std::string{} : written.error().message;
}

} // namespace isoparm::ui
