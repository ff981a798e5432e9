// One table per enumeration: every name reads back as its value, the names files and answers
// depend on are pinned, and labels fall back to names.
#include <gtest/gtest.h>

#include <set>
#include <string>

#include "core/doc/document.hpp"
#include "core/geom/enum_names.hpp"
#include "core/geom/interpolate.hpp"
#include "core/geom/primitives.hpp"
#include "core/geom/status.hpp"
#include "core/geom/types.hpp"

namespace isoparm {
namespace {

// Each value's name parses back to it and no two values share a name.
template <class E> void expect_round_trip() {
    std::set<std::string> seen;
    for (const geom::EnumName<E>& entry : enum_names(E{})) {
        EXPECT_EQ(geom::parse_name<E>(geom::name_of(entry.value)), entry.value) << entry.name;
        EXPECT_TRUE(seen.insert(entry.name).second) << "duplicate name " << entry.name;
    }
    EXPECT_FALSE(geom::parse_name<E>("").has_value());
    EXPECT_FALSE(geom::parse_name<E>("no such name").has_value());
}

TEST(EnumNames, EveryTableReadsBackWhatItWrites) {
    expect_round_trip<geom::SplineType>();
    expect_round_trip<geom::Dir>();
    expect_round_trip<geom::Parametrization>();
    expect_round_trip<geom::Plane>();
    expect_round_trip<geom::ErrorCode>();
    expect_round_trip<doc::CurvePlane>();
    expect_round_trip<doc::CurveKnotMode>();
    expect_round_trip<doc::ObjectKind>();
    expect_round_trip<doc::Continuity>();
    expect_round_trip<doc::DisplayStyle>();
}

TEST(EnumNames, FileNamesAreTheOnesScenesAndAnswersUse) {
    EXPECT_STREQ(geom::name_of(geom::SplineType::rational_bezier), "rational_bezier");
    EXPECT_STREQ(geom::name_of(geom::ErrorCode::unknown_op), "unknown_op");
    EXPECT_STREQ(geom::name_of(geom::Dir::v), "v");
    EXPECT_STREQ(geom::name_of(doc::CurvePlane::free3d), "free3d");
    EXPECT_STREQ(geom::name_of(doc::CurveKnotMode::clamped_uniform), "clamped_uniform");
    EXPECT_STREQ(geom::name_of(doc::ObjectKind::implicit), "implicit");
    EXPECT_STREQ(geom::name_of(doc::Continuity::c1), "C1");
    EXPECT_STREQ(geom::name_of(doc::DisplayStyle::wireframe), "wireframe");
}

TEST(EnumNames, LabelsSayItForPeopleAndFallBackToTheName) {
    EXPECT_STREQ(geom::label_of(geom::SplineType::bspline), "B-spline");
    EXPECT_STREQ(geom::label_of(doc::CurvePlane::free3d), "3D");
    EXPECT_STREQ(geom::label_of(doc::CurvePlane::xz), "xz");
    EXPECT_STREQ(geom::label_of(doc::CurveKnotMode::chord), "chord length");
    EXPECT_STREQ(geom::label_of(doc::ObjectKind::implicit), "implicit surface");
    EXPECT_STREQ(geom::label_of(geom::ErrorCode::schema), "schema");
}

TEST(EnumNames, ANumberOutsideTheEnumerationHasNoName) {
    EXPECT_STREQ(geom::name_of(static_cast<geom::Dir>(7)), "?");
    EXPECT_STREQ(geom::label_of(static_cast<doc::ObjectKind>(-1)), "?");
}

TEST(EnumNames, NamesAreCaseSensitive) {
    EXPECT_FALSE(geom::parse_name<doc::Continuity>("c0").has_value());
    EXPECT_EQ(geom::parse_name<doc::Continuity>("C0"), doc::Continuity::c0);
}

} // namespace
} // namespace isoparm
