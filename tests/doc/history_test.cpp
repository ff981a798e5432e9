// The history: merged drags, sealing, labels, the clean mark and the memory bound.
#include <gtest/gtest.h>

#include "tests/doc/doc_fixtures.hpp"

using namespace isoparm;
using namespace isoparm::doc;
using namespace isoparm::doc::testing;

namespace {

// A drag of P22 of the hill through several positions.
void drag(History& h, Document& doc, int i, int j, int steps, double dz = 0.1) {
    const glm::dvec3 p0 = surface_of(doc, hill_id).point(i, j);
    for (int k = 1; k <= steps; ++k)
        ASSERT_TRUE(
            h.execute(doc, move_control_point(hill_id, i, j, p0 + glm::dvec3(0, 0, dz * k))).ok());
}

TEST(History, EmptyHistory) {
    Document doc = default_document();
    History h;
    EXPECT_FALSE(h.can_undo());
    EXPECT_FALSE(h.can_redo());
    EXPECT_FALSE(h.undo(doc));
    EXPECT_FALSE(h.redo(doc));
    EXPECT_EQ(h.undo_label(), "");
    EXPECT_EQ(h.redo_label(), "");
    EXPECT_TRUE(h.is_clean());
    EXPECT_TRUE(same_document(doc, default_document()));
}

TEST(History, ADragIsOneUndoStep) {
    Document doc = default_document();
    const Document before = doc;
    History h;
    drag(h, doc, 2, 2, 10);
    const Document after = doc;
    EXPECT_EQ(h.size(), 1u);
    EXPECT_EQ(h.undo_label(), "Move P22");
    EXPECT_DOUBLE_EQ(surface_of(doc, hill_id).point(2, 2).z, 1.6 + 1.0);
    ASSERT_TRUE(h.undo(doc));
    EXPECT_TRUE(same_document(doc, before));
    EXPECT_FALSE(h.can_undo());
    ASSERT_TRUE(h.redo(doc));
    EXPECT_TRUE(same_document(doc, after));
}

TEST(History, SealSeparatesGestures) {
    Document doc = default_document();
    History h;
    drag(h, doc, 2, 2, 3);
    const Document mid = doc;
    h.seal();
    drag(h, doc, 2, 2, 3);
    EXPECT_EQ(h.size(), 2u);
    h.undo(doc);
    EXPECT_TRUE(same_document(doc, mid));
}

TEST(History, DifferentTargetsDoNotMerge) {
    Document doc = default_document();
    History h;
    ASSERT_TRUE(h.execute(doc, move_control_point(hill_id, 2, 2, {0, 0, 1})).ok());
    ASSERT_TRUE(h.execute(doc, move_control_point(hill_id, 2, 3, {0, 0, 1})).ok());
    ASSERT_TRUE(h.execute(doc, set_weight(hill_id, 2, 3, 3)).ok());
    ASSERT_TRUE(h.execute(doc, set_weight(hill_id, 2, 3, 4)).ok()); // merges with the previous
    ASSERT_TRUE(h.execute(doc, set_weight(hill_id, 1, 3, 4)).ok());
    EXPECT_EQ(h.size(), 4u);
}

TEST(History, UndoSealsSoANewDragDoesNotMergeBelow) {
    Document doc = default_document();
    History h;
    drag(h, doc, 2, 2, 2);
    h.seal();
    drag(h, doc, 1, 1, 2);
    h.undo(doc);
    const Document mid = doc;
    drag(h, doc, 2, 2, 2); // same target as the command now on top, but a new gesture
    EXPECT_EQ(h.size(), 2u);
    h.undo(doc);
    EXPECT_TRUE(same_document(doc, mid));
}

TEST(History, ExecuteClearsRedo) {
    Document doc = default_document();
    History h;
    drag(h, doc, 2, 2, 1);
    h.undo(doc);
    EXPECT_TRUE(h.can_redo());
    EXPECT_EQ(h.redo_label(), "Move P22");
    ASSERT_TRUE(h.execute(doc, set_weight(hill_id, 0, 0, 2)).ok());
    EXPECT_FALSE(h.can_redo());
}

TEST(History, RefusedCommandChangesNothing) {
    Document doc = default_document();
    History h;
    drag(h, doc, 2, 2, 1);
    h.undo(doc);
    const auto st = h.execute(doc, set_weight(hill_id, 9, 9, 2));
    EXPECT_FALSE(st.ok());
    EXPECT_TRUE(h.can_redo()); // the failed command did not clear redo
    EXPECT_FALSE(h.can_undo());
}

TEST(History, CleanMarkAcrossUndoRedo) {
    Document doc = default_document();
    History h;
    EXPECT_TRUE(h.is_clean());
    drag(h, doc, 2, 2, 2);
    EXPECT_FALSE(h.is_clean());
    h.mark_clean(); // saved after the first drag
    EXPECT_TRUE(h.is_clean());
    h.seal();
    ASSERT_TRUE(h.execute(doc, set_weight(hill_id, 0, 0, 3)).ok());
    EXPECT_FALSE(h.is_clean());
    h.undo(doc);
    EXPECT_TRUE(h.is_clean());
    h.undo(doc);
    EXPECT_FALSE(h.is_clean());
    h.redo(doc);
    EXPECT_TRUE(h.is_clean());
    h.redo(doc);
    EXPECT_FALSE(h.is_clean());
}

TEST(History, MergingIntoTheSavedStateMakesItDirty) {
    Document doc = default_document();
    History h;
    ASSERT_TRUE(h.execute(doc, set_weight(hill_id, 0, 0, 3)).ok());
    h.mark_clean(); // mark_clean seals: the next weight edit is a new command
    ASSERT_TRUE(h.execute(doc, set_weight(hill_id, 0, 0, 4)).ok());
    EXPECT_EQ(h.size(), 2u);
    EXPECT_FALSE(h.is_clean());
    h.undo(doc);
    EXPECT_TRUE(h.is_clean());
}

TEST(History, LostCleanStateStaysDirty) {
    Document doc = default_document();
    History h;
    drag(h, doc, 2, 2, 1);
    h.mark_clean();
    h.undo(doc);
    EXPECT_FALSE(h.is_clean());
    // A new edit replaces the redo stack that held the saved state: no state is clean now.
    ASSERT_TRUE(h.execute(doc, set_weight(hill_id, 0, 0, 2)).ok());
    EXPECT_FALSE(h.is_clean());
    h.undo(doc);
    EXPECT_FALSE(h.is_clean());
}

TEST(History, CleanAtTheStartSurvivesUndoToTheBottom) {
    Document doc = default_document();
    History h;
    drag(h, doc, 2, 2, 1);
    h.seal();
    drag(h, doc, 1, 1, 1);
    h.undo(doc);
    h.undo(doc);
    EXPECT_TRUE(h.is_clean());
}

TEST(History, MemoryBoundDropsTheOldest) {
    Document doc = default_document();
    const Document start = doc;
    // Each elevation command holds the previous shape: a few hundred bytes at least.
    History h(1200);
    ASSERT_TRUE(h.execute(doc, insert_knot(hill_id, geom::Dir::u, 0.25)).ok());
    for (double t : {0.3, 0.35, 0.4, 0.45, 0.55, 0.6})
        ASSERT_TRUE(h.execute(doc, insert_knot(hill_id, geom::Dir::v, t)).ok());
    EXPECT_LT(h.size(), 7u);
    EXPECT_GE(h.size(), 1u);
    while (h.undo(doc)) {
    }
    EXPECT_FALSE(same_geometry(doc, start)); // the first steps were dropped
    EXPECT_FALSE(h.is_clean());              // the saved (initial) state is gone
}

TEST(History, MemoryBoundKeepsTheLatestCommand) {
    Document doc = default_document();
    History h(1); // smaller than any command
    ASSERT_TRUE(h.execute(doc, insert_knot(hill_id, geom::Dir::u, 0.25)).ok());
    ASSERT_TRUE(h.execute(doc, insert_knot(hill_id, geom::Dir::u, 0.75)).ok());
    EXPECT_EQ(h.size(), 1u);
    const Document after_first_undo_target = [&] {
        Document d = default_document();
        History tmp;
        (void)tmp.execute(d, insert_knot(hill_id, geom::Dir::u, 0.25));
        return d;
    }();
    ASSERT_TRUE(h.undo(doc));
    EXPECT_TRUE(same_geometry(doc, after_first_undo_target));
    EXPECT_FALSE(h.undo(doc));
}

TEST(History, CleanMarkSurvivesDroppingOlderCommands) {
    Document doc = default_document();
    History h(1); // keeps only the latest command
    ASSERT_TRUE(h.execute(doc, insert_knot(hill_id, geom::Dir::u, 0.25)).ok());
    ASSERT_TRUE(h.execute(doc, insert_knot(hill_id, geom::Dir::u, 0.75)).ok());
    h.mark_clean();
    ASSERT_TRUE(h.execute(doc, insert_knot(hill_id, geom::Dir::v, 0.75)).ok());
    EXPECT_FALSE(h.is_clean());
    h.undo(doc);
    EXPECT_TRUE(h.is_clean());
}

TEST(History, ClearKeepsTheCleanState) {
    Document doc = default_document();
    History h;
    drag(h, doc, 2, 2, 1);
    h.clear();
    EXPECT_FALSE(h.can_undo());
    EXPECT_FALSE(h.is_clean()); // the edit was never saved
    h.mark_clean();
    EXPECT_TRUE(h.is_clean());
    drag(h, doc, 2, 2, 1);
    h.undo(doc);
    h.clear();
    EXPECT_TRUE(h.is_clean());
    EXPECT_FALSE(h.can_redo());
}

} // namespace
