// The current subpatch follows the indicator over the group's domain, and a patch picked
// otherwise takes the indicator along.
#include <gtest/gtest.h>

#include <tuple>

#include "core/doc/commands.hpp"
#include "ui/view/current_patch.hpp"

namespace isoparm::ui {
namespace {

using doc::Selection;

// The paper's example on the default hill: split at u = 0.75, then the left part at v = 0.5.
struct PaperSplit {
    doc::Document doc = doc::default_document();
    doc::History history;
    std::uint64_t left = 0, right = 0, left_low = 0, left_high = 0;

    std::pair<std::uint64_t, std::uint64_t> split(std::uint64_t id, geom::Dir dir, double t) {
        auto cmd = doc::split_object(id, dir, t);
        const doc::Command* raw = cmd.get();
        EXPECT_TRUE(history.execute(doc, std::move(cmd)));
        return doc::split_piece_ids(*raw);
    }
    PaperSplit() {
        std::tie(left, right) = split(doc.objects[0].id, geom::Dir::u, 0.75);
        std::tie(left_low, left_high) = split(left, geom::Dir::v, 0.5);
    }
};

TEST(CurrentPatch, TheIndicatorPicksThePatchUnderIt) {
    PaperSplit p;
    // The indicator is normalized over the group's domain.
    p.doc.view.indicator = {0.9, 0.6};
    EXPECT_EQ(patch_for_indicator(p.doc, p.left_low), p.right);
    p.doc.view.indicator = {0.1, 0.6};
    EXPECT_EQ(patch_for_indicator(p.doc, p.right), p.left_high);
    p.doc.view.indicator = {0.1, 0.4};
    EXPECT_EQ(patch_for_indicator(p.doc, p.left_low), p.left_low);

    // Following the indicator changes the selection (its point is dropped), once.
    p.doc.view.selection = {p.left_low, 1, 1};
    p.doc.view.indicator = {0.95, 0.95};
    EXPECT_TRUE(follow_indicator(p.doc, p.left_low));
    EXPECT_EQ(p.doc.view.selection, (Selection{p.right, -1, -1}));
    EXPECT_FALSE(follow_indicator(p.doc, p.right));
}

TEST(CurrentPatch, IndicatorAndCurrentPatchStayInStep) {
    PaperSplit p;
    // The indicator moved into the right part: that patch becomes current.
    p.doc.view.selection = {p.left_low, 2, 2};
    const glm::dvec2 before = p.doc.view.indicator;
    p.doc.view.indicator = {0.9, 0.3};
    EXPECT_EQ(sync_patch_and_indicator(p.doc, p.left_low, before, p.left_low), p.right);
    EXPECT_EQ(p.doc.view.selection, (Selection{p.right, -1, -1}));
    // A patch picked otherwise (the 3D view) takes the indicator along, to its nearest point.
    const glm::dvec2 still = p.doc.view.indicator;
    p.doc.view.selection = {p.left_high, -1, -1};
    EXPECT_EQ(sync_patch_and_indicator(p.doc, p.left_high, still, p.right), p.left_high);
    EXPECT_DOUBLE_EQ(p.doc.view.indicator.x, 0.75); // the right edge of the left part
    EXPECT_DOUBLE_EQ(p.doc.view.indicator.y, 0.5);  // the bottom edge of the upper part
    // Nothing moved and nothing else picked: nothing changes.
    const doc::Document same = p.doc;
    EXPECT_EQ(sync_patch_and_indicator(p.doc, p.left_high, p.doc.view.indicator, p.left_high),
              p.left_high);
    EXPECT_TRUE(doc::same_document(p.doc, same));
}

} // namespace
} // namespace isoparm::ui
