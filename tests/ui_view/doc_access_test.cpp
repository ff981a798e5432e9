// The panels' read helpers: the current surface, a selection that still exists, point names
// and the indicator in a surface's own parameters.
#include <gtest/gtest.h>

#include "ui/view/doc_access.hpp"

namespace isoparm::ui {
namespace {

doc::Document with_curve() {
    doc::Document d = doc::default_document();
    doc::Object c;
    c.id = d.allocate_id();
    c.name = "curve";
    c.shape = doc::CurveObject{
        geom::Curve{geom::SplineType::bspline, 1, {0, 0, 1, 1}, {{0, 0, 0}, {1, 0, 0}}, {1, 1}}};
    d.objects.insert(d.objects.begin(), c);
    return d;
}

TEST(DocAccess, TheCurrentSurfaceIsTheSelectedOneElseTheFirstVisible) {
    doc::Document d = with_curve();
    const doc::Object* object = nullptr;
    d.view.selection = {d.objects[0].id, -1, -1}; // the curve
    EXPECT_EQ(current_surface(d, &object), d.objects[1].surface());
    EXPECT_EQ(object, &d.objects[1]);
    d.objects[1].visible = false;
    EXPECT_EQ(current_surface(d), nullptr);
    d.view.selection = {d.objects[1].id, -1, -1}; // selected, though hidden
    EXPECT_EQ(current_surface(d), d.objects[1].surface());
}

TEST(DocAccess, ASelectionThatNoLongerFitsIsDropped) {
    doc::Document d = with_curve();
    d.view.selection = {d.objects[0].id, 1, -1};
    EXPECT_TRUE(has_valid_point(d));
    d.view.selection.i = 2; // the curve has two points
    EXPECT_FALSE(has_valid_point(d));
    normalize_selection(d);
    EXPECT_EQ(d.view.selection, (doc::Selection{d.objects[0].id, -1, -1}));
    d.view.selection = {999, 0, 0};
    normalize_selection(d);
    EXPECT_EQ(d.view.selection, doc::Selection{});
}

TEST(DocAccess, PointNamesAsThePaperWritesThem) {
    EXPECT_EQ(point_name('P', 2, 2, 5, 5), "P22");
    EXPECT_EQ(point_name('w', 26, 11, 30, 12), "w26,11");
    EXPECT_EQ(point_name('P', 3, -1, 0, 0), "P3");
}

TEST(DocAccess, TheIndicatorInTheSurfacesOwnDomainAndBack) {
    doc::Document d = doc::default_document();
    d.view.indicator = {0.25, 0.75};
    const doc::Object& o = d.objects[0];
    EXPECT_EQ(indicator_params(d, o), glm::dvec2(0.25, 0.75)); // the hill's domain is [0, 1]^2
    const glm::dvec2 own = indicator_in_own_domain(d, o);
    EXPECT_EQ(own, glm::dvec2(0.25, 0.75));
    EXPECT_EQ(indicator_from_own_domain(d, o, own), d.view.indicator);
}

} // namespace
} // namespace isoparm::ui
