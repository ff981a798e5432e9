// Dragging a knot of multiplicity > 1 in the tracing panel: all its copies move as one run.
#include <gtest/gtest.h>

#include "tests/doc/doc_fixtures.hpp"

using namespace isoparm;
using namespace isoparm::doc;
using namespace isoparm::doc::testing;
using geom::Dir;
using geom::ErrorCode;

namespace {

TEST(MoveKnotRun, DoubleKnotMovesTogetherAndUndoesExactly) {
    Document doc = sample_document();
    const std::uint64_t curve_id = doc.objects[1].id; // knots 0^4 0.25 0.5^2 1^4
    const Document after = expect_undo_redo_exact(doc, move_knot_run(curve_id, Dir::u, 5, 2, 0.6));
    const geom::Knots& U = std::get<CurveObject>(after.objects[1].shape).curve.knots;
    EXPECT_EQ(U[5], 0.6);
    EXPECT_EQ(U[6], 0.6);
    EXPECT_EQ(U[4], 0.25);
}

TEST(MoveKnotRun, DragStepsMergeIntoOneUndoStep) {
    Document doc = sample_document();
    const Document before = doc;
    const std::uint64_t curve_id = doc.objects[1].id;
    History h;
    for (double t : {0.45, 0.4, 0.35})
        ASSERT_TRUE(h.execute(doc, move_knot_run(curve_id, Dir::u, 5, 2, t)).ok());
    EXPECT_EQ(h.size(), 1u);
    EXPECT_EQ(h.undo_label(), "Set knot t5 = 0.35 (2 copies)");
    h.undo(doc);
    EXPECT_TRUE(same_geometry(doc, before));
}

TEST(MoveKnotRun, RefusalsNameTheValue) {
    Document doc = sample_document();
    const Document before = doc;
    const std::uint64_t curve_id = doc.objects[1].id;
    History h;
    // Past the neighbour 0.25 below the run.
    auto r = h.execute(doc, move_knot_run(curve_id, Dir::u, 5, 2, 0.2));
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.error().code, ErrorCode::knots);
    EXPECT_EQ(r.error().path, "/value");
    EXPECT_NE(r.error().message.find("[0.25, 1]"), std::string::npos) << r.error().message;
    // Indices 4 and 5 hold different knots: not one run.
    r = h.execute(doc, move_knot_run(curve_id, Dir::u, 4, 2, 0.3));
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.error().path, "/count");
    // A clamped end run cannot move.
    r = h.execute(doc, move_knot_run(curve_id, Dir::u, 7, 4, 0.9));
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.error().code, ErrorCode::knots);
    EXPECT_TRUE(same_geometry(doc, before));
}

} // namespace
