// The document's enumeration tables: names read back, the names scenes use are pinned, labels
// say it for people, and the refusals of scene files list the tables' names.
#include <gtest/gtest.h>

#include "core/doc/border_measure.hpp"
#include "core/doc/document.hpp"
#include "tests/support/enum_round_trip.hpp"

namespace isoparm {
namespace {

using test::expect_round_trip;

TEST(DocEnumNames, EveryTableReadsBackWhatItWrites) {
    expect_round_trip<doc::CurvePlane>();
    expect_round_trip<doc::CurveKnotMode>();
    expect_round_trip<doc::ObjectKind>();
    expect_round_trip<doc::Continuity>();
    expect_round_trip<doc::DisplayStyle>();
    expect_round_trip<doc::AnalysisMode>();
    expect_round_trip<doc::BorderLevel>();
}

TEST(DocEnumNames, FileNamesAreTheOnesScenesUse) {
    EXPECT_STREQ(geom::name_of(doc::CurvePlane::free3d), "free3d");
    EXPECT_STREQ(geom::name_of(doc::CurveKnotMode::clamped_uniform), "clamped_uniform");
    EXPECT_STREQ(geom::name_of(doc::ObjectKind::implicit), "implicit");
    EXPECT_STREQ(geom::name_of(doc::Continuity::c1), "C1");
    EXPECT_STREQ(geom::name_of(doc::DisplayStyle::wireframe), "wireframe");
}

TEST(DocEnumNames, LabelsSayItForPeople) {
    EXPECT_STREQ(geom::label_of(doc::CurvePlane::free3d), "3D");
    EXPECT_STREQ(geom::label_of(doc::CurvePlane::xz), "xz");
    EXPECT_STREQ(geom::label_of(doc::CurveKnotMode::chord), "chord length");
    EXPECT_STREQ(geom::label_of(doc::ObjectKind::implicit), "implicit surface");
    EXPECT_STREQ(doc::border_level_name(doc::BorderLevel::g2), "C1 + G2");
    EXPECT_STREQ(doc::border_level_name(doc::BorderLevel::broken), "broken");
    EXPECT_STREQ(geom::label_of(static_cast<doc::ObjectKind>(-1)), "?");
}

TEST(DocEnumNames, NamesAreCaseSensitive) {
    EXPECT_FALSE(geom::parse_name<doc::Continuity>("c0").has_value());
    EXPECT_EQ(geom::parse_name<doc::Continuity>("C0"), doc::Continuity::c0);
}

TEST(DocEnumNames, RefusalsListTheTablesNames) {
    EXPECT_EQ(geom::names_list<doc::ObjectKind>(), "surface, curve, implicit or triangle");
    EXPECT_EQ(geom::names_list<doc::CurvePlane>(), "xy, xz, yz or free3d");
    EXPECT_EQ(geom::names_list<doc::Continuity>(), "off, C0 or C1");
}

} // namespace
} // namespace isoparm
