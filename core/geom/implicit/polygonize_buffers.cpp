// The planes' and chunks' arrays kept between polygonizations (see polygonize_work.hpp).
#include "core/geom/implicit/polygonize_work.hpp"

#include <utility>

namespace isoparm::geom::implicit::detail {

std::size_t Buffers::bytes() const {
    std::size_t n = 0;
    auto group = [&](const VertexGroup& g) {
        n += (g.positions.capacity() + g.normals.capacity()) * sizeof(glm::dvec3) +
             g.pinned.capacity() * sizeof(g.pinned[0]);
    };
    for (const BoundaryPlane& p : planes) {
        group(p.vertices);
        n += p.values.capacity() * sizeof(double) + p.rows.capacity() +
             p.ids.capacity() * sizeof(Index);
    }
    for (const Chunk& c : chunks) {
        group(c.vertices);
        n += c.triangles.capacity() * sizeof(c.triangles[0]);
    }
    return n;
}

Buffers BufferPool::take() {
    std::lock_guard lock(mutex_);
    if (free_.empty()) return {};
    Buffers b = std::move(free_.back());
    free_.pop_back();
    return b;
}

void BufferPool::give(Buffers&& b) {
    if (b.bytes() > (std::size_t{128} << 20)) return;
    std::lock_guard lock(mutex_);
    if (free_.size() < 2) free_.push_back(std::move(b));
}

BufferPool& buffer_pool() {
    static BufferPool pool;
    return pool;
}

// Empty arrays that keep their room.
void clear(VertexGroup& g) {
    g.positions.clear();
    g.normals.clear();
    g.pinned.clear();
}

} // namespace isoparm::geom::implicit::detail
