// Grid and snap: steps a ruler uses, grid values that are the decimals they show, snapping to
// points, axes and the grid, and the modifier's "off".
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <random>

#include "ui/view/snap.hpp"

using namespace isoparm::ui;

namespace {

// The decimal k m 10^e read by strtod: what a person types for that grid line.
double decimal(GridStep s, long long k) {
    char text[64];
    std::snprintf(text, sizeof text, "%llde%d", k * s.mantissa, s.exponent);
    return std::strtod(text, nullptr);
}

TEST(Snap, GridStepsAreOneTwoFiveAndFollowTheZoom) {
    EXPECT_EQ(grid_step_for(100, 20), (GridStep{2, -1})); // 0.2 units = 20 px
    EXPECT_EQ(grid_step_for(100, 21), (GridStep{5, -1}));
    EXPECT_EQ(grid_step_for(10, 20), (GridStep{2, 0}));
    EXPECT_EQ(grid_step_for(1e4, 10), (GridStep{1, -3}));
    EXPECT_EQ(grid_step_for(0.5, 20), (GridStep{5, 1}));
    EXPECT_EQ(coarser({1, -1}), (GridStep{2, -1}));
    EXPECT_EQ(coarser({5, -1}), (GridStep{1, 0}));
    // Never finer than asked, at any zoom.
    for (double ppu = 0.01; ppu < 1e6; ppu *= 1.37) {
        const GridStep s = grid_step_for(ppu, 16);
        EXPECT_GE(s.value() * ppu, 16 * (1 - 1e-9)) << ppu;
        EXPECT_LT(s.value() * ppu, 16 * 2.5 + 1e-9) << ppu;
    }
}

TEST(Snap, SnappingLandsExactlyOnGridValues) {
    EXPECT_EQ(snap_to_grid(0.003, {1, -1}), 0.0);
    EXPECT_FALSE(std::signbit(snap_to_grid(-0.003, {1, -1}))); // never -0
    EXPECT_EQ(snap_to_grid(0.29, {1, -1}), 0.3);               // not 3 * 0.1
    EXPECT_NE(3 * 0.1, 0.3);
    EXPECT_EQ(snap_to_grid(0.71, {5, -2}), 0.7);
    EXPECT_EQ(snap_to_grid(-1.26, {2, -1}), -1.2);
    EXPECT_EQ(snap_to_grid(1234.0, {5, 2}), 1000.0);
    EXPECT_EQ(grid_label({1, -1}, 3), "0.3");
    std::mt19937_64 rng(32);
    std::uniform_real_distribution<double> x(-50, 50);
    const GridStep steps[] = {{1, -3}, {2, -2}, {5, -2}, {1, -1}, {2, -1}, {5, -1}, {1, 0}, {2, 1}};
    for (const GridStep s : steps)
        for (int n = 0; n < 2000; ++n) {
            const double v = x(rng);
            const double g = snap_to_grid(v, s);
            const long long k = std::llround(g / s.value());
            // The snapped value is bit for bit the decimal a person would type for it ...
            ASSERT_EQ(g, decimal(s, k) + 0.0) << v << " step " << s.mantissa << "e" << s.exponent;
            // ... and the nearest grid value.
            EXPECT_LE(std::abs(g - v), s.value() / 2 * (1 + 1e-12));
        }
}

TEST(Snap, GridRangeListsTheLinesInsideAView) {
    const GridRange r = grid_range({1, -1}, -0.25, 0.31);
    EXPECT_EQ(r.first, -2);
    EXPECT_EQ(r.last, 3);
    const GridRange exact = grid_range({1, -1}, 0.3, 0.3);
    EXPECT_EQ(exact.first, 3);
    EXPECT_EQ(exact.last, 3);
    EXPECT_GT(grid_range({1, 0}, 0.2, 0.8).first, grid_range({1, 0}, 0.2, 0.8).last);
}

TEST(Snap, PlanePointsSnapToPointsThenAxesThenAlignmentsThenTheGrid) {
    SnapSettings s; // grid, axes and points, 8 px
    const GridStep step{1, -1};
    const double upp = 0.01; // 100 px per unit: the radius is 0.08 units
    // Near another point: exactly its coordinates.
    Snapped2 a = snap_plane_point({1.03, 0.51}, s, step, upp, {{1, 0.5}, {3, 3}});
    EXPECT_EQ(a.p, glm::dvec2(1, 0.5));
    EXPECT_EQ(a.point, 0);
    // Near the axis x = 0: 0, the other coordinate to the grid.
    Snapped2 b = snap_plane_point({0.003, 0.77}, s, step, upp, {});
    EXPECT_EQ(b.p, glm::dvec2(0, 0.8));
    EXPECT_EQ(b.kind[0], SnapKind::axis);
    EXPECT_EQ(b.kind[1], SnapKind::grid);
    // Aligned with another point in one coordinate only: exactly that coordinate (1.55 is not a
    // grid value), the other to the grid; the axis wins over an alignment.
    Snapped2 d = snap_plane_point({1.56, 0.77}, s, step, upp, {{1.55, 0.3}, {1.5, 2}});
    EXPECT_EQ(d.p, glm::dvec2(1.55, 0.8));
    EXPECT_EQ(d.kind[0], SnapKind::point);
    EXPECT_EQ(d.kind[1], SnapKind::grid);
    EXPECT_EQ(d.point, -1);
    EXPECT_EQ(snap_plane_point({0.003, 0.77}, s, step, upp, {{0.01, 3}}).p, glm::dvec2(0, 0.8));
    // Axes without the grid.
    s.grid = false;
    Snapped2 c = snap_plane_point({0.05, 0.77}, s, step, upp, {});
    EXPECT_EQ(c.p, glm::dvec2(0, 0.77));
    // Everything off (the modifier): as it is.
    s = SnapSettings{false, false, false};
    EXPECT_EQ(snap_plane_point({0.003, 0.77}, s, step, upp, {{0, 0.77}}).p,
              glm::dvec2(0.003, 0.77));
}

TEST(Snap, SpacePointsSnapOnlyTheAxesTheDragMoves) {
    SnapSettings s;
    const bool along_z[3] = {false, false, true};
    Snapped3 a =
        snap_space_point({0.123, 0.456, 0.789}, {10, 10}, s, {1, -1}, 0.001, along_z, {}, {});
    EXPECT_EQ(a.p, glm::dvec3(0.123, 0.456, 0.8));
    const bool all[3] = {true, true, true};
    Snapped3 b = snap_space_point({0.123, 0.456, 0.789}, {10, 10}, s, {1, -1}, 0.001, all,
                                  {{2, 2, 2}}, {{14, 13}});
    EXPECT_EQ(b.p, glm::dvec3(2, 2, 2)); // 5 px away on screen
    EXPECT_EQ(b.point, 0);
}

} // namespace
