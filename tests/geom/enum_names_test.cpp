// One table per enumeration: every name reads back as its value, the names files and answers
// depend on are pinned, labels fall back to names, and refusals list the table's names (the
// document's enumerations: tests/doc/enum_names_test.cpp).
#include <gtest/gtest.h>

#include <string>

#include "core/geom/enum_names.hpp"
#include "core/geom/interpolate.hpp"
#include "core/geom/primitives.hpp"
#include "core/geom/status.hpp"
#include "core/geom/types.hpp"
#include "tests/support/enum_round_trip.hpp"

namespace isoparm {
namespace {

using test::expect_round_trip;

TEST(EnumNames, EveryTableReadsBackWhatItWrites) {
    expect_round_trip<geom::SplineType>();
    expect_round_trip<geom::Dir>();
    expect_round_trip<geom::Parametrization>();
    expect_round_trip<geom::Plane>();
    expect_round_trip<geom::ErrorCode>();
}

TEST(EnumNames, FileNamesAreTheOnesScenesAndAnswersUse) {
    EXPECT_STREQ(geom::name_of(geom::SplineType::rational_bezier), "rational_bezier");
    EXPECT_STREQ(geom::name_of(geom::ErrorCode::unknown_op), "unknown_op");
    EXPECT_STREQ(geom::name_of(geom::Dir::v), "v");
}

TEST(EnumNames, LabelsSayItForPeopleAndFallBackToTheName) {
    EXPECT_STREQ(geom::label_of(geom::SplineType::bspline), "B-spline");
    EXPECT_STREQ(geom::label_of(geom::ErrorCode::schema), "schema");
}

TEST(EnumNames, ANumberOutsideTheEnumerationHasNoName) {
    EXPECT_STREQ(geom::name_of(static_cast<geom::Dir>(7)), "?");
    EXPECT_STREQ(geom::label_of(static_cast<geom::SplineType>(-1)), "?");
}

TEST(EnumNames, NamesAreCaseSensitive) {
    EXPECT_FALSE(geom::parse_name<geom::SplineType>("NURBS").has_value());
    EXPECT_EQ(geom::parse_name<geom::SplineType>("nurbs"), geom::SplineType::nurbs);
}

// Refusals list what a table accepts, from the table: "a, b or c", or "a, b, c".
TEST(EnumNames, RefusalsListTheTablesNames) {
    EXPECT_EQ(geom::names_list<geom::SplineType>(", "), "bezier, rational_bezier, bspline, nurbs");
    EXPECT_EQ(geom::names_list<geom::Dir>(), "u or v");
    EXPECT_EQ(geom::names_list<geom::Plane>(), "xy, xz or yz");
}

} // namespace
} // namespace isoparm
