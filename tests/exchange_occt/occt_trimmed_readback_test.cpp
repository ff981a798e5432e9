// Trimmed faces written by isoparm (IGES 144 with 142 curves on surface; STEP ADVANCED_FACE with
// FACE_BOUNDs and p-curves) read back by OpenCASCADE's readers: each comes back as one face
// with as many wires as the trim has loops, OCCT's area of it (BRepGProp) equals isoparm's
// trimmed area within 1e-6 relative, and every edge of the face lies on a trim loop's trace
// S(C(t)) within the file's tolerance (and every loop's trace on an edge of the face).
#include <gtest/gtest.h>

#include <BRepAdaptor_Curve.hxx>
#include <BRepBuilderAPI_MakeVertex.hxx>
#include <BRepExtrema_DistShapeShape.hxx>
#include <BRepGProp.hxx>
#include <BRep_Tool.hxx>
#include <GProp_GProps.hxx>
#include <IGESControl_Reader.hxx>
#include <STEPControl_Reader.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <algorithm>
#include <cmath>
#include <fstream>
#include <glm/geometric.hpp>

#include "core/exchange/iges_writer.hpp"
#include "core/exchange/step_writer.hpp"
#include "core/geom/evaluate.hpp"
#include "core/geom/knots.hpp"
#include "core/geom/trim/trim_area.hpp"
#include "core/geom/trim/trim_validate.hpp"
#include "tests/support/temp_dir.hpp"

namespace {

using namespace isoparm;
using exchange::ExactShape;

enum class Format { iges, step };

TopoDS_Shape read_back(Format f, const std::string& path) {
    std::unique_ptr<XSControl_Reader> reader;
    if (f == Format::step)
        reader = std::make_unique<STEPControl_Reader>();
    else
        reader = std::make_unique<IGESControl_Reader>();
    if (reader->ReadFile(path.c_str()) != IFSelect_RetDone) return {};
    reader->TransferRoots();
    return reader->OneShape();
}

// A bicubic B-spline patch over [0, 1]^2 with a bump (rational when `weighted`).
geom::Surface wavy_patch(bool weighted) {
    geom::Surface s;
    s.type = weighted ? geom::SplineType::nurbs : geom::SplineType::bspline;
    s.degree_u = s.degree_v = 3;
    s.n_u = 5;
    s.n_v = 4;
    s.knots_u = {0, 0, 0, 0, 0.4, 1, 1, 1, 1};
    s.knots_v = {0, 0, 0, 0, 1, 1, 1, 1};
    for (int i = 0; i < s.n_u; ++i)
        for (int j = 0; j < s.n_v; ++j) {
            s.points.push_back({10.0 * i / 4, 8.0 * j / 3, (i == 2 && j == 1) ? 4.0 : 0.5 * i});
            s.weights.push_back(weighted && i == 2 ? 1.7 : 1.0);
        }
    return s;
}

// The flat square [0, 20] x [0, 20] in z = 0, degree 1, parameters [0, 1]^2.
geom::Surface flat_square() {
    geom::Surface s;
    s.type = geom::SplineType::bspline;
    s.degree_u = s.degree_v = 1;
    s.n_u = s.n_v = 2;
    s.knots_u = s.knots_v = {0, 0, 1, 1};
    for (int i = 0; i < 2; ++i)
        for (int j = 0; j < 2; ++j)
            s.points.push_back({20.0 * i, 20.0 * j, 0}), s.weights.push_back(1);
    return s;
}

struct Case {
    std::string name;
    geom::TrimmedSurface face;
};

std::vector<Case> cases() {
    std::vector<Case> out;
    {
        // A square plate with a round hole: exactly 400 - pi 25 mm^2.
        geom::Trim t;
        t.holes.push_back(*geom::circle_loop({0.5, 0.5}, 0.25, true));
        out.push_back({"plate with a round hole", {flat_square(), t}});
    }
    {
        // A curved patch: a pentagon outer loop and a circular hole.
        geom::Trim t;
        t.outer =
            geom::polygon_loop({{0.05, 0.1}, {0.9, 0.05}, {0.95, 0.6}, {0.5, 0.95}, {0.1, 0.7}});
        t.holes.push_back(*geom::circle_loop({0.45, 0.45}, 0.15, true));
        out.push_back({"wavy patch, pentagon and hole", {wavy_patch(false), t}});
    }
    {
        // A rational patch: an outer loop of an arc and lines, two holes.
        geom::TrimLoop outer;
        outer.curves.push_back(geom::trim_line({0.1, 0.1}, {0.9, 0.1}));
        outer.curves.push_back(*geom::trim_arc({0.9, 0.5}, 0.4, -90, 90));
        outer.curves.push_back(geom::trim_line({0.9, 0.9}, {0.1, 0.9}));
        outer.curves.push_back(geom::trim_line({0.1, 0.9}, {0.1, 0.1}));
        geom::Trim t;
        t.outer = outer;
        // The arc leaves the domain: scale it into [0, 1] in u.
        t = geom::map_affine(t, {0.75, 1}, {0.0, 0});
        t.holes.push_back(geom::reversed(geom::polygon_loop({{0.2, 0.2}, {0.4, 0.2}, {0.3, 0.4}})));
        t.holes.push_back(*geom::circle_loop({0.5, 0.7}, 0.08, true));
        out.push_back({"rational patch, arc outer loop and two holes", {wavy_patch(true), t}});
    }
    return out;
}

// The trace of every loop, S(C(t)) at `n` parameters per curve; `spacing` (when given) the
// largest distance between consecutive samples of one curve.
std::vector<glm::dvec3> loop_trace(const geom::TrimmedSurface& f, int n,
                                   double* spacing = nullptr) {
    std::vector<glm::dvec3> out;
    const geom::Trim& t = f.trim;
    std::vector<geom::TrimLoop> loops;
    loops.push_back(t.outer ? *t.outer : geom::rectangle_loop(geom::domain(f.surface)));
    for (const geom::TrimLoop& h : t.holes) loops.push_back(h);
    for (const geom::TrimLoop& loop : loops)
        for (const geom::Curve& c : loop.curves) {
            const geom::Interval d = geom::domain(c);
            for (int k = 0; k <= n; ++k) {
                const auto p = geom::curve_point(c, d.lo + (d.hi - d.lo) * k / n);
                if (!p) continue;
                const auto q = geom::surface_point(f.surface, p->x, p->y);
                if (!q) continue;
                if (spacing && k > 0) *spacing = std::max(*spacing, glm::distance(out.back(), *q));
                out.push_back(*q);
            }
        }
    return out;
}

double distance_to(const TopoDS_Shape& shape, const glm::dvec3& p) {
    BRepExtrema_DistShapeShape d(BRepBuilderAPI_MakeVertex(gp_Pnt(p.x, p.y, p.z)).Vertex(), shape);
    return d.IsDone() && d.NbSolution() > 0 ? d.Value() : 1e300;
}

void check_round_trip(Format format) {
    const test::TempDir dir("isoparm-trimmed-readback");
    for (const Case& c : cases()) {
        ASSERT_TRUE(geom::validate_trim(c.face.trim, geom::domain(c.face.surface)))
            << c.name << ": "
            << geom::validate_trim(c.face.trim, geom::domain(c.face.surface)).error().message;
        const std::vector<ExactShape> shapes{c.face};
        const auto text = format == Format::step ? exchange::step_text(shapes, "trimmed")
                                                 : exchange::iges_text(shapes, "trimmed");
        ASSERT_TRUE(text) << c.name << ": " << text.error().message;
        const std::string path = dir.path(format == Format::step ? "t.stp" : "t.igs");
        std::ofstream(path, std::ios::binary) << *text;
        const TopoDS_Shape shape = read_back(format, path);
        ASSERT_FALSE(shape.IsNull()) << c.name << ": OCCT read nothing";
        int faces = 0;
        TopoDS_Face face;
        for (TopExp_Explorer e(shape, TopAbs_FACE); e.More(); e.Next(), ++faces)
            face = TopoDS::Face(e.Current());
        ASSERT_EQ(faces, 1) << c.name;
        int wires = 0;
        for (TopExp_Explorer e(face, TopAbs_WIRE); e.More(); e.Next()) ++wires;
        EXPECT_EQ(wires, 1 + static_cast<int>(c.face.trim.holes.size())) << c.name;

        GProp_GProps props;
        BRepGProp::SurfaceProperties(face, props, 1e-12);
        const double ours = geom::trimmed_area(c.face.surface, c.face.trim, 192);
        const double theirs = props.Mass();
        EXPECT_NEAR(theirs / ours, 1.0, 1e-6)
            << c.name << ": OCCT's area " << theirs << ", isoparm's " << ours;

        // The boundary: OCCT's edges against the loops' traces, both ways, within the file's
        // tolerance (the largest edge tolerance OCCT gives the face's edges).
        double tolerance = 0;
        for (TopExp_Explorer e(face, TopAbs_EDGE); e.More(); e.Next())
            tolerance = std::max(tolerance, BRep_Tool::Tolerance(TopoDS::Edge(e.Current())));
        double worst = 0;
        // Each trace point's distance to the face's boundary (its wires).
        for (const glm::dvec3& p : loop_trace(c.face, 16)) {
            double best = 1e300;
            for (TopExp_Explorer w(face, TopAbs_WIRE); w.More(); w.Next())
                best = std::min(best, distance_to(w.Current(), p));
            worst = std::max(worst, best);
        }
        // Each of OCCT's edges sampled against the loops' traces (finely sampled).
        double spacing = 0;
        const std::vector<glm::dvec3> trace = loop_trace(c.face, 400, &spacing);
        double worst_back = 0;
        for (TopExp_Explorer e(face, TopAbs_EDGE); e.More(); e.Next()) {
            BRepAdaptor_Curve a(TopoDS::Edge(e.Current()));
            for (int k = 0; k <= 16; ++k) {
                const gp_Pnt q =
                    a.Value(a.FirstParameter() + (a.LastParameter() - a.FirstParameter()) * k / 16);
                double best = 1e300;
                for (const glm::dvec3& p : trace)
                    best = std::min(best, glm::distance(p, glm::dvec3(q.X(), q.Y(), q.Z())));
                worst_back = std::max(worst_back, best);
            }
        }
        EXPECT_LE(worst, tolerance) << c.name << ": the loops are " << worst
                                    << " from OCCT's edges (tolerance " << tolerance << ")";
        std::cout << (format == Format::step ? "STEP" : "IGES") << " " << c.name << ": area ratio "
                  << theirs / ours - 1 << " off 1, loops within " << worst
                  << " of the edges (file tolerance " << tolerance << "), edges within "
                  << worst_back << " of the sampled loops\n";
        // An edge point on a loop is within half the samples' spacing of one of them.
        EXPECT_LE(worst_back, spacing) << c.name << ": an edge strays from the loops";
    }
}

TEST(OcctTrimmedReadBack, StepFacesComeBackWithTheirAreaAndBoundary) {
    check_round_trip(Format::step);
}

TEST(OcctTrimmedReadBack, IgesFacesComeBackWithTheirAreaAndBoundary) {
    check_round_trip(Format::iges);
}

} // namespace
