// New objects land beside the scene, not on top of it.
#include <gtest/gtest.h>

#include "core/doc/placement.hpp"

using namespace isoparm::doc;

namespace {
Object grid_object(std::uint64_t id, bool visible = true) {
    Object o;
    o.id = id;
    o.name = "grid";
    o.visible = visible;
    o.shape = SurfaceObject{make_planar_grid(5, 5, 3, 3, isoparm::geom::SplineType::nurbs)};
    return o;
}
} // namespace

TEST(Placement, EmptySceneLeavesTheShapeWhereItIs) {
    Document doc;
    doc.objects.clear();
    Shape s = grid_object(1).shape;
    const Shape before = s;
    place_beside_scene(doc, s);
    EXPECT_EQ(std::get<SurfaceObject>(s).surface.points,
              std::get<SurfaceObject>(before).surface.points);
}

TEST(Placement, ANewGridGoesBesideTheExistingOneWithoutOverlap) {
    Document doc;
    doc.objects = {grid_object(1)};
    Shape s = grid_object(2).shape;
    place_beside_scene(doc, s);
    const Box existing = *bounds_of(doc.objects[0].shape);
    const Box placed = *bounds_of(s);
    EXPECT_GT(placed.lo.x, existing.hi.x); // beside it, in +x
    EXPECT_NEAR(placed.hi.x - placed.lo.x, existing.hi.x - existing.lo.x, 1e-12); // same size
    EXPECT_NEAR(placed.lo.y + placed.hi.y, existing.lo.y + existing.hi.y, 1e-12); // level
}

TEST(Placement, HiddenObjectsDoNotPushNewOnesAway) {
    Document doc;
    doc.objects = {grid_object(1, /*visible=*/false)};
    EXPECT_FALSE(scene_bounds(doc).has_value());
    Shape s = grid_object(2).shape;
    const Box before = *bounds_of(s);
    place_beside_scene(doc, s);
    EXPECT_EQ(bounds_of(s)->lo, before.lo);
}

TEST(Placement, ImplicitSurfacesMoveWithTheirFormula) {
    Document doc;
    doc.objects = {grid_object(1)};
    Shape s = ImplicitObject{"x^2+y^2+z^2-1", {}, {}, {-1, -1, -1}, {1, 1, 1}, 0.05};
    place_beside_scene(doc, s);
    const ImplicitObject& f = std::get<ImplicitObject>(s);
    const Box existing = *bounds_of(doc.objects[0].shape);
    EXPECT_GT(f.lo.x, existing.hi.x); // beside the grid, not on it
    EXPECT_NEAR(f.hi.x - f.lo.x, 2, 1e-12);
    // The formula moved with the box: its zero set is the unit sphere about the box's centre.
    const double dx = f.lo.x + 1, dy = f.lo.y + 1;
    EXPECT_NE(f.expression.find("(x - "), std::string::npos) << f.expression;
    EXPECT_EQ(f.expression.find("z -"), std::string::npos) << "z was not moved: " << f.expression;
    const ImplicitObject again = translated(f, {-dx, -dy, 0});
    EXPECT_NEAR(again.lo.x, -1, 1e-12);
}

TEST(Placement, TranslatedFormulasKeepFunctionNamesNumbersAndParameters) {
    const ImplicitObject f{
        "exp(x) + 1e-3*y - xa + sqrt(z)", {"xa"}, {2}, {0, 0, 0}, {1, 1, 1}, 0.1};
    const ImplicitObject g = translated(f, {2, 0.5, -1});
    EXPECT_EQ(g.expression, "exp((x - 2)) + 1e-3*(y - 0.5) - xa + sqrt((z + 1))");
    EXPECT_EQ(g.lo, glm::dvec3(2, 0.5, -1));
}

TEST(Placement, UniqueNamesCountOnFromTheTakenOne) {
    Document doc;
    doc.objects = {grid_object(1), grid_object(2)};
    doc.objects[1].name = "grid (2)";
    EXPECT_EQ(unique_name(doc, "wave"), "wave");
    EXPECT_EQ(unique_name(doc, "grid"), "grid (3)");
    EXPECT_EQ(unique_name(doc, "grid", 1), "grid"); // the object itself does not count
}
