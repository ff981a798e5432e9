// Tests of the implicit-surface polygonizer: topology, accuracy, orientation, errors, determinism.
#include <gtest/gtest.h>

#include <cmath>
#include <glm/geometric.hpp>
#include <map>
#include <numbers>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "core/geom/implicit/polygonize.hpp"

namespace isoparm::geom::implicit {
namespace {

Program must_compile(const std::string& text, const std::vector<std::string>& names = {}) {
    auto p = compile(text, names);
    EXPECT_TRUE(p.ok()) << text;
    return p ? std::move(p).value() : std::move(compile("x")).value();
}

Mesh must_polygonize(const Program& f, const PolygonizeOptions& o) {
    auto m = polygonize(f, o);
    EXPECT_TRUE(m.ok()) << (m ? "" : m.error().message);
    return m ? std::move(m).value() : Mesh{};
}

PolygonizeOptions box(double lo, double hi, double cell) {
    PolygonizeOptions o;
    o.lo = glm::dvec3(lo);
    o.hi = glm::dvec3(hi);
    o.cell = cell;
    return o;
}

struct Topology {
    bool closed = true;         // every edge has exactly two triangles
    bool consistent = true;     // each directed edge appears at most once
    bool degenerate = false;    // some triangle repeats a vertex
    bool unused_vertex = false; // some vertex has no triangle
    long euler = 0;             // V - E + F
    long boundary_edges = 0;
};

Topology topology(const Mesh& m) {
    Topology t;
    std::map<std::pair<std::uint32_t, std::uint32_t>, int> directed;
    std::vector<char> used(m.positions.size(), 0);
    for (const auto& tri : m.triangles) {
        if (tri[0] == tri[1] || tri[1] == tri[2] || tri[0] == tri[2]) t.degenerate = true;
        for (int k = 0; k < 3; ++k) {
            used[tri[k]] = 1;
            if (++directed[{tri[k], tri[(k + 1) % 3]}] > 1) t.consistent = false;
        }
    }
    long edges = 0;
    for (const auto& [e, count] : directed) {
        const bool has_reverse = directed.count({e.second, e.first}) > 0;
        if (!has_reverse) {
            t.closed = false;
            ++t.boundary_edges;
            ++edges;
        } else if (e.first < e.second) {
            ++edges;
        }
    }
    for (char u : used)
        if (!u) t.unused_vertex = true;
    t.euler = static_cast<long>(m.positions.size()) - edges + static_cast<long>(m.triangles.size());
    return t;
}

// Signed volume by the divergence theorem: positive when triangles face outwards.
double signed_volume(const Mesh& m) {
    double v = 0;
    for (const auto& t : m.triangles)
        v += glm::dot(m.positions[t[0]], glm::cross(m.positions[t[1]], m.positions[t[2]])) / 6.0;
    return v;
}

// Every vertex is on the surface (|f| tiny against |grad f|), its normal is grad f / |grad f|,
// and every triangle turns counter-clockwise about its vertices' normals.
void expect_accurate(const Program& f, const Mesh& m, const std::vector<double>& params = {},
                     double tolerance = 1e-9) {
    const double* pv = params.empty() ? nullptr : params.data();
    ASSERT_EQ(m.normals.size(), m.positions.size());
    ASSERT_EQ(m.exists.size(), m.positions.size());
    int worst_count = 0;
    for (std::size_t v = 0; v < m.positions.size(); ++v) {
        glm::dvec3 g;
        const double value = f.value_and_gradient(m.positions[v], g, pv);
        const double gl = glm::length(g);
        if (!(std::fabs(value) <= tolerance * gl) && worst_count++ < 5)
            ADD_FAILURE() << "vertex " << v << " has f = " << value << ", |grad f| = " << gl;
        EXPECT_NEAR(glm::length(m.normals[v]), 1.0, 1e-12);
        if (gl > 0 && worst_count == 0) {
            EXPECT_GT(glm::dot(m.normals[v], g / gl), 1 - 1e-12);
        }
    }
    int flipped = 0;
    for (const auto& t : m.triangles) {
        const glm::dvec3 face = glm::cross(m.positions[t[1]] - m.positions[t[0]],
                                           m.positions[t[2]] - m.positions[t[0]]);
        EXPECT_GT(glm::length(face), 0.0);
        const glm::dvec3 around = m.normals[t[0]] + m.normals[t[1]] + m.normals[t[2]];
        if (glm::dot(face, around) <= 0) ++flipped;
    }
    EXPECT_EQ(flipped, 0) << "of " << m.triangles.size() << " triangles";
}

TEST(ImplicitPolygonize, SphereIsAClosedSphere) {
    const Program f = must_compile("x^2 + y^2 + z^2 - 0.8^2");
    const Mesh m = must_polygonize(f, box(-1, 1, 0.1));
    ASSERT_GT(m.triangles.size(), 500u);
    const Topology t = topology(m);
    EXPECT_TRUE(t.closed);
    EXPECT_TRUE(t.consistent);
    EXPECT_FALSE(t.degenerate);
    EXPECT_FALSE(t.unused_vertex);
    EXPECT_EQ(t.euler, 2);
    expect_accurate(f, m);
    // Outward-facing (grad f points out), and close to the true volume.
    const double exact = 4.0 / 3.0 * std::numbers::pi * 0.8 * 0.8 * 0.8;
    EXPECT_NEAR(signed_volume(m), exact, 0.02 * exact);
}

TEST(ImplicitPolygonize, TorusIsAClosedTorus) {
    const Program f =
        must_compile("(x^2 + y^2 + z^2 + R^2 - r^2)^2 - 4*R^2*(x^2 + y^2)", {"R", "r"});
    PolygonizeOptions o = box(-1, 1, 2.0 / 64);
    o.parameters = {0.6, 0.25};
    const Mesh m = must_polygonize(f, o);
    const Topology t = topology(m);
    EXPECT_TRUE(t.closed);
    EXPECT_TRUE(t.consistent);
    EXPECT_FALSE(t.degenerate);
    EXPECT_FALSE(t.unused_vertex);
    EXPECT_EQ(t.euler, 0);
    expect_accurate(f, m, o.parameters);
    const double exact = 2 * std::numbers::pi * std::numbers::pi * 0.6 * 0.25 * 0.25;
    EXPECT_NEAR(signed_volume(m), exact, 0.02 * exact);
}

TEST(ImplicitPolygonize, ManySpheresAtRandomPlacesAreClosed) {
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> centre(-0.3, 0.3), radius(0.15, 0.6), cell(0.04, 0.2);
    for (int k = 0; k < 25; ++k) {
        const double cx = centre(rng), cy = centre(rng), cz = centre(rng), r = radius(rng);
        const Program f = must_compile("(x-a)^2 + (y-b)^2 + (z-c)^2 - r^2", {"a", "b", "c", "r"});
        PolygonizeOptions o = box(-1, 1, cell(rng));
        o.parameters = {cx, cy, cz, r};
        const Mesh m = must_polygonize(f, o);
        const Topology t = topology(m);
        EXPECT_TRUE(t.closed && t.consistent && !t.degenerate && !t.unused_vertex) << k;
        EXPECT_EQ(t.euler, 2) << k;
        expect_accurate(f, m, o.parameters);
        EXPECT_GT(signed_volume(m), 0) << k;
    }
}

TEST(ImplicitPolygonize, ZerosOnGridPointsAreWelded) {
    // The unit sphere in [-1, 1]^3 with cell 0.1 passes exactly through grid points (the
    // poles touch the bounds, and (0.6, 0.8, 0) is on it up to rounding); a sphere of radius
    // 0.5 with cell 0.25 passes exactly through six interior grid points.
    for (const auto& [text, cell] :
         std::vector<std::pair<std::string, double>>{{"x^2 + y^2 + z^2 - 1", 0.1},
                                                     {"x^2 + y^2 + z^2 - 0.25", 0.25},
                                                     {"x^2 + y^2 + z^2 - 0.25", 0.125},
                                                     {"abs(x) + abs(y) + abs(z) - 0.5", 0.25}}) {
        const Program f = must_compile(text);
        const Mesh m = must_polygonize(f, box(-1, 1, cell));
        const Topology t = topology(m);
        EXPECT_TRUE(t.closed) << text;
        EXPECT_TRUE(t.consistent) << text;
        EXPECT_FALSE(t.degenerate) << text;
        EXPECT_FALSE(t.unused_vertex) << text;
        EXPECT_EQ(t.euler, 2) << text;
        expect_accurate(f, m);
        EXPECT_GT(signed_volume(m), 0) << text;
    }
}

TEST(ImplicitPolygonize, PlaneOnAGridLayerIsOneSheet) {
    const Program f = must_compile("z");
    const Mesh m = must_polygonize(f, box(-1, 1, 0.1));
    const Topology t = topology(m);
    EXPECT_TRUE(t.consistent);
    EXPECT_FALSE(t.degenerate);
    EXPECT_FALSE(t.unused_vertex);
    EXPECT_EQ(t.euler, 1); // a disk
    EXPECT_EQ(m.positions.size(), 21u * 21u);
    EXPECT_EQ(t.boundary_edges, 80);
    for (const auto& p : m.positions) EXPECT_EQ(p.z, 0.0);
    for (const auto& n : m.normals) EXPECT_EQ(n, glm::dvec3(0, 0, 1));
    expect_accurate(f, m);
}

TEST(ImplicitPolygonize, OpenWhereTheSurfaceLeavesTheBounds) {
    const Program f = must_compile("x^2 + y^2 + z^2 - 1");
    const Mesh m = must_polygonize(f, box(0, 2, 0.1)); // one octant of the sphere
    const Topology t = topology(m);
    EXPECT_FALSE(t.closed);
    EXPECT_TRUE(t.consistent);
    EXPECT_EQ(t.euler, 1);
    expect_accurate(f, m);
}

TEST(ImplicitPolygonize, EmptyWhenTheSurfaceIsOutsideTheBounds) {
    const Program f = must_compile("x^2 + y^2 + z^2 - 0.01");
    PolygonizeOptions o = box(2, 3, 0.1);
    auto m = polygonize(f, o);
    ASSERT_TRUE(m.ok());
    EXPECT_TRUE(m->positions.empty());
    EXPECT_TRUE(m->triangles.empty());
    const Program nowhere = must_compile("x^2 + 1");
    auto n = polygonize(nowhere, box(-1, 1, 0.2));
    ASSERT_TRUE(n.ok());
    EXPECT_TRUE(n->triangles.empty());
}

TEST(ImplicitPolygonize, HugeGridIsALimitError) {
    const Program f = must_compile("x^2 + y^2 + z^2 - 0.5");
    auto m = polygonize(f, box(-1, 1, 1e-3));
    ASSERT_FALSE(m.ok());
    EXPECT_EQ(m.error().code, ErrorCode::limit);
    EXPECT_EQ(m.error().path, "/cell");
    auto tiny = polygonize(f, box(-1, 1, 1e-300)); // no integer overflow on the way
    ASSERT_FALSE(tiny.ok());
    EXPECT_EQ(tiny.error().code, ErrorCode::limit);
    // 215^3 points is under 10,000,000; 216^3 is over.
    PolygonizeOptions under = box(0, 214, 1);
    const Program none = must_compile("x + 1000");
    EXPECT_TRUE(polygonize(none, under).ok());
    PolygonizeOptions over = box(0, 215, 1);
    EXPECT_FALSE(polygonize(none, over).ok());
}

TEST(ImplicitPolygonize, BadOptionsAreSchemaErrors) {
    const Program f = must_compile("x^2 + y^2 + z^2 - a", {"a"});
    auto check = [&](PolygonizeOptions o, const std::string& path) {
        auto m = polygonize(f, o);
        ASSERT_FALSE(m.ok()) << path;
        EXPECT_EQ(m.error().code, ErrorCode::schema) << m.error().message;
        EXPECT_EQ(m.error().path, path) << m.error().message;
    };
    PolygonizeOptions o = box(-1, 1, 0.1);
    o.parameters = {0.5};
    EXPECT_TRUE(polygonize(f, o).ok());
    for (double cell : {0.0, -0.1, std::nan(""), HUGE_VAL}) {
        PolygonizeOptions b = o;
        b.cell = cell;
        check(b, "/cell");
    }
    PolygonizeOptions flat = o;
    flat.hi.y = flat.lo.y;
    check(flat, "/bounds");
    PolygonizeOptions inverted = o;
    inverted.lo.z = 2;
    check(inverted, "/bounds");
    PolygonizeOptions infinite = o;
    infinite.hi.x = HUGE_VAL;
    check(infinite, "/bounds");
    PolygonizeOptions missing = o;
    missing.parameters.clear();
    check(missing, "/parameters");
    PolygonizeOptions nan_param = o;
    nan_param.parameters = {std::nan("")};
    check(nan_param, "/parameters/0");
}

TEST(ImplicitPolygonize, SameMeshForAnyThreadCount) {
    const Program f = must_compile("(x^2 + y^2 + z^2 + 0.36 - 0.0625)^2 - 1.44*(x^2 + y^2)");
    PolygonizeOptions o = box(-1, 1, 2.0 / 96);
    o.threads = 1;
    const Mesh a = must_polygonize(f, o);
    o.threads = 2;
    const Mesh b = must_polygonize(f, o);
    o.threads = 5;
    const Mesh c = must_polygonize(f, o);
    o.threads = 0;
    const Mesh d = must_polygonize(f, o);
    ASSERT_FALSE(a.triangles.empty());
    for (const Mesh* other : {&b, &c, &d}) {
        EXPECT_EQ(a.positions, other->positions);
        EXPECT_EQ(a.normals, other->normals);
        EXPECT_EQ(a.triangles, other->triangles);
    }
}

TEST(ImplicitPolygonize, ProgressReportsAndCancels) {
    const Program f = must_compile("x^2 + y^2 + z^2 - 0.5");
    PolygonizeOptions o = box(-1, 1, 0.05);
    std::vector<double> seen;
    o.progress = [&](double p) {
        seen.push_back(p);
        return true;
    };
    ASSERT_TRUE(polygonize(f, o).ok());
    ASSERT_FALSE(seen.empty());
    EXPECT_EQ(seen.back(), 1.0);
    for (std::size_t k = 1; k < seen.size(); ++k) EXPECT_LE(seen[k - 1], seen[k]);
    for (double p : seen) EXPECT_TRUE(p >= 0 && p <= 1);

    // Only the calling thread reports, after each unit it finishes. Alone it reports after
    // every unit, so it can be stopped at the third; with a helper, a busy machine may let the
    // helper take all but one unit (then the calling thread reports twice: one unit and the
    // end), so there only the first report is sure to come before the end.
    for (int threads : {1, 2}) {
        const int cancel_at = threads == 1 ? 3 : 1;
        int calls = 0;
        o.threads = threads;
        o.progress = [&](double) { return ++calls < cancel_at; };
        auto m = polygonize(f, o);
        ASSERT_FALSE(m.ok()) << threads;
        EXPECT_EQ(m.error().code, ErrorCode::limit);
        EXPECT_EQ(m.error().message, "polygonization was cancelled");
        EXPECT_EQ(calls, cancel_at);
    }
}

TEST(ImplicitPolygonize, ZeroGradientStillGetsAUnitNormal) {
    // A double cone: grad f = 0 at its apex, which is a grid point.
    const Program f = must_compile("x^2 + y^2 - z^2");
    const Mesh m = must_polygonize(f, box(-1, 1, 0.25));
    ASSERT_FALSE(m.triangles.empty());
    bool apex = false;
    for (std::size_t v = 0; v < m.positions.size(); ++v) {
        EXPECT_NEAR(glm::length(m.normals[v]), 1.0, 1e-12);
        if (m.positions[v] == glm::dvec3(0.0)) apex = true;
    }
    EXPECT_TRUE(apex);
    EXPECT_FALSE(topology(m).degenerate);
}

TEST(ImplicitPolygonize, UndefinedValuesCountAsPositive) {
    // log(x) is NaN for x < 0 (counted positive), -inf at 0 and negative up to x = 1: the
    // polygonizer still gives finite positions and unit normals, and no triangle crosses x < 0.
    const Program f = must_compile("log(x) + 0*y*z");
    const Mesh m = must_polygonize(f, box(-1, 1, 0.1));
    ASSERT_FALSE(m.triangles.empty());
    EXPECT_TRUE(topology(m).consistent);
    for (std::size_t v = 0; v < m.positions.size(); ++v) {
        EXPECT_TRUE(std::isfinite(glm::length(m.positions[v])));
        EXPECT_NEAR(glm::length(m.normals[v]), 1.0, 1e-12);
        EXPECT_GE(m.positions[v].x, -1e-12);
    }
}

TEST(ImplicitPolygonize, PresetsGiveConsistentMeshes) {
    // Goursat's tangle (closed, genus 5), a heart, Steiner's Roman surface and the Clebsch cubic
    // (singular or unbounded, so only orientation consistency and unit normals are checked).
    const Program goursat = must_compile("x^4 - 5*x^2 + y^4 - 5*y^2 + z^4 - 5*z^2 + 11.8");
    const Mesh g = must_polygonize(goursat, box(-3, 3, 0.1));
    const Topology tg = topology(g);
    EXPECT_TRUE(tg.closed && tg.consistent && !tg.degenerate);
    EXPECT_EQ(tg.euler, 2 - 2 * 5);
    expect_accurate(goursat, g);
    for (const std::string text :
         {"(x^2 + 9/4*y^2 + z^2 - 1)^3 - x^2*z^3 - 9/80*y^2*z^3",
          "x^2*y^2 + y^2*z^2 + z^2*x^2 - x*y*z",
          "81*(x^3 + y^3 + z^3) - 189*(x^2*y + x^2*z + y^2*x + y^2*z + z^2*x + z^2*y) + "
          "54*x*y*z + 126*(x*y + x*z + y*z) - 9*(x^2 + y^2 + z^2) - 9*(x + y + z) + 1"}) {
        const Program f = must_compile(text);
        const Mesh m = must_polygonize(f, box(-1.5, 1.5, 0.07));
        EXPECT_FALSE(m.triangles.empty()) << text;
        const Topology t = topology(m);
        EXPECT_TRUE(t.consistent) << text;
        EXPECT_FALSE(t.degenerate) << text;
        for (const auto& n : m.normals) EXPECT_NEAR(glm::length(n), 1.0, 1e-12);
    }
}

TEST(ImplicitPolygonize, GridFollowsConvention18) {
    // ceil(2 / 0.3) = 7 cells per axis, so the plane x = 0.01 lies in one column of cells and
    // crosses (2n + 1)^2 = 225 of its edges (x, x+y, x+z and x+y+z directions) for n = 7.
    const Program f = must_compile("x - 0.01");
    const Mesh m = must_polygonize(f, box(-1, 1, 0.3));
    EXPECT_EQ(m.positions.size(), 225u);
    EXPECT_EQ(m.triangles.size(), 8u * 7 * 7); // a disk: V - E + F = 1 with 56 boundary edges
    for (const auto& p : m.positions) EXPECT_NEAR(p.x, 0.01, 1e-15);
    expect_accurate(f, m);
}

TEST(ImplicitPolygonize, DropDegenerateTriangles) {
    Mesh m;
    m.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {5, 5, 5}, {1, 1, 0}};
    m.normals.assign(5, glm::dvec3(0, 0, 1));
    m.exists.assign(5, 1);
    m.triangles = {{0, 1, 2}, {1, 1, 3}, {1, 4, 2}, {3, 3, 3}};
    EXPECT_EQ(drop_degenerate_triangles(m), 2u);
    ASSERT_EQ(m.positions.size(), 4u); // vertex 3 is gone
    EXPECT_EQ(m.positions[3], glm::dvec3(1, 1, 0));
    EXPECT_EQ(m.triangles, (std::vector<std::array<std::uint32_t, 3>>{{0, 1, 2}, {1, 3, 2}}));
}

// A closed mesh inside its box is seen from outside only from the sign of f on the box's
// boundary: its triangles run counter-clockwise seen from there (the cross product of a
// sphere's triangle points outward for f = r^2 - 1, inward for 1 - r^2). A surface that meets a
// face of the box, or no surface at all, has no such side.
TEST(Polygonize, SideSeenFromOutsideOfAClosedMesh) {
    struct Case {
        const char* f;
        double lo, hi;
        int side;
    };
    const Case cases[] = {
        {"x^2 + y^2 + z^2 - 1", -2, 2, 1},
        {"1 - x^2 - y^2 - z^2", -2, 2, -1},
        {"(x^2 + y^2 + z^2 - 1) * (x^2 + y^2 + z^2 - 2.25)", -2, 2, 1}, // nested spheres
        {"x^2 + y^2 + z^2 - 1", -0.5, 2, 0},                            // cut by the box
        {"x - 0.25", -1, 1, 0},                                         // a plane leaves it
        {"x^2 + y^2 + z^2 + 1", -2, 2, 0},                              // nothing inside
    };
    for (const Case& c : cases) {
        const Program f = must_compile(c.f);
        const PolygonizeOptions o = box(c.lo, c.hi, 0.125);
        const Mesh m = must_polygonize(f, o);
        EXPECT_EQ(side_seen_from_outside(f, o, m), c.side) << c.f << " in " << c.lo;
        if (c.side == 0 || c.lo != -2 || std::string(c.f).find('*') != std::string::npos) continue;
        EXPECT_TRUE(topology(m).closed) << c.f;
        for (const auto& t : m.triangles) {
            const glm::dvec3 a = m.positions[t[0]], b = m.positions[t[1]], d = m.positions[t[2]];
            const double outward = glm::dot(glm::cross(b - a, d - a), a + b + d);
            ASSERT_GT(outward * c.side, 0) << c.f;
        }
    }
}

} // namespace
} // namespace isoparm::geom::implicit
