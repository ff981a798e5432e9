// The STEP AP214 writer: a well-formed Part 21 file (every reference defined, complex instances
// in alphabetical order), the numbers read back exactly, the face topology of open, closed and
// polar surfaces, and the positive-weight rule. OCCT reading the files back is
// tests/exchange_occt (built where OCCT is installed).
#include <gtest/gtest.h>

#include <cctype>
#include <map>
#include <set>
#include <sstream>
#include <string>

#include "core/exchange/step_writer.hpp"
#include "core/geom/construct.hpp"
#include "core/geom/primitives.hpp"
#include "tests/support/random_geometry.hpp"

namespace {

using namespace isoparm;

// The DATA section as id -> record ("#12=RECORD;" lines; no std::regex, whose libstdc++
// code trips GCC's -Wmaybe-uninitialized under the sanitizers).
std::map<int, std::string> instances(const std::string& text) {
    std::map<int, std::string> out;
    std::istringstream in(text.substr(text.find("DATA;")));
    for (std::string l; std::getline(in, l);) {
        const auto eq = l.find('=');
        if (l.size() < 4 || l[0] != '#' || eq == std::string::npos || l.back() != ';') continue;
        out[std::stoi(l.substr(1, eq - 1))] = l.substr(eq + 1, l.size() - eq - 2);
    }
    return out;
}

// The instance references "#n" in a record, in order.
std::vector<int> references(const std::string& record) {
    std::vector<int> out;
    for (std::size_t k = 0; k < record.size(); ++k) {
        if (record[k] != '#' || k + 1 >= record.size() || !std::isdigit(record[k + 1])) continue;
        std::size_t end = k + 1;
        while (end < record.size() && std::isdigit(record[end])) ++end;
        out.push_back(std::stoi(record.substr(k + 1, end - k - 1)));
        k = end - 1;
    }
    return out;
}

int count_of(const std::map<int, std::string>& data, const std::string& prefix) {
    int n = 0;
    for (const auto& [id, record] : data) n += record.rfind(prefix, 0) == 0;
    return n;
}

void expect_well_formed(const std::string& text) {
    EXPECT_EQ(text.rfind("ISO-10303-21;\nHEADER;\n", 0), 0u);
    EXPECT_NE(text.find("FILE_SCHEMA(('AUTOMOTIVE_DESIGN { 1 0 10303 214 1 1 1 1 }'));"),
              std::string::npos);
    EXPECT_EQ(text.substr(text.size() - 26), "ENDSEC;\nEND-ISO-10303-21;\n");
    const auto data = instances(text);
    ASSERT_FALSE(data.empty());
    EXPECT_EQ(data.rbegin()->first, static_cast<int>(data.size())); // #1 .. #n, none missing
    for (const auto& [id, record] : data)
        for (int r : references(record)) EXPECT_TRUE(data.count(r)) << "#" << id << " " << record;
    EXPECT_EQ(count_of(data, "SHAPE_DEFINITION_REPRESENTATION("), 1);
    EXPECT_EQ(count_of(data, "PRODUCT("), 1);
}

geom::Surface bilinear() {
    geom::Surface s;
    s.type = geom::SplineType::bspline;
    s.degree_u = s.degree_v = 1;
    s.n_u = s.n_v = 2;
    s.knots_u = s.knots_v = {0, 0, 1, 1};
    s.points = {{0, 0, 0}, {0, 1, 0}, {1, 0, 0}, {1, 1, 0.5}};
    s.weights.assign(4, 1.0);
    return s;
}

TEST(StepWriter, APolynomialSurfaceIsAnAdvancedFaceWithFourEdges) {
    isoparm::testing::RandomGeometry random(7);
    const geom::Surface s = random.surface(3, 2, 5, 4, false);
    const auto text = exchange::step_text({s}, "patch");
    ASSERT_TRUE(text) << text.error().message;
    expect_well_formed(*text);
    const auto data = instances(*text);
    EXPECT_EQ(count_of(data, "B_SPLINE_SURFACE_WITH_KNOTS('',3,2,"), 1);
    EXPECT_EQ(count_of(data, "ADVANCED_FACE("), 1);
    EXPECT_EQ(count_of(data, "OPEN_SHELL("), 1);
    EXPECT_EQ(count_of(data, "SHELL_BASED_SURFACE_MODEL("), 1);
    EXPECT_EQ(count_of(data, "MANIFOLD_SURFACE_SHAPE_REPRESENTATION("), 1);
    EXPECT_EQ(count_of(data, "EDGE_CURVE("), 4);
    EXPECT_EQ(count_of(data, "VERTEX_POINT("), 4);
    EXPECT_EQ(count_of(data, "EDGE_LOOP("), 1);
    // 20 control points, 4 + 4 + 4 + 5 + 5 side points, 4 vertices, the origin, and the two
    // (u, v) ends of each side's p-curve.
    EXPECT_EQ(count_of(data, "CARTESIAN_POINT("), 20 + 18 + 4 + 1 + 8);
    // Each side carries its (u, v) line, so that a reader need not project it onto the surface
    // (OCCT spent a quarter of reading a big file doing so).
    EXPECT_EQ(count_of(data, "SURFACE_CURVE("), 4);
    EXPECT_EQ(count_of(data, "PCURVE("), 4);
    for (const auto& [id, record] : data) {
        if (record.rfind("EDGE_CURVE(", 0) == 0) {
            EXPECT_EQ(data.at(references(record)[2]).rfind("SURFACE_CURVE(", 0), 0u) << record;
        }
        if (record.rfind("SURFACE_CURVE(", 0) != 0) continue;
        EXPECT_NE(record.find(".CURVE_3D."), std::string::npos) << record;
        const auto pcurve = data.at(references(record)[1]);
        const auto definition = data.at(references(pcurve)[1]);
        const auto line = data.at(references(definition)[0]);
        // Degree 1 over the side's own parameter range: the domain's u or v interval.
        EXPECT_EQ(line.rfind("B_SPLINE_CURVE_WITH_KNOTS('',1,", 0), 0u) << line;
        const auto at = line.find(",(2,2),(");
        ASSERT_NE(at, std::string::npos) << line;
        std::size_t used = 0;
        const double lo = std::stod(line.substr(at + 8), &used);
        const double hi = std::stod(line.substr(at + 8 + used + 1));
        const geom::ParamRect dom = geom::domain(s);
        EXPECT_TRUE((lo == dom.u.lo && hi == dom.u.hi) || (lo == dom.v.lo && hi == dom.v.hi))
            << line;
    }
}

TEST(StepWriter, SidesOfAClosedOrPolarSurfaceHaveNoPcurves) {
    // A seam is one edge on two sides of the domain (two p-curves, a SEAM_CURVE): left to the
    // reader, as before.
    const geom::Curve profile = geom::line_segment({1, 0, 0}, {2, 0, 1});
    const auto band = geom::revolve(profile, 360);
    ASSERT_TRUE(band);
    const auto text = exchange::step_text({*band}, "band");
    ASSERT_TRUE(text);
    EXPECT_EQ(count_of(instances(*text), "PCURVE("), 0);
}

TEST(StepWriter, KnotsAreDistinctValuesWithMultiplicitiesAndPointsU_Major) {
    geom::Surface s = bilinear();
    s.knots_u = {0, 0, 1, 1};
    const auto text = exchange::step_text({s}, "p");
    ASSERT_TRUE(text);
    const auto data = instances(*text);
    std::string surface;
    for (const auto& [id, r] : data)
        if (r.rfind("B_SPLINE_SURFACE_WITH_KNOTS", 0) == 0) surface = r;
    const std::string head = "B_SPLINE_SURFACE_WITH_KNOTS('',1,1,((#";
    const std::string tail = ")),.UNSPECIFIED.,.F.,.F.,.F.,(2,2),(2,2),(0.0,1.0),(0.0,1.0),"
                             ".UNSPECIFIED.)";
    ASSERT_EQ(surface.rfind(head, 0), 0u) << surface;
    ASSERT_EQ(surface.substr(surface.size() - tail.size()), tail) << surface;
    const std::vector<int> m = references(surface);
    ASSERT_EQ(m.size(), 4u) << surface;
    // P(1, 1) is the fourth reference: the outer list runs along u.
    EXPECT_EQ(data.at(m[3]), "CARTESIAN_POINT('',(1.0,1.0,0.5))");
    EXPECT_EQ(data.at(m[1]), "CARTESIAN_POINT('',(0.0,1.0,0.0))");
}

TEST(StepWriter, RationalObjectsAreTheComplexInstanceInAlphabeticalOrder) {
    geom::Surface s = bilinear();
    s.type = geom::SplineType::nurbs;
    s.weights = {1, 0.5, 2, 1};
    const auto text = exchange::step_text({s}, "r");
    ASSERT_TRUE(text);
    const std::string head = "( BOUNDED_SURFACE() B_SPLINE_SURFACE(1,1,";
    const auto at = text->find(head);
    ASSERT_NE(at, std::string::npos);
    const std::string record = text->substr(at, text->find('\n', at) - at);
    // The partial entities in alphabetical order, the weights u-major.
    std::size_t at_part = 0;
    for (const char* part :
         {"( BOUNDED_SURFACE() B_SPLINE_SURFACE(1,1,", ") B_SPLINE_SURFACE_WITH_KNOTS(",
          ") GEOMETRIC_REPRESENTATION_ITEM() RATIONAL_B_SPLINE_SURFACE(((1.0,0.5),(2.0,1.0))) "
          "REPRESENTATION_ITEM('') SURFACE() );"}) {
        const auto found = record.find(part, at_part);
        ASSERT_NE(found, std::string::npos) << part << " in " << record;
        at_part = found + 1;
    }
    EXPECT_EQ(record.substr(record.size() - 12), "SURFACE() );") << record;
    // The sides of a rational surface are rational curves.
    EXPECT_NE(text->find("( BOUNDED_CURVE() B_SPLINE_CURVE(1,"), std::string::npos);
}

TEST(StepWriter, AFullRevolutionHasOneSeamEdgeUsedTwice) {
    // A segment away from the axis turned 360 degrees: a closed band, open in u.
    const geom::Curve profile = geom::line_segment({1, 0, 0}, {2, 0, 1});
    const auto band = geom::revolve(profile, 360);
    ASSERT_TRUE(band);
    const auto text = exchange::step_text({*band}, "band");
    ASSERT_TRUE(text);
    expect_well_formed(*text);
    const auto data = instances(*text);
    EXPECT_EQ(count_of(data, "EDGE_CURVE("), 3);    // the seam and the two circles
    EXPECT_EQ(count_of(data, "ORIENTED_EDGE("), 4); // the seam twice
    EXPECT_EQ(count_of(data, "VERTEX_POINT("), 2);  // one on each circle
    EXPECT_NE(text->find(".F.,.T.,.F.) B_SPLINE_SURFACE_WITH_KNOTS((3,3),(3,2,2,2,3),"),
              std::string::npos)
        << "v_closed should be true";
}

TEST(StepWriter, ATorusHasTwoSeamsAndOneVertexASphereOneSeamAndNoPoleEdges) {
    const auto circle = geom::full_circle({3, 0, 0}, 1, geom::Plane::xz);
    ASSERT_TRUE(circle);
    const auto torus = geom::revolve(*circle, 360);
    ASSERT_TRUE(torus);
    const auto torus_text = exchange::step_text({*torus}, "torus");
    ASSERT_TRUE(torus_text);
    expect_well_formed(*torus_text);
    const auto t = instances(*torus_text);
    EXPECT_EQ(count_of(t, "EDGE_CURVE("), 2);
    EXPECT_EQ(count_of(t, "ORIENTED_EDGE("), 4);
    EXPECT_EQ(count_of(t, "VERTEX_POINT("), 1);

    const auto half = geom::circular_arc({0, 0, 0}, 1, -90, 90, geom::Plane::xz);
    ASSERT_TRUE(half);
    const auto sphere = geom::revolve(*half, 360);
    ASSERT_TRUE(sphere);
    const auto sphere_text = exchange::step_text({*sphere}, "sphere");
    ASSERT_TRUE(sphere_text);
    expect_well_formed(*sphere_text);
    const auto s = instances(*sphere_text);
    EXPECT_EQ(count_of(s, "EDGE_CURVE("), 1);
    EXPECT_EQ(count_of(s, "ORIENTED_EDGE("), 2);
    EXPECT_EQ(count_of(s, "VERTEX_POINT("), 2); // the poles
}

TEST(StepWriter, CurvesGoIntoAGeometricCurveSetBesideTheSurfaces) {
    isoparm::testing::RandomGeometry random(11);
    const geom::Curve c = random.curve(3, 6, true);
    const auto only_curve = exchange::step_text({c}, "c");
    ASSERT_TRUE(only_curve);
    expect_well_formed(*only_curve);
    auto data = instances(*only_curve);
    EXPECT_EQ(count_of(data, "GEOMETRIC_CURVE_SET("), 1);
    EXPECT_EQ(count_of(data, "GEOMETRICALLY_BOUNDED_WIREFRAME_SHAPE_REPRESENTATION("), 1);
    EXPECT_EQ(count_of(data, "( BOUNDED_CURVE() B_SPLINE_CURVE(3,"), 1);

    const auto both = exchange::step_text({c, bilinear()}, "both");
    ASSERT_TRUE(both);
    expect_well_formed(*both);
    data = instances(*both);
    EXPECT_EQ(count_of(data, "SHAPE_REPRESENTATION_RELATIONSHIP("), 2);
    EXPECT_EQ(count_of(data, "SHAPE_REPRESENTATION("), 1);
}

TEST(StepWriter, NamesAreQuotedAndTheBytesRepeat) {
    const auto a = exchange::step_text({bilinear()}, "it's a \\ name\n");
    ASSERT_TRUE(a);
    EXPECT_NE(a->find("PRODUCT('it''s a \\\\ name?','it''s a \\\\ name?'"), std::string::npos);
    EXPECT_EQ(*a, *exchange::step_text({bilinear()}, "it's a \\ name\n"));
}

TEST(StepWriter, NonPositiveWeightsAreRefusedNamingThePointAndTheMeshFormats) {
    geom::Surface s = bilinear();
    s.type = geom::SplineType::nurbs;
    s.weights = {1, 1, 0, -1};
    const auto one = exchange::step_text({s}, "w");
    ASSERT_FALSE(one);
    EXPECT_EQ(one.error().code, geom::ErrorCode::weights);
    EXPECT_EQ(one.error().path, "/weights/1/0");
    EXPECT_NE(one.error().message.find("control point (1, 0)"), std::string::npos);
    EXPECT_NE(one.error().message.find("mesh"), std::string::npos);
    const auto two = exchange::step_text({bilinear(), s}, "w");
    ASSERT_FALSE(two);
    EXPECT_EQ(two.error().path, "/objects/1/weights/1/0");
}

} // namespace
