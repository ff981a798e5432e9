// add_objects: several objects as one undo step (File > Import); all checked before any is
// added, ids assigned after every id in use.
#include <gtest/gtest.h>

#include "core/doc/commands.hpp"
#include "tests/doc/doc_fixtures.hpp"

using namespace isoparm;
using namespace isoparm::doc;
using namespace isoparm::doc::testing;

namespace {

Object grid_object(const std::string& name, std::uint64_t id = 0) {
    Object o;
    o.id = id;
    o.name = name;
    o.shape = SurfaceObject{make_planar_grid(3, 4, 2, 3, geom::SplineType::nurbs)};
    return o;
}

TEST(AddObjects, AddsThemInOrderAsOneUndoStep) {
    Document doc = sample_document();
    const std::size_t before = doc.objects.size();
    const std::uint64_t first_id = doc.next_id;
    const Document after =
        expect_undo_redo_exact(doc, add_objects({grid_object("a"), grid_object("b")}, "Import x"));
    ASSERT_EQ(after.objects.size(), before + 2);
    EXPECT_EQ(after.objects[before].name, "a");
    EXPECT_EQ(after.objects[before].id, first_id);
    EXPECT_EQ(after.objects[before + 1].id, first_id + 1);
    EXPECT_EQ(after.next_id, first_id + 2);
}

TEST(AddObjects, FreshIdsComeAfterTheIdsTheListNames) {
    Document doc = sample_document();
    const std::uint64_t high = doc.next_id + 10;
    const Document after =
        expect_undo_redo_exact(doc, add_objects({grid_object("a"), grid_object("b", high)}));
    EXPECT_EQ(after.objects[after.objects.size() - 2].id, high + 1);
    EXPECT_EQ(after.objects.back().id, high);
    EXPECT_EQ(after.next_id, high + 2);
}

TEST(AddObjects, OneBadObjectRefusesThemAll) {
    Document doc = sample_document();
    Object bad = grid_object("bad");
    bad.shape = SurfaceObject{make_planar_grid(3, 3, 2, 2, geom::SplineType::nurbs)};
    std::get<SurfaceObject>(bad.shape).surface.knots_u[1] = 7;
    expect_refused(doc, add_objects({grid_object("ok"), bad}), geom::ErrorCode::knots,
                   "/objects/1/shape/knots/0/2");
    expect_refused(doc, add_objects({grid_object("ok"), grid_object("")}), geom::ErrorCode::schema,
                   "/objects/1/name");
    expect_refused(doc, add_objects({grid_object("a", hill_id)}), geom::ErrorCode::schema,
                   "/objects/0/id");
    expect_refused(doc, add_objects({grid_object("a", 90), grid_object("b", 90)}),
                   geom::ErrorCode::schema, "/objects/1/id");
    expect_refused(doc, add_objects({}), geom::ErrorCode::schema, "/objects");
}

TEST(AddObjects, UndoClearsASelectionOfAnAddedObject) {
    Document doc = sample_document();
    History h;
    ASSERT_TRUE(h.execute(doc, add_objects({grid_object("a"), grid_object("b")})).ok());
    doc.view.selection = Selection{doc.objects.back().id, 0, 0};
    ASSERT_TRUE(h.undo(doc));
    EXPECT_EQ(doc.view.selection.object, 0u);
}

} // namespace
