// Trim loops: validation errors, point classification, watertight trimmed meshes, area.
#include <gtest/gtest.h>

#include <cmath>
#include <glm/geometric.hpp>
#include <map>
#include <numbers>
#include <random>

#include "core/geom/evaluate.hpp"
#include "core/geom/knots.hpp"
#include "core/geom/trim/trim.hpp"
#include "core/geom/trim/trim_area.hpp"
#include "core/geom/trim/trim_classify.hpp"
#include "core/geom/trim/trim_validate.hpp"
#include "core/geom/trim/trimmed_tessellator.hpp"

using namespace isoparm::geom;

namespace {

const ParamRect unit{{0, 1}, {0, 1}};

// A bicubic height field over [0, 2] x [0, 1] (parameters = x, y up to the bump).
Surface bump(int nu = 6, int nv = 5) {
    Surface s;
    s.type = SplineType::bspline;
    s.degree_u = s.degree_v = 3;
    s.n_u = nu;
    s.n_v = nv;
    s.knots_u = clamped_uniform_knots(nu, 3);
    s.knots_v = clamped_uniform_knots(nv, 3);
    for (int i = 0; i < nu; ++i)
        for (int j = 0; j < nv; ++j) {
            s.points.push_back(
                {2.0 * i / (nu - 1), 1.0 * j / (nv - 1), 0.3 * std::sin(1.7 * i + 0.9 * j)});
            s.weights.push_back(1);
        }
    return s;
}

// The plane z = 0 over [0, w] x [0, h] as a bilinear patch on [0, 1]^2.
Surface plane(double w, double h) {
    Surface s;
    s.type = SplineType::bspline;
    s.degree_u = s.degree_v = 1;
    s.n_u = s.n_v = 2;
    s.knots_u = s.knots_v = {0, 0, 1, 1};
    s.points = {{0, 0, 0}, {0, h, 0}, {w, 0, 0}, {w, h, 0}};
    s.weights = {1, 1, 1, 1};
    return s;
}

Trim disc_with_holes() {
    Trim t;
    t.outer = *circle_loop({0.5, 0.5}, 0.45, false);
    t.holes.push_back(reversed(polygon_loop({{0.3, 0.3}, {0.45, 0.3}, {0.45, 0.45}, {0.3, 0.45}})));
    t.holes.push_back(*circle_loop({0.62, 0.6}, 0.1, true));
    return t;
}

Error error_of(const Trim& t, const ParamRect& d = unit) {
    const Status s = validate_trim(t, d);
    EXPECT_FALSE(s.ok());
    return s.ok() ? Error{} : s.error();
}

} // namespace

TEST(TrimValidate, AcceptsLinesArcsAndPolygons) {
    EXPECT_TRUE(validate_trim(disc_with_holes(), unit).ok());
    Trim holes_only;
    holes_only.holes.push_back(*circle_loop({0.5, 0.5}, 0.2, true));
    EXPECT_TRUE(validate_trim(holes_only, unit).ok());
    Trim whole;
    whole.outer = rectangle_loop(unit);
    EXPECT_TRUE(validate_trim(whole, unit).ok());
    // A slot: two lines and two half circles, mixing degrees.
    Trim slot;
    slot.outer = TrimLoop{{trim_line({0.3, 0.4}, {0.7, 0.4}), *trim_arc({0.7, 0.5}, 0.1, -90, 90),
                           trim_line({0.7, 0.6}, {0.3, 0.6}), *trim_arc({0.3, 0.5}, 0.1, 90, 270)}};
    EXPECT_TRUE(validate_trim(slot, unit).ok()) << validate_trim(slot, unit).error().message;
}

TEST(TrimValidate, NamesAGapInALoop) {
    Trim t;
    t.outer = TrimLoop{{trim_line({0.1, 0.1}, {0.9, 0.1}), trim_line({0.9, 0.1}, {0.9, 0.9}),
                        trim_line({0.9, 0.92}, {0.1, 0.1})}};
    const Error e = error_of(t);
    EXPECT_EQ(e.code, ErrorCode::geometry);
    EXPECT_EQ(e.path, "/outer/2");
    EXPECT_NE(e.message.find("the outer loop is not closed"), std::string::npos) << e.message;
    EXPECT_NE(e.message.find("curve 1 ends at"), std::string::npos) << e.message;
}

TEST(TrimValidate, NamesASelfIntersection) {
    Trim t;
    t.holes.push_back(polygon_loop({{0.2, 0.2}, {0.8, 0.8}, {0.8, 0.2}, {0.2, 0.8}})); // a bow tie
    const Error e = error_of(t);
    EXPECT_EQ(e.code, ErrorCode::geometry);
    EXPECT_EQ(e.path, "/holes/0/0");
    EXPECT_NE(e.message.find("hole 0 is self-intersecting: its curves 0 and 2 meet at (u, v) = "
                             "(0.5, 0.5)"),
              std::string::npos)
        << e.message;
    // A spike folding back along itself touches itself too.
    Trim spike;
    spike.outer = polygon_loop({{0.1, 0.1}, {0.9, 0.1}, {0.5, 0.1}, {0.5, 0.9}});
    EXPECT_NE(error_of(spike).message.find("self-intersecting"), std::string::npos);
}

TEST(TrimValidate, NamesALoopOutsideTheDomain) {
    Trim t;
    t.holes.push_back(*circle_loop({0.9, 0.5}, 0.2, true));
    const Error e = error_of(t);
    EXPECT_EQ(e.code, ErrorCode::domain);
    EXPECT_EQ(e.path, "/holes/0/0");
    EXPECT_NE(e.message.find("hole 0 leaves the domain [0, 1] x [0, 1]: curve 0 reaches"),
              std::string::npos)
        << e.message;
    // Within the closing tolerance of the edge is inside (files round their numbers).
    Trim edge;
    edge.outer = polygon_loop({{0, -1e-9}, {1 + 1e-9, 0}, {1, 1}, {0, 1}});
    EXPECT_TRUE(validate_trim(edge, unit).ok());
}

TEST(TrimValidate, NamesAWrongOrientation) {
    Trim t;
    t.outer = reversed(*circle_loop({0.5, 0.5}, 0.4, false));
    Error e = error_of(t);
    EXPECT_EQ(e.path, "/outer");
    EXPECT_NE(e.message.find("the outer loop runs clockwise; the outer loop must run "
                             "counter-clockwise"),
              std::string::npos)
        << e.message;
    Trim h;
    h.holes.push_back(*circle_loop({0.5, 0.5}, 0.2, true));
    h.holes.push_back(*circle_loop({0.1, 0.1}, 0.05, false));
    e = error_of(h);
    EXPECT_EQ(e.path, "/holes/1");
    EXPECT_NE(e.message.find("hole 1 runs counter-clockwise; a hole must run clockwise"),
              std::string::npos)
        << e.message;
}

TEST(TrimValidate, NamesLoopsThatCrossOrNest) {
    Trim cross;
    cross.outer = *circle_loop({0.5, 0.5}, 0.3, false);
    cross.holes.push_back(*circle_loop({0.75, 0.5}, 0.1, true));
    Error e = error_of(cross);
    EXPECT_EQ(e.path, "/holes/0");
    EXPECT_NE(e.message.find("hole 0 crosses the outer loop at (u, v) = (0.7"), std::string::npos)
        << e.message;

    Trim outside;
    outside.outer = *circle_loop({0.3, 0.3}, 0.2, false);
    outside.holes.push_back(*circle_loop({0.8, 0.8}, 0.1, true));
    e = error_of(outside);
    EXPECT_EQ(e.path, "/holes/0");
    EXPECT_NE(e.message.find("hole 0 lies outside the outer loop"), std::string::npos) << e.message;

    Trim nested;
    nested.holes.push_back(*circle_loop({0.5, 0.5}, 0.3, true));
    nested.holes.push_back(*circle_loop({0.5, 0.5}, 0.1, true));
    e = error_of(nested);
    EXPECT_EQ(e.path, "/holes/1");
    EXPECT_NE(e.message.find("hole 1 lies inside hole 0"), std::string::npos) << e.message;

    // Touching at one point is crossing too (the kept region would not be a surface there).
    Trim touch;
    touch.holes.push_back(polygon_loop({{0.2, 0.2}, {0.2, 0.5}, {0.5, 0.5}, {0.5, 0.2}}));
    touch.holes.push_back(polygon_loop({{0.5, 0.5}, {0.5, 0.8}, {0.8, 0.8}, {0.8, 0.5}}));
    EXPECT_NE(error_of(touch).message.find("hole 1 crosses hole 0 at (u, v) = (0.5, 0.5)"),
              std::string::npos)
        << error_of(touch).message;
}

TEST(TrimValidate, NamesBadCurves) {
    Trim t;
    t.outer = *circle_loop({0.5, 0.5}, 0.3, false);
    t.outer->curves[0].weights[1] = -0.5;
    Error e = error_of(t);
    EXPECT_EQ(e.code, ErrorCode::weights);
    EXPECT_EQ(e.path, "/outer/0/weights/1");
    EXPECT_NE(e.message.find("the outer loop, curve 0: weight 1 is -0.5; trim curves need "
                             "positive weights"),
              std::string::npos)
        << e.message;

    Trim k;
    k.holes.push_back(*circle_loop({0.5, 0.5}, 0.3, true));
    k.holes[0].curves[0].knots[4] = 0.9; // decreasing
    e = error_of(k);
    EXPECT_EQ(e.code, ErrorCode::knots);
    EXPECT_EQ(e.path.rfind("/holes/0/0/knots", 0), 0u) << e.path;
    EXPECT_EQ(e.message.rfind("hole 0, curve 0: ", 0), 0u) << e.message;

    Trim empty;
    empty.holes.push_back(TrimLoop{});
    e = error_of(empty);
    EXPECT_EQ(e.path, "/holes/0");
    EXPECT_NE(e.message.find("hole 0 has no curves"), std::string::npos);

    Trim flat;
    flat.outer = polygon_loop({{0.1, 0.1}, {0.9, 0.9}}); // there and back
    e = error_of(flat);
    EXPECT_NE(e.message.find("encloses no area"), std::string::npos) << e.message;
}

TEST(TrimClassify, KeptCutAndBoundary) {
    const Trim t = disc_with_holes();
    const TrimClassifier c(t, unit);
    EXPECT_EQ(c.classify({0.5, 0.2}), TrimSide::kept);
    EXPECT_EQ(c.classify({0.02, 0.02}), TrimSide::cut); // outside the outer circle
    EXPECT_EQ(c.classify({0.4, 0.4}), TrimSide::cut);   // in the square hole
    EXPECT_EQ(c.classify({0.62, 0.6}), TrimSide::cut);  // in the round hole
    EXPECT_EQ(c.classify({1.5, 0.5}), TrimSide::cut);   // outside the domain
    EXPECT_EQ(c.classify({0.95, 0.5}), TrimSide::boundary);
    EXPECT_EQ(c.classify({0.45, 0.35}), TrimSide::boundary);
    EXPECT_EQ(c.classify({0.62, 0.5}), TrimSide::boundary);
    // A hair off a loop, inside the chords' tolerance band: the curves decide.
    EXPECT_EQ(c.classify({0.95 - 1e-8, 0.5}), TrimSide::kept);
    EXPECT_EQ(c.classify({0.95 + 1e-8, 0.5}), TrimSide::cut);
    EXPECT_EQ(c.classify({0.62, 0.5 + 1e-8}), TrimSide::cut);
    EXPECT_EQ(c.classify({0.62, 0.5 - 1e-8}), TrimSide::kept);
    // Without an outer loop the domain's edge bounds the kept region.
    Trim h;
    h.holes.push_back(*circle_loop({0.5, 0.5}, 0.2, true));
    const TrimClassifier ch(h, unit);
    EXPECT_EQ(ch.classify({0.05, 0.05}), TrimSide::kept);
    EXPECT_EQ(ch.classify({0.0, 0.5}), TrimSide::boundary);
    EXPECT_EQ(ch.classify({0.5, 0.5}), TrimSide::cut);
}

TEST(TrimClassify, AgreesWithTheExactShapes) {
    const Trim t = disc_with_holes();
    const TrimClassifier c(t, unit);
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> r(-0.1, 1.1);
    int kept = 0, cut = 0;
    for (int k = 0; k < 20000; ++k) {
        const glm::dvec2 p{r(rng), r(rng)};
        const double outer = glm::length(p - glm::dvec2(0.5, 0.5)) - 0.45;
        const double round = glm::length(p - glm::dvec2(0.62, 0.6)) - 0.1;
        const double square = std::max(std::abs(p.x - 0.375), std::abs(p.y - 0.375)) - 0.075;
        const double margin = std::min({std::abs(outer), std::abs(round), std::abs(square)});
        if (margin < 1e-7) continue;
        const bool in_domain = unit.contains(p);
        const bool expected = in_domain && outer < 0 && round > 0 && square > 0;
        const TrimSide got = c.classify(p);
        ASSERT_EQ(got, expected ? TrimSide::kept : TrimSide::cut) << p.x << " " << p.y;
        (expected ? kept : cut) += 1;
    }
    EXPECT_GT(kept, 5000);
    EXPECT_GT(cut, 5000);
}

namespace {

// The watertight property, or what breaks it: every edge used by one triangle runs along a
// loop (consecutive loop vertices, in the loop's direction: the kept region on its left) or,
// without an outer loop, along the domain's edge; every other edge is shared by exactly two
// triangles running it in opposite directions; every loop edge is on the mesh; triangles run
// counter-clockwise in (u, v).
std::string watertight_problem(const TrimmedLayout& L, const Trim& t, const ParamRect& d) {
    std::map<std::pair<std::uint32_t, std::uint32_t>, int> directed;
    for (const auto& tri : L.triangles) {
        for (int k = 0; k < 3; ++k) directed[{tri[k], tri[(k + 1) % 3]}] += 1;
        const glm::dvec2 a = L.param(tri[0]), b = L.param(tri[1]), c = L.param(tri[2]);
        if ((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x) <= 0)
            return "a triangle runs clockwise in (u, v)";
    }
    std::map<std::pair<std::uint32_t, std::uint32_t>, bool> loop_edges;
    for (const auto& loop : L.loops)
        for (std::size_t k = 0; k < loop.size(); ++k)
            loop_edges[{loop[k], loop[(k + 1) % loop.size()]}] = true;
    int boundary = 0;
    for (const auto& [edge, count] : directed) {
        if (count != 1) return "an edge run twice the same way";
        if (directed.count({edge.second, edge.first})) continue;
        ++boundary;
        if (loop_edges.count(edge)) continue;
        const glm::dvec2 a = L.param(edge.first), b = L.param(edge.second);
        const bool on_domain_edge =
            !t.outer && ((a.x == d.u.lo && b.x == d.u.lo) || (a.x == d.u.hi && b.x == d.u.hi) ||
                         (a.y == d.v.lo && b.y == d.v.lo) || (a.y == d.v.hi && b.y == d.v.hi));
        if (!on_domain_edge) return "a boundary edge off every loop";
    }
    for (const auto& [edge, _] : loop_edges) {
        if (!directed.count(edge)) return "a loop edge missing from the mesh";
        if (directed.count({edge.second, edge.first})) return "a loop edge inside the mesh";
    }
    if (boundary == 0) return "no boundary";
    return "";
}

double param_area(const TrimmedLayout& L) {
    double a = 0;
    for (const auto& tri : L.triangles) {
        const glm::dvec2 p = L.param(tri[0]), q = L.param(tri[1]), r = L.param(tri[2]);
        a += 0.5 * ((q.x - p.x) * (r.y - p.y) - (q.y - p.y) * (r.x - p.x));
    }
    return a;
}

double polygon_area(const TrimmedLayout& L, const Trim& t, const ParamRect& d) {
    double a = t.outer ? 0.0 : (d.u.hi - d.u.lo) * (d.v.hi - d.v.lo);
    for (const auto& loop : L.loops) {
        std::vector<glm::dvec2> pts;
        for (auto v : loop) pts.push_back(L.param(v));
        a += 0.5 * twice_signed_area(pts);
    }
    return a;
}

} // namespace

TEST(TrimTessellate, MeshesAreWatertightAlongEveryLoop) {
    const Surface s = bump();
    std::vector<Trim> trims;
    trims.push_back(disc_with_holes());
    Trim holes;
    holes.holes.push_back(*circle_loop({0.5, 0.5}, 0.21, true));
    holes.holes.push_back(reversed(polygon_loop({{0.05, 0.05}, {0.3, 0.1}, {0.2, 0.3}})));
    trims.push_back(holes);
    Trim whole; // the domain's own rectangle, through grid points
    whole.outer = rectangle_loop(unit);
    whole.holes.push_back(
        reversed(polygon_loop({{0.25, 0.25}, {0.75, 0.25}, {0.75, 0.75}, {0.25, 0.75}})));
    trims.push_back(whole);
    Trim star; // a star whose corners touch the domain's edge
    std::vector<glm::dvec2> corners;
    for (int k = 0; k < 10; ++k) {
        const double a = std::numbers::pi * k / 5, r = k % 2 == 0 ? 0.5 : 0.2;
        corners.push_back({0.5 + r * std::cos(a), 0.5 + r * std::sin(a)});
    }
    star.outer = polygon_loop(corners);
    trims.push_back(star);
    for (std::size_t k = 0; k < trims.size(); ++k) {
        ASSERT_TRUE(validate_trim(trims[k], unit).ok()) << k;
        for (const auto& [nu, nv] : {std::pair{5, 5}, {17, 9}, {33, 33}, {64, 80}}) {
            SCOPED_TRACE("trim " + std::to_string(k) + ", grid " + std::to_string(nu) + " x " +
                         std::to_string(nv));
            const TrimmedTessellator tess(s, trims[k], nu, nv);
            EXPECT_EQ(watertight_problem(tess.layout(), trims[k], unit), "");
            EXPECT_NEAR(param_area(tess.layout()), polygon_area(tess.layout(), trims[k], unit),
                        1e-12);
            Mesh m;
            tess.evaluate(s, m);
            ASSERT_EQ(m.positions.size(), tess.layout().vertex_count());
            // Every vertex is the surface at its parameters (grid points from the kernel).
            for (std::uint32_t v = 0; v < m.positions.size(); v += 7) {
                const glm::dvec2 p = tess.layout().param(v);
                EXPECT_LT(glm::length(m.positions[v] - *surface_point(s, p.x, p.y)), 1e-12);
            }
        }
    }
}

TEST(TrimTessellate, TheWatertightCheckSeesCracks) {
    const Surface s = bump();
    const Trim t = disc_with_holes();
    const TrimmedTessellator tess(s, t, 17, 17);
    ASSERT_EQ(watertight_problem(tess.layout(), t, unit), "");
    for (std::size_t k :
         {std::size_t(0), tess.layout().grid_triangles, tess.layout().triangles.size() - 1}) {
        TrimmedLayout cracked = tess.layout();
        cracked.triangles.erase(cracked.triangles.begin() + static_cast<long>(k));
        EXPECT_NE(watertight_problem(cracked, t, unit), "") << k;
    }
    TrimmedLayout flipped = tess.layout();
    std::swap(flipped.triangles[3][0], flipped.triangles[3][1]);
    EXPECT_NE(watertight_problem(flipped, t, unit), "");
}

TEST(TrimTessellate, BoundaryFollowsTheLoopsWithinTheChordTolerance) {
    const Surface s = bump();
    const Trim t = disc_with_holes();
    for (double tol : {1e-2, 1e-3, 1e-4}) {
        const TrimmedTessellator tess(s, t, 20, 20, tol);
        Mesh m;
        tess.evaluate(s, m);
        const TrimClassifier c(t, unit);
        // The mesh's boundary polylines in 3D, loop by loop.
        std::vector<std::pair<glm::dvec3, glm::dvec3>> edges;
        for (const auto& loop : tess.layout().loops)
            for (std::size_t k = 0; k < loop.size(); ++k) {
                EXPECT_EQ(c.classify(tess.layout().param(loop[k])), TrimSide::boundary);
                edges.push_back({m.positions[loop[k]], m.positions[loop[(k + 1) % loop.size()]]});
            }
        // Every point of every trim curve on the surface lies within tol of that boundary.
        double worst = 0;
        for (int l = 0; l < t.loop_count(); ++l)
            for (const Curve& curve : t.loop(l).curves)
                for (int k = 0; k <= 400; ++k) {
                    const Interval d = domain(curve);
                    const glm::dvec3 q = *curve_point(curve, d.lo + (d.hi - d.lo) * k / 400);
                    const glm::dvec3 on = *surface_point(s, q.x, q.y);
                    double best = INFINITY;
                    for (const auto& [a, b] : edges) {
                        const glm::dvec3 ab = b - a;
                        const double f =
                            std::clamp(glm::dot(on - a, ab) / glm::dot(ab, ab), 0.0, 1.0);
                        best = std::min(best, glm::length(on - (a + f * ab)));
                    }
                    worst = std::max(worst, best);
                }
        EXPECT_LT(worst, tol) << tol;
        EXPECT_GT(worst, tol / 100) << "far finer than asked: " << tol;
    }
}

TEST(TrimTessellate, EmptyTrimIsTheGrid) {
    const Surface s = bump();
    const Mesh a = tessellate_trimmed(s, Trim{}, 9, 7);
    const Mesh b = tessellate(s, 9, 7);
    EXPECT_EQ(a.triangles, b.triangles);
    // Holes only: whole cells keep the grid's triangles and vertices.
    Trim h;
    h.holes.push_back(*circle_loop({0.5, 0.5}, 0.05, true));
    const TrimmedTessellator tess(s, h, 33, 33);
    EXPECT_GT(tess.layout().grid_triangles, 2u * 32 * 32 - 40);
}

TEST(TrimArea, PlaneWithAHoleAndADisc) {
    const Surface s = plane(2, 1);
    Trim h;
    h.holes.push_back(*circle_loop({0.5, 0.5}, 0.3, true));
    // The circle in (u, v) is an ellipse 0.6 x 0.3 wide on the plane: area pi 0.6 0.3.
    EXPECT_NEAR(trimmed_area(s, h), 2.0 - std::numbers::pi * 0.6 * 0.3, 2e-9);
    Trim d;
    d.outer = *circle_loop({0.5, 0.5}, 0.3, false);
    EXPECT_NEAR(trimmed_area(s, d), std::numbers::pi * 0.6 * 0.3, 2e-9);
    EXPECT_NEAR(trimmed_area(s, Trim{}), 2.0, 1e-12);
}

TEST(TrimLoops, SmoothLoopIsAClosedC2CubicInsideItsPolygon) {
    const std::vector<glm::dvec2> control{{0.2, 0.2}, {0.8, 0.25}, {0.7, 0.8}, {0.3, 0.7}};
    const TrimLoop loop = smooth_loop(control);
    ASSERT_EQ(loop.curves.size(), 4u);
    for (std::size_t k = 0; k < 4; ++k) {
        const Curve& a = loop.curves[k];
        const Curve& b = loop.curves[(k + 1) % 4];
        EXPECT_EQ(a.degree, 3);
        // Closed exactly, and C2 where the pieces meet (uniform knots, equal Bezier spans).
        EXPECT_EQ(a.points.back(), b.points.front());
        const auto da = *curve_derivatives(a, 1.0, 2), db = *curve_derivatives(b, 0.0, 2);
        for (int d = 1; d <= 2; ++d) EXPECT_NEAR(glm::length(da[d] - db[d]), 0.0, 1e-12) << d;
    }
    // The B-spline's point at the knot between P1 and P2: (P0 + 4 P1 + P2) / 6.
    const glm::dvec3 start = *curve_point(loop.curves[1], 0.0);
    EXPECT_NEAR(start.x, (0.2 + 4 * 0.8 + 0.7) / 6, 1e-15);
    EXPECT_NEAR(start.y, (0.2 + 4 * 0.25 + 0.8) / 6, 1e-15);
    // Runs the polygon's way (counter-clockwise) and is a valid outer loop of the unit square.
    Trim t;
    t.outer = loop;
    EXPECT_TRUE(validate_trim(t, unit));
    EXPECT_FALSE(validate_trim(Trim{std::nullopt, {loop}}, unit)); // not a clockwise hole
}
