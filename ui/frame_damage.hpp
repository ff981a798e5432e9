// What changed on screen from one ImGui frame to the next: each draw list's fingerprint (a hash
// of its vertices, indices and commands, and the pixels it covers), and from two frames'
// fingerprints the framebuffer rectangles whose pixels may differ. A CPU rasteriser then redraws
// only those (ui/retained_frame.hpp): during a drag most panels draw the very same triangles as
// the frame before.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

struct ImDrawData;

namespace isoparm::ui {

// Framebuffer pixels, rows top-down, half-open: [x0, x1) x [y0, y1).
struct PixelRect {
    int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
    bool empty() const { return x1 <= x0 || y1 <= y0; }
    long area() const { return empty() ? 0 : static_cast<long>(x1 - x0) * (y1 - y0); }
    bool operator==(const PixelRect&) const = default;
};

PixelRect unite(const PixelRect& a, const PixelRect& b);     // the bounding rectangle
PixelRect intersect(const PixelRect& a, const PixelRect& b); // empty when apart

struct DrawListPrint {
    std::string key;       // the owner window's name, with its rank among lists of that name
    std::size_t hash = 0;  // of the vertices, indices and commands
    PixelRect bounds;      // the pixels its triangles may cover (clipped), a pixel of room
    PixelRect volatile_px; // drawn with a texture other than the font atlas: redrawn always
};

// The fingerprints of a frame's draw lists in drawing order. `font_texture`: the font atlas's
// texture id (its pixels change only when the fonts are rebuilt, which the caller reports).
std::vector<DrawListPrint> fingerprint(const ImDrawData& dd, const void* font_texture);

// The rectangles of `frame` (the framebuffer) to draw again for `after` to replace `before`:
// the old and new bounds of every list that changed, came or went, and every list's volatile
// part; the whole frame when the stacking order of the lists both frames have changed.
std::vector<PixelRect> damage(const std::vector<DrawListPrint>& before,
                              const std::vector<DrawListPrint>& after, const PixelRect& frame);

// Overlapping rectangles merged, then the pair whose union adds the least area merged until at
// most `max_rects` remain (each is one more pass over the draw lists).
std::vector<PixelRect> merge_rects(std::vector<PixelRect> rects, std::size_t max_rects);

} // namespace isoparm::ui
