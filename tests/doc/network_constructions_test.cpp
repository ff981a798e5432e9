// Construct > Coons and Gordon on document curves: the surfaces keep their boundaries (their
// network), and refusals name the curve or the count at fault.
#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include "core/doc/commands_curve.hpp"
#include "core/doc/curve_constructions.hpp"
#include "core/geom/evaluate.hpp"
#include "tests/doc/doc_fixtures.hpp"

using namespace isoparm;
using namespace isoparm::doc;
using namespace isoparm::doc::testing;
using geom::ErrorCode;

namespace {

std::uint64_t add_curve(Document& doc, const std::string& name, std::vector<glm::dvec3> points) {
    auto o = new_curve_object(name, CurvePlane::free3d, std::move(points), 2,
                              CurveKnotMode::clamped_uniform);
    EXPECT_TRUE(o.ok());
    o->id = doc.allocate_id();
    doc.objects.push_back(*o);
    return o->id;
}

// Four boundaries of a saddle-like patch over the unit square whose ends meet at the corners.
struct Network {
    Document doc = default_document();
    std::uint64_t bottom = add_curve(doc, "bottom", {{0, 0, 0}, {0.5, 0, 0.5}, {1, 0, 0}});
    std::uint64_t top = add_curve(doc, "top", {{0, 1, 0}, {0.5, 1, -0.3}, {1, 1, 0}});
    std::uint64_t left = add_curve(doc, "left", {{0, 0, 0}, {0, 0.5, 0.2}, {0, 1, 0}});
    std::uint64_t right = add_curve(doc, "right", {{1, 0, 0}, {1, 0.5, 0}, {1, 1, 0}});
};

glm::dvec3 at(const Document& doc, std::uint64_t id, double t) {
    return *geom::curve_point(curve_of(doc, id), t);
}

TEST(CoonsConstruction, ReproducesItsFourBoundaries) {
    Network n;
    ConstructionRequest r;
    r.kind = Construction::coons;
    r.curves = {n.bottom, n.top, n.left, n.right};
    auto built = build_construction(n.doc, r);
    ASSERT_TRUE(built.ok()) << built.error().message;
    EXPECT_EQ(built->object.name, "coons bottom-top-left-right");
    const geom::Surface& s = std::get<SurfaceObject>(built->object.shape).surface;
    for (int k = 0; k <= 20; ++k) {
        const double t = k / 20.0;
        EXPECT_LT(glm::distance(*geom::surface_point(s, t, 0), at(n.doc, n.bottom, t)), 1e-12);
        EXPECT_LT(glm::distance(*geom::surface_point(s, t, 1), at(n.doc, n.top, t)), 1e-12);
        EXPECT_LT(glm::distance(*geom::surface_point(s, 0, t), at(n.doc, n.left, t)), 1e-12);
        EXPECT_LT(glm::distance(*geom::surface_point(s, 1, t), at(n.doc, n.right, t)), 1e-12);
    }
    // Undoable like every construction: it is an add_object.
    expect_undo_redo_exact(n.doc, add_object(built->object));
}

TEST(CoonsConstruction, AnOpenCornerNamesTheCurve) {
    Network n;
    const std::uint64_t astray = add_curve(n.doc, "astray", {{1, 0, 0.1}, {1, 0.5, 0}, {1, 1, 0}});
    ConstructionRequest r;
    r.kind = Construction::coons;
    r.curves = {n.bottom, n.top, n.left, astray};
    auto built = build_construction(n.doc, r);
    ASSERT_FALSE(built.ok());
    EXPECT_EQ(built.error().code, ErrorCode::geometry);
    EXPECT_EQ(built.error().path, "/curves/3");
    EXPECT_NE(built.error().message.find("astray"), std::string::npos) << built.error().message;
    r.curves.pop_back();
    auto three = build_construction(n.doc, r);
    ASSERT_FALSE(three.ok());
    EXPECT_EQ(three.error().path, "/curves");
}

TEST(GordonConstruction, InterpolatesItsNetwork) {
    Network n;
    // A third u-curve at v = 1/2 that meets both v-curves at their middles.
    const glm::dvec3 l = at(n.doc, n.left, 0.5), rr = at(n.doc, n.right, 0.5);
    const std::uint64_t middle =
        add_curve(n.doc, "middle", {l, 0.5 * (l + rr) + glm::dvec3(0, 0, 0.4), rr});
    ConstructionRequest r;
    r.kind = Construction::gordon;
    r.curves = {n.bottom, middle, n.top, n.left, n.right};
    r.gordon_u_count = 3;
    auto built = build_construction(n.doc, r);
    ASSERT_TRUE(built.ok()) << built.error().message;
    EXPECT_NE(built->note.find("3 u-curves"), std::string::npos) << built->note;
    const geom::Surface& s = std::get<SurfaceObject>(built->object.shape).surface;
    for (int k = 0; k <= 20; ++k) {
        const double t = k / 20.0;
        EXPECT_LT(glm::distance(*geom::surface_point(s, t, 0), at(n.doc, n.bottom, t)), 1e-9);
        EXPECT_LT(glm::distance(*geom::surface_point(s, t, 1), at(n.doc, n.top, t)), 1e-9);
        EXPECT_LT(glm::distance(*geom::surface_point(s, 0, t), at(n.doc, n.left, t)), 1e-9);
        EXPECT_LT(glm::distance(*geom::surface_point(s, 1, t), at(n.doc, n.right, t)), 1e-9);
    }
    // The middle curve: somewhere at constant v the surface follows it.
    bool found = false;
    for (int j = 1; j < 200 && !found; ++j) {
        const double v = j / 200.0;
        double worst = 0;
        for (int k = 0; k <= 10; ++k)
            worst = std::max(worst, glm::distance(*geom::surface_point(s, k / 10.0, v),
                                                  at(n.doc, middle, k / 10.0)));
        found = worst < 1e-9;
    }
    EXPECT_TRUE(found) << "no isocurve of the Gordon surface is the middle curve";
}

TEST(GordonConstruction, TooFewInAFamilyIsRefusedWithTheCount) {
    Network n;
    ConstructionRequest r;
    r.kind = Construction::gordon;
    r.curves = {n.bottom, n.top, n.left, n.right};
    r.gordon_u_count = 1;
    auto built = build_construction(n.doc, r);
    ASSERT_FALSE(built.ok());
    EXPECT_EQ(built.error().path, "/gordon_u_count");
    EXPECT_NE(built.error().message.find("1 of the 4"), std::string::npos) << built.error().message;
}

} // namespace
