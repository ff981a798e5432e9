// The field readers' wording of numbers (the same wording across requests, geometry and scenes
// is tests/integration/shared_wording_test.cpp).
#include <gtest/gtest.h>

#include <string>

#include "core/json/fields.hpp"
#include "core/json/shapes.hpp"

namespace {

using nlohmann::json;
using namespace isoparm;

TEST(JsonFields, NumbersAreRefusedWithTheirTypeOrValue) {
    auto text = json_io::read_finite(json("3"), "/x", "x");
    ASSERT_FALSE(text);
    EXPECT_EQ(text.error().message, "x must be a number, got a string");
    auto inf = json_io::read_finite(json(1e308 * 10), "/x", "x");
    ASSERT_FALSE(inf);
    EXPECT_EQ(inf.error().message, "x must be a finite number, got inf");
    auto half = json_io::read_integer(json(2.5), "/n", "n", 1, 9);
    ASSERT_FALSE(half);
    EXPECT_EQ(half.error().message, "n must be an integer, got 2.5");
    auto big = json_io::read_integer(json(12), "/n", "n", 1, 9);
    ASSERT_FALSE(big);
    EXPECT_EQ(big.error().message, "n must be between 1 and 9, got 12");
    EXPECT_EQ(json_io::member_path("/a", "b/c~"), "/a/b~1c~0");
}

} // namespace
