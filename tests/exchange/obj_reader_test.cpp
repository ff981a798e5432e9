// OBJ free-form import (core/exchange/obj_reader.hpp): good files read exactly, each error
// names its line and value (the scene's round trip is tests/scene/obj_import_test.cpp).
#include <gtest/gtest.h>

#include "core/exchange/obj_reader.hpp"

using namespace isoparm;
using exchange::read_obj_freeform;

namespace {

const char* const curve_file = R"(# a quadratic rational curve
o arc
v 1 0 0 1
v 1 1 0 0.5
v 0 1 0
cstype rat bspline
deg 2
curv 0 1 1 2 -1
parm u 0 0 0 1 1 1
end
)";

TEST(ObjReader, ReadsARationalCurveWithItsNameAndWeights) {
    const auto r = read_obj_freeform(curve_file);
    ASSERT_TRUE(r) << r.error().message;
    ASSERT_EQ(r->objects.size(), 1u);
    EXPECT_EQ(r->objects[0].name, "arc");
    const auto& c = std::get<geom::Curve>(r->objects[0].shape);
    EXPECT_EQ(c.type, geom::SplineType::nurbs);
    EXPECT_EQ(c.degree, 2);
    EXPECT_EQ(c.knots, (geom::Knots{0, 0, 0, 1, 1, 1}));
    ASSERT_EQ(c.count(), 3);
    EXPECT_EQ(c.points[1], glm::dvec3(1, 1, 0));
    EXPECT_EQ(c.weights, (std::vector<double>{1, 0.5, 1}));
    EXPECT_TRUE(r->skipped.empty());
}

TEST(ObjReader, ReadsASurfaceWithUFastestVerticesContinuationsAndSkips) {
    const char* text = "g patch\n"
                       "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 1 7\n"
                       "cstype bspline\r\n"
                       "deg 1 1\n"
                       "surf 0 1 0 2 1/1 2 \\\n 3/3/3 4\n"
                       "parm u 0 0 1 1\nparm v 0 0 2 2\n"
                       "trim 0 1 1\n"
                       "end\n"
                       "f 1 2 3\nf 2 3 4\n";
    const auto r = read_obj_freeform(text);
    ASSERT_TRUE(r) << r.error().message;
    ASSERT_EQ(r->objects.size(), 1u);
    EXPECT_EQ(r->objects[0].name, "patch");
    const auto& s = std::get<geom::Surface>(r->objects[0].shape);
    EXPECT_EQ(s.type, geom::SplineType::bspline);
    EXPECT_EQ(s.n_u, 2);
    EXPECT_EQ(s.n_v, 2);
    EXPECT_EQ(s.point(1, 0), glm::dvec3(1, 0, 0)); // u varies fastest in the file
    EXPECT_EQ(s.point(0, 1), glm::dvec3(0, 1, 0));
    EXPECT_EQ(s.weight(1, 1), 1.0); // a non-rational cstype ignores the weight
    ASSERT_EQ(r->skipped.size(), 2u);
    EXPECT_NE(r->skipped[0].entity.find("trim (line 12)"), std::string::npos);
    EXPECT_NE(r->skipped[1].entity.find("2 'f' statements (first at line 14)"), std::string::npos);
}

TEST(ObjReader, SkipsOtherTypesAndTrimmedRanges) {
    const char* text = "v 0 0 0\nv 1 0 0\nv 2 1 0\n"
                       "cstype bezier\ndeg 2\ncurv 0 1 1 2 3\nparm u 0 1\nend\n"
                       "cstype bspline\ncurv 0 0.5 1 2 3\nparm u 0 0 0 1 1 1\nend\n";
    const auto r = read_obj_freeform(text);
    ASSERT_TRUE(r) << r.error().message;
    EXPECT_TRUE(r->objects.empty());
    ASSERT_EQ(r->skipped.size(), 2u);
    EXPECT_EQ(r->skipped[0].entity, "line 6: curv (cstype bezier)");
    EXPECT_NE(r->skipped[1].reason.find("[0, 0.5]"), std::string::npos);
}

struct BadFile {
    bool after_head; // after five lines of vertices, cstype bspline and deg 2
    const char* text;
    geom::ErrorCode code;
    const char* message; // must appear in the error
};

TEST(ObjReader, EachErrorNamesItsLineAndValue) {
    const std::string head = "v 0 0 0\nv 1 0 0\nv 2 1 0\ncstype bspline\ndeg 2\n";
    const BadFile cases[] = {
        {false, "v 1 2 x\n", geom::ErrorCode::parse, "line 1: z 'x' is not a finite number"},
        {false, "v 1 2\n", geom::ErrorCode::parse, "line 1: v takes x y z"},
        {false, "v 1 2 3 nan\n", geom::ErrorCode::parse, "line 1: weight 'nan' is not a finite"},
        {false, "cstype spline\n", geom::ErrorCode::parse, "line 1: cstype 'spline' is not"},
        {false, "deg 0\n", geom::ErrorCode::degree, "line 1: degree 0 is not in 1..64"},
        {false, "vertex 1 2 3\n", geom::ErrorCode::parse,
         "line 1: 'vertex' is not an OBJ statement"},
        {false, "v 0 0 0\ncurv 0 1 1\n", geom::ErrorCode::parse,
         "line 2: curv comes before any cstype"},
        {false, "parm u 0 1\n", geom::ErrorCode::parse, "line 1: parm outside a curv or surf"},
        {false, "end\n", geom::ErrorCode::parse, "line 1: end without a curv or surf"},
        {true, "curv 0 1 1 2 4\n", geom::ErrorCode::parse,
         "line 6: control vertex '4' names no vertex"},
        {true, "curv 0 1 1 2 0\n", geom::ErrorCode::parse,
         "line 6: control vertex '0' names no vertex"},
        {true, "curv 0 1 1 2 -4\n", geom::ErrorCode::parse, "control vertex '-4' names no vertex"},
        {true, "curv 0 1 1 2 a\n", geom::ErrorCode::parse,
         "line 6: control vertex 'a' is not a vertex"},
        {true, "curv 0 1 1 2 3\nend\n", geom::ErrorCode::parse,
         "line 7: curv of line 6 has no 'parm u'"},
        {true, "curv 0 1 1 2 3\nparm u 0 0 1 1\nend\n", geom::ErrorCode::knots,
         "line 6: curv of line 6: parm u has 4 knots; 3 control vertices of degree 2 need 6"},
        {true, "curv 0 1 1 2 3\nparm u 0 0 0 1 0.5 1\nend\n", geom::ErrorCode::knots,
         "line 6: curv"},
        {true, "curv 0 1 1 2 3\nparm u 0 0 0 1 1 1\n", geom::ErrorCode::parse,
         "line 6: curv has no 'end' before the file ends"},
        {true, "curv 0 1 1 2 3\ncurv 0 1 1 2 3\n", geom::ErrorCode::parse,
         "line 7: curv begins before the curv of line 6 has its 'end'"},
        {true, "surf 0 1 0 1 1 2 3\n", geom::ErrorCode::parse, "line 6: surf needs 'deg' with two"},
        {true, "curv 0 1 1 2 3\nparm v 0 1\n", geom::ErrorCode::parse,
         "line 7: a curve has no parm v"},
        {true, "curv 0 1 1 2 3\nparm u 0 0 0 1 1 1\nparm u 0 1\n", geom::ErrorCode::parse,
         "line 8: a second parm u"},
        {true, "curv 0 x 1 2 3\n", geom::ErrorCode::parse, "line 6: u1 'x' is not a finite number"},
        {true, "deg 1 1\nsurf 0 1 0 1 1 2 3\nparm u 0 0 1 1\nparm v 0 0 1 1\nend\n",
         geom::ErrorCode::knots,
         "line 7: surf of line 7 lists 3 control vertices; its knots "
         "ask for 2 x 2 = 4"},
    };
    for (const BadFile& c : cases) {
        const std::string text = c.after_head ? head + c.text : std::string(c.text);
        const auto r = read_obj_freeform(text);
        ASSERT_FALSE(r) << text;
        EXPECT_EQ(r.error().code, c.code) << text << "\n" << r.error().message;
        EXPECT_NE(r.error().message.find(c.message), std::string::npos)
            << text << "\ngot: " << r.error().message << "\nwanted: " << c.message;
    }
}

TEST(ObjReader, NegativeIndicesCountBackAndContinuationLinesKeepTheFirstLineNumber) {
    const char* text = "v 0 0 0\nv 1 0 0\nv 2 1 0\ncstype bspline\ndeg 2\n"
                       "curv 0 1 -3 \\\n -2 \\\n -1\nparm u 0 0 0 1 1 1\nend\n"
                       "curv 0 1 1 2 \\\n 9\n";
    const auto r = read_obj_freeform(text);
    ASSERT_FALSE(r);
    EXPECT_NE(r.error().message.find("line 11: control vertex '9'"), std::string::npos)
        << r.error().message;
}

// The reader keeps a vertex as where its statement starts and reads it again when an element
// names it: a vertex continued over lines, one after its element, one never named.
TEST(ObjReader, VerticesAreReadAgainFromTheTextWhenAnElementNamesThem) {
    const auto r = read_obj_freeform("v 9 9 9\nv 1 \\\n 2 3\nv 4 5 6 # a comment\n"
                                     "cstype bspline\ndeg 1\ncurv 0 1 2 -1\nparm u 0 0 1 1\nend\n"
                                     "v 7 8 9\n");
    ASSERT_TRUE(r) << r.error().message;
    ASSERT_EQ(r->objects.size(), 1u);
    const auto& c = std::get<geom::Curve>(r->objects[0].shape);
    EXPECT_EQ(c.points, (std::vector<glm::dvec3>{{1, 2, 3}, {4, 5, 6}}));
}

// One import takes at most max_import_control_points: a file naming the same vertices over and
// over is stopped while it is read, at the element that passes the budget.
TEST(ObjReader, AnImportHasABudgetOfControlPoints) {
    // Surfaces of 1000 x 1000 control points (the most one surface has) on four vertices: the
    // fifth passes the budget of 4,000,000.
    std::string text = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 1\ncstype bspline\ndeg 1 1\n";
    constexpr int n = 1000;
    std::string element = "surf 0 1 0 1";
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) element += (i + j) % 2 ? " 2" : " 1";
    std::string knots = "0";
    for (int k = 0; k < n; ++k) knots += " " + std::to_string(k);
    knots += " " + std::to_string(n - 1);
    for (int k = 0; k < 5; ++k)
        text += element + "\nparm u " + knots + "\nparm v " + knots + "\nend\n";
    const auto r = read_obj_freeform(text);
    ASSERT_FALSE(r);
    EXPECT_EQ(r.error().code, geom::ErrorCode::limit);
    EXPECT_NE(r.error().message.find("line 23: the file's curves and surfaces have more than "
                                     "4000000 control points"),
              std::string::npos)
        << r.error().message;
}

} // namespace
