// Draw list fingerprints and the damage between two frames (see frame_damage.hpp).
#include "ui/frame_damage.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <imgui.h>
#include <limits>
#include <string_view>
#include <unordered_map>
#include <unordered_set>

namespace isoparm::ui {

PixelRect unite(const PixelRect& a, const PixelRect& b) {
    if (a.empty()) return b;
    if (b.empty()) return a;
    return {std::min(a.x0, b.x0), std::min(a.y0, b.y0), std::max(a.x1, b.x1), std::max(a.y1, b.y1)};
}

PixelRect intersect(const PixelRect& a, const PixelRect& b) {
    const PixelRect r{std::max(a.x0, b.x0), std::max(a.y0, b.y0), std::min(a.x1, b.x1),
                      std::min(a.y1, b.y1)};
    return r.empty() ? PixelRect{} : r;
}

namespace {

std::size_t combine(std::size_t h, std::size_t x) {
    return h ^ (x + 0x9e3779b97f4a7c15ULL + (h << 6) + (h >> 2)); // boost's hash_combine
}

std::size_t hash_bytes(const void* data, std::size_t bytes) {
    return std::hash<std::string_view>{}(std::string_view(static_cast<const char*>(data), bytes));
}

// ImGui's coordinates to framebuffer pixels, as ImGui_ImplOpenGL3 maps them.
struct PixelMap {
    ImVec2 offset, scale;
    PixelRect frame;
    // Outward to whole pixels, one more each side (antialiased fringes, rounding), clipped.
    PixelRect around(float x0, float y0, float x1, float y1) const {
        const PixelRect r{static_cast<int>(std::floor((x0 - offset.x) * scale.x)) - 1,
                          static_cast<int>(std::floor((y0 - offset.y) * scale.y)) - 1,
                          static_cast<int>(std::ceil((x1 - offset.x) * scale.x)) + 1,
                          static_cast<int>(std::ceil((y1 - offset.y) * scale.y)) + 1};
        return intersect(r, frame);
    }
};

// The pixels a command's triangles may cover: their vertices' box within its clip rectangle.
PixelRect command_bounds(const ImDrawList& l, const ImDrawCmd& c, const PixelMap& map) {
    if (c.UserCallback) // a callback may draw anywhere in its clip rectangle
        return map.around(c.ClipRect.x, c.ClipRect.y, c.ClipRect.z, c.ClipRect.w);
    float x0 = HUGE_VALF, y0 = HUGE_VALF, x1 = -HUGE_VALF, y1 = -HUGE_VALF;
    for (unsigned k = c.IdxOffset; k < c.IdxOffset + c.ElemCount; ++k) {
        const ImVec2 p =
            l.VtxBuffer[static_cast<int>(c.VtxOffset + l.IdxBuffer[static_cast<int>(k)])].pos;
        x0 = std::min(x0, p.x);
        y0 = std::min(y0, p.y);
        x1 = std::max(x1, p.x);
        y1 = std::max(y1, p.y);
    }
    if (x0 > x1) return {};
    return map.around(std::max(x0, c.ClipRect.x), std::max(y0, c.ClipRect.y),
                      std::min(x1, c.ClipRect.z), std::min(y1, c.ClipRect.w));
}

} // namespace

std::vector<DrawListPrint> fingerprint(const ImDrawData& dd, const void* font_texture) {
    const PixelMap map{dd.DisplayPos,
                       dd.FramebufferScale,
                       {0, 0, static_cast<int>(dd.DisplaySize.x * dd.FramebufferScale.x),
                        static_cast<int>(dd.DisplaySize.y * dd.FramebufferScale.y)}};
    std::vector<DrawListPrint> out;
    std::unordered_map<std::string, int> rank; // lists of one owner, told apart by their order
    for (int n = 0; n < dd.CmdListsCount; ++n) {
        const ImDrawList& l = *dd.CmdLists[n];
        DrawListPrint p;
        const std::string owner = l._OwnerName ? l._OwnerName : "";
        p.key = owner + "#" + std::to_string(rank[owner]++);
        std::size_t h = hash_bytes(l.VtxBuffer.Data,
                                   static_cast<std::size_t>(l.VtxBuffer.Size) * sizeof(ImDrawVert));
        h = combine(h, hash_bytes(l.IdxBuffer.Data,
                                  static_cast<std::size_t>(l.IdxBuffer.Size) * sizeof(ImDrawIdx)));
        for (const ImDrawCmd& c : l.CmdBuffer) {
            for (float x : {c.ClipRect.x, c.ClipRect.y, c.ClipRect.z, c.ClipRect.w})
                h = combine(h, std::hash<float>{}(x));
            h = combine(h, std::hash<const void*>{}(c.TextureId));
            h = combine(h, c.VtxOffset);
            h = combine(h, c.IdxOffset);
            h = combine(h, c.ElemCount);
            h = combine(h, reinterpret_cast<std::size_t>(c.UserCallback));
            if (c.ElemCount == 0 && !c.UserCallback) continue;
            const PixelRect b = command_bounds(l, c, map);
            p.bounds = unite(p.bounds, b);
            if (c.UserCallback || c.TextureId != font_texture)
                p.volatile_px = unite(p.volatile_px, b);
        }
        p.hash = h;
        out.push_back(std::move(p));
    }
    return out;
}

std::vector<PixelRect> damage(const std::vector<DrawListPrint>& before,
                              const std::vector<DrawListPrint>& after, const PixelRect& frame) {
    std::unordered_map<std::string_view, const DrawListPrint*> old;
    for (const DrawListPrint& p : before) old.emplace(p.key, &p);
    std::unordered_set<std::string_view> now;
    for (const DrawListPrint& p : after) now.insert(p.key);
    // The lists both frames draw, in each frame's order: another order stacks them otherwise.
    std::vector<std::string_view> kept_before, kept_after;
    for (const DrawListPrint& p : before)
        if (now.count(p.key)) kept_before.push_back(p.key);
    for (const DrawListPrint& p : after)
        if (old.count(p.key)) kept_after.push_back(p.key);
    if (kept_before != kept_after) return {frame};

    std::vector<PixelRect> out;
    for (const DrawListPrint& p : after) {
        out.push_back(p.volatile_px);
        const auto it = old.find(p.key);
        if (it == old.end()) {
            out.push_back(p.bounds);
        } else if (it->second->hash != p.hash || it->second->bounds != p.bounds) {
            out.push_back(it->second->bounds);
            out.push_back(p.bounds);
        }
    }
    for (const DrawListPrint& p : before)
        if (!now.count(p.key)) out.push_back(p.bounds);
    std::erase_if(out, [](const PixelRect& r) { return r.empty(); });
    return out;
}

namespace {

// Merges every two rectangles that overlap until none do.
void merge_overlapping(std::vector<PixelRect>& r) {
    for (bool merged = true; merged;) {
        merged = false;
        for (std::size_t a = 0; a < r.size() && !merged; ++a)
            for (std::size_t b = a + 1; b < r.size() && !merged; ++b)
                if (!intersect(r[a], r[b]).empty()) {
                    r[a] = unite(r[a], r[b]);
                    r.erase(r.begin() + static_cast<std::ptrdiff_t>(b));
                    merged = true;
                }
    }
}

} // namespace

std::vector<PixelRect> merge_rects(std::vector<PixelRect> rects, std::size_t max_rects) {
    std::erase_if(rects, [](const PixelRect& r) { return r.empty(); });
    merge_overlapping(rects);
    max_rects = std::max<std::size_t>(max_rects, 1);
    while (rects.size() > max_rects) {
        std::size_t best_a = 0, best_b = 1;
        long best = std::numeric_limits<long>::max();
        for (std::size_t a = 0; a < rects.size(); ++a)
            for (std::size_t b = a + 1; b < rects.size(); ++b) {
                const long grow =
                    unite(rects[a], rects[b]).area() - rects[a].area() - rects[b].area();
                if (grow < best) {
                    best = grow;
                    best_a = a;
                    best_b = b;
                }
            }
        rects[best_a] = unite(rects[best_a], rects[best_b]);
        rects.erase(rects.begin() + static_cast<std::ptrdiff_t>(best_b));
        merge_overlapping(rects);
    }
    return rects;
}

} // namespace isoparm::ui
