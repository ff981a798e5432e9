// The control nets the Control point panel's plane canvases draw: a surface's rows and
// columns, a triangle's lines i, j, k = const, each segment one step of the net.
#include <gtest/gtest.h>

#include <cstdlib>
#include <set>

#include "core/doc/commands_triangle.hpp"
#include "ui/view/control_net.hpp"

using namespace isoparm;
using namespace isoparm::ui;

namespace {

doc::Object object_with(doc::Shape shape) {
    doc::Object o;
    o.shape = std::move(shape);
    return o;
}

} // namespace

TEST(ControlNet, ASurfacesRowsAndColumns) {
    geom::Surface s;
    s.n_u = 3;
    s.n_v = 4;
    for (int k = 0; k < 12; ++k) s.points.push_back({static_cast<double>(k), 0, 0});
    s.weights.assign(12, 1.0);
    const ControlNet net = control_net_of(object_with(doc::SurfaceObject{s}));
    ASSERT_EQ(net.points.size(), 12u);
    EXPECT_EQ(net.lines.size(), 7u);
    EXPECT_EQ(net.points[static_cast<std::size_t>(net.find(2, 1))], s.point(2, 1));
    EXPECT_EQ(net.find(3, 0), -1);
}

TEST(ControlNet, ATrianglesLinesCoverItsEdgesOnce) {
    for (int n : {1, 2, 3, 5}) {
        const geom::TrianglePatch t = doc::make_flat_triangle(n, false).value();
        const ControlNet net = control_net_of(object_with(doc::TriangleObject{t}));
        ASSERT_EQ(net.points.size(), static_cast<std::size_t>((n + 1) * (n + 2) / 2));
        std::set<std::pair<int, int>> segments;
        for (const auto& line : net.lines)
            for (std::size_t q = 1; q < line.size(); ++q) {
                const auto [i0, j0] = net.ids[static_cast<std::size_t>(line[q - 1])];
                const auto [i1, j1] = net.ids[static_cast<std::size_t>(line[q])];
                // One step of the net: one index up by one, another down by one.
                const int di = i1 - i0, dj = j1 - j0, dk = -(di + dj);
                EXPECT_EQ(std::abs(di) + std::abs(dj) + std::abs(dk), 2) << n;
                segments.insert(std::minmax(line[q - 1], line[q]));
            }
        EXPECT_EQ(segments.size(), static_cast<std::size_t>(3 * n * (n + 1) / 2)) << n;
        for (std::size_t q = 0; q < net.points.size(); ++q) {
            const auto [i, j] = net.ids[q];
            EXPECT_EQ(net.points[q], t.points[geom::TrianglePatch::index(n, i, j)]);
        }
    }
}
