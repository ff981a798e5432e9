// The document's facts: each holds when it is made, and an edit that changes what it says
// makes it fail (so an author's pick is a real check).
#include <gtest/gtest.h>

#include "core/doc/commands.hpp"
#include "core/scene/facts.hpp"

using namespace isoparm;

namespace {

const scene::Fact* find(const std::vector<scene::Fact>& facts, const std::string& words) {
    for (const scene::Fact& f : facts)
        if (f.text.find(words) != std::string::npos) return &f;
    return nullptr;
}

TEST(Facts, EveryFactHoldsAndNamesWhatItChecks) {
    doc::Document d = doc::default_document(); // P2,2 of 'hill' selected, weight 2
    d.view.indicator = {0.25, 0.75};
    const std::vector<scene::Fact> facts = scene::document_facts(d);
    for (const scene::Fact& f : facts)
        EXPECT_TRUE(scene::unmet_expectations(f.expect, d).empty()) << f.text;
    for (const char* words :
         {"the scene holds 1 object", "'hill' is a NURBS", "'hill' has degree 3 in u",
          "'hill' has degree 3 in v", "'hill''s knots in u are [0, 0, 0, 0, 0.5, 1, 1, 1, 1]",
          "P2,2 of 'hill' is at (0, 0, 1.6)", "the weight of P2,2 of 'hill' is 2",
          "S(0.25, 0.75) = (", "sum to 1 at (u, v) = (0.25, 0.75)",
          "R2,2 = ", "Gaussian curvature"})
        EXPECT_NE(find(facts, words), nullptr) << words;
}

TEST(Facts, AnEditMakesTheFactAboutItFail) {
    doc::Document d = doc::default_document();
    const std::vector<scene::Fact> facts = scene::document_facts(d);
    const scene::Fact* weight = find(facts, "the weight of P2,2");
    const scene::Fact* point = find(facts, "S(0.5, 0.5)");
    ASSERT_TRUE(weight && point);
    doc::History h;
    ASSERT_TRUE(h.execute(d, doc::edit_point({1, 2, 2, std::nullopt, 0.3})).ok());
    EXPECT_FALSE(scene::unmet_expectations(weight->expect, d).empty());
    EXPECT_FALSE(scene::unmet_expectations(point->expect, d).empty());
    const scene::Fact* unity = find(facts, "sum to 1");
    ASSERT_TRUE(unity);
    EXPECT_TRUE(scene::unmet_expectations(unity->expect, d).empty()); // always
}

TEST(Facts, ASplitGroupsBordersAreAFact) {
    doc::Document d = doc::default_document();
    d.continuity = doc::Continuity::c1;
    doc::History h;
    ASSERT_TRUE(h.execute(d, doc::split_object(1, geom::Dir::u, 0.75)).ok());
    const std::vector<scene::Fact> facts = scene::document_facts(d);
    const scene::Fact* borders = find(facts, "the borders of patch group");
    ASSERT_NE(borders, nullptr);
    EXPECT_NE(borders->text.find("C1"), std::string::npos) << borders->text;
    EXPECT_TRUE(scene::unmet_expectations(borders->expect, d).empty());
}

} // namespace
