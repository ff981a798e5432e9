// Data points from CSV and XYZ text: curves, grids, headers and comments, and errors that name
// the line and the value.
#include <gtest/gtest.h>

#include "core/scene/point_file.hpp"

using namespace isoparm;
using scene::points_from_text;

namespace {

std::string message_of(std::string_view text) {
    auto r = points_from_text(text);
    EXPECT_FALSE(r.ok()) << text;
    return r.ok() ? std::string() : r.error().message;
}

TEST(PointFile, CsvWithAHeaderAndXyzWithComments) {
    auto csv = points_from_text("x,y,z\n0,0,0\n1, 2, 3\r\n-1.5e0;4;+2\n");
    ASSERT_TRUE(csv.ok()) << csv.error().message;
    EXPECT_FALSE(csv->grid());
    ASSERT_EQ(csv->points.size(), 3u);
    EXPECT_EQ(csv->points[1], glm::dvec3(1, 2, 3));
    EXPECT_EQ(csv->points[2], glm::dvec3(-1.5, 4, 2));
    auto xy = points_from_text("# two numbers a line: z = 0\n0 0\n1\t1 # a comment\n\n\n");
    ASSERT_TRUE(xy.ok()) << xy.error().message;
    EXPECT_EQ(xy->points.size(), 2u);
    EXPECT_EQ(xy->rows, 1);
    EXPECT_EQ(xy->points[1], glm::dvec3(1, 1, 0));
}

TEST(PointFile, BlankLinesSeparateTheRowsOfAGrid) {
    auto g =
        points_from_text("0 0 0\n0 1 0\n0 2 1\n\n1 0 0\n1 1 2\n1 2 0\n\n2 0 0\n2 1 0\n2 2 0\n");
    ASSERT_TRUE(g.ok()) << g.error().message;
    EXPECT_TRUE(g->grid());
    EXPECT_EQ(g->rows, 3);
    EXPECT_EQ(g->columns, 3);
    EXPECT_EQ(g->points[4], glm::dvec3(1, 1, 2));
    // A comment line does not end a row.
    auto c = points_from_text("0 0\n# middle\n1 0\n\n0 1\n1 1\n");
    ASSERT_TRUE(c.ok());
    EXPECT_EQ(c->rows, 2);
    EXPECT_EQ(c->columns, 2);
}

TEST(PointFile, ErrorsNameTheLineAndTheValue) {
    EXPECT_EQ(message_of("0 0 0\n1 x 2\n"), "line 2: 'x' is not a number");
    EXPECT_EQ(message_of("0 0 0\n1 2\n"), "line 2: 2 numbers, but line 1 has 3");
    EXPECT_EQ(message_of("1 2 3 4\n"), "line 1: 4 numbers; a point is 2 (x y) or 3 (x y z)");
    EXPECT_EQ(message_of("0 0\n1 nan\n"), "line 2: 'nan' is not a finite number");
    EXPECT_EQ(message_of("0 0\n1e999 1\n"), "line 2: '1e999' is not a number");
    EXPECT_NE(message_of("# nothing\n\n").find("no points"), std::string::npos);
    EXPECT_NE(message_of("0 0\n1 0\n\n0 1\n").find("grid row 2 has 1 points, row 1 has 2"),
              std::string::npos);
    EXPECT_NE(message_of("0 0\n1 0\n\n0 1\n1 1\n2 1\n").find("line 6: grid row 2 is longer"),
              std::string::npos);
    // A header only on the first line: text later is an error.
    EXPECT_EQ(message_of("x y\n0 0\nx y\n"), "line 3: 'x' is not a number");
}

TEST(PointFile, AMissingFileIsAnErrorNamingIt) {
    auto r = scene::load_points("/nonexistent/points.csv");
    ASSERT_FALSE(r.ok());
    EXPECT_NE(r.error().message.find("/nonexistent/points.csv"), std::string::npos);
}

} // namespace
