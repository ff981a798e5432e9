// The tessellated meshes of the document's triangular patches, cached per object: re-made
// only when the patch or the subdivision changes, so orbiting or editing another object
// never re-tessellates a triangle. The renderer draws them as ready-made meshes.
#pragma once

#include <cstdint>
#include <unordered_map>

#include "core/doc/document.hpp"
#include "core/geom/tessellate.hpp"

namespace isoparm::ui {

class TriangleMeshes {
public:
    struct View {
        const geom::Mesh* mesh = nullptr;
        std::uint64_t revision = 0; // changes whenever *mesh changes
    };

    // Brings every visible triangle up to date and drops objects no longer present. `density`
    // is the display's samples per knot span; a triangle is cut into that many rows (at least
    // 4 per degree, so a high degree keeps its shape).
    void update(const doc::Document& d, int density);
    View view(std::uint64_t id) const;

    // The rows a patch of this degree is cut into at this display density.
    static int subdivisions(int degree, int density);

private:
    struct Entry {
        geom::TrianglePatch patch;
        int rows = 0;
        geom::Mesh mesh;
        std::uint64_t revision = 0;
    };
    std::unordered_map<std::uint64_t, Entry> entries_;
    std::uint64_t next_revision_ = 1;
};

} // namespace isoparm::ui
