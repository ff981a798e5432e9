// isoparm's IGES and STEP files read back by OCCT's readers (IGESControl_Reader,
// STEPControl_Reader): every spline object of every scene in assets/scenes and random rational
// surfaces and curves (clamped and not, repeated knots) come back as B-spline faces and edges
// whose points agree with isoparm's own evaluation at 1000 parameters per surface, within 1e-9
// of the object's size.
#include <gtest/gtest.h>

#include <BRepCheck_Analyzer.hxx>
#include <BRep_Tool.hxx>
#include <Geom_BSplineCurve.hxx>
#include <Geom_BSplineSurface.hxx>
#include <Geom_RectangularTrimmedSurface.hxx>
#include <Geom_TrimmedCurve.hxx>
#include <IGESControl_Reader.hxx>
#include <STEPControl_Reader.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <glm/geometric.hpp>

#include "core/exchange/iges_writer.hpp"
#include "core/exchange/step_writer.hpp"
#include "core/geom/construct.hpp"
#include "core/geom/evaluate.hpp"
#include "core/geom/knots.hpp"
#include "core/geom/primitives.hpp"
#include "core/scene/scene_io.hpp"
#include "tests/support/random_geometry.hpp"
#include "tests/support/temp_dir.hpp"

namespace {

using namespace isoparm;
using exchange::ExactShape;

enum class Format { iges, step };

const char* format_name(Format f) {
    return f == Format::iges ? "IGES" : "STEP";
}

// The diagonal of the control points' bounding box: the scale of the comparison.
template <class G> double size_of(const G& g) {
    glm::dvec3 lo(1e300), hi(-1e300);
    for (const glm::dvec3& p : g.points) lo = glm::min(lo, p), hi = glm::max(hi, p);
    return std::max(glm::distance(lo, hi), 1e-300);
}

TopoDS_Shape read_back(Format f, const std::string& path) {
    if (f == Format::step) {
        STEPControl_Reader reader;
        if (reader.ReadFile(path.c_str()) != IFSelect_RetDone) return {};
        reader.TransferRoots();
        return reader.OneShape();
    }
    IGESControl_Reader reader;
    if (reader.ReadFile(path.c_str()) != IFSelect_RetDone) return {};
    reader.TransferRoots();
    return reader.OneShape();
}

std::string write(const test::TempDir& dir, Format f, const std::vector<ExactShape>& shapes) {
    const auto text = f == Format::step ? exchange::step_text(shapes, "readback")
                                        : exchange::iges_text(shapes, "readback");
    EXPECT_TRUE(text) << text.error().message;
    const std::string path = dir.path(f == Format::step ? "out.stp" : "out.igs");
    std::ofstream(path, std::ios::binary) << (text ? *text : std::string());
    return path;
}

// The largest distance between isoparm's and OCCT's points over a 40 x 25 parameter grid
// (1000 points, both domain ends included), divided by the surface's size.
double surface_deviation(const geom::Surface& s, const Handle(Geom_Surface) & g) {
    const geom::ParamRect d = geom::domain(s);
    double worst = 0;
    for (int i = 0; i < 40; ++i)
        for (int j = 0; j < 25; ++j) {
            const double u = i == 39 ? d.u.hi : d.u.lo + (d.u.hi - d.u.lo) * i / 39;
            const double v = j == 24 ? d.v.hi : d.v.lo + (d.v.hi - d.v.lo) * j / 24;
            const auto mine = geom::surface_point(s, u, v);
            if (!mine) continue;
            const gp_Pnt theirs = g->Value(u, v);
            worst = std::max(worst, glm::distance(*mine, {theirs.X(), theirs.Y(), theirs.Z()}));
        }
    return worst / size_of(s);
}

// A piece of an edge as OCCT built it: its curve and parameter range.
struct Piece {
    Handle(Geom_Curve) curve;
    double first = 0, last = 0;
};

// The largest distance, over 1000 parameters of the curve's domain, between isoparm's point
// and the point of the piece whose range holds the parameter, divided by the curve's size.
double curve_deviation(const geom::Curve& c, const std::vector<Piece>& pieces) {
    const geom::Interval d = geom::domain(c);
    double worst = 0;
    for (int k = 0; k < 1000; ++k) {
        const double t = k == 999 ? d.hi : d.lo + (d.hi - d.lo) * k / 999;
        const auto mine = geom::curve_point(c, t);
        if (!mine) continue;
        const double slack = 1e-12 * (d.hi - d.lo);
        const auto piece = std::find_if(pieces.begin(), pieces.end(), [&](const Piece& p) {
            return p.first - slack <= t && t <= p.last + slack;
        });
        if (piece == pieces.end()) return 1e300; // a parameter no piece covers
        const gp_Pnt theirs = piece->curve->Value(t);
        worst = std::max(worst, glm::distance(*mine, {theirs.X(), theirs.Y(), theirs.Z()}));
    }
    return worst / size_of(c);
}

// Face k of `shape` against surface k.
void expect_faces(Format f, const TopoDS_Shape& shape, const std::vector<geom::Surface>& surfaces,
                  const std::string& what) {
    std::size_t k = 0;
    for (TopExp_Explorer e(shape, TopAbs_FACE); e.More(); e.Next(), ++k) {
        ASSERT_LT(k, surfaces.size()) << format_name(f) << " " << what << ": too many faces";
        Handle(Geom_Surface) g = BRep_Tool::Surface(TopoDS::Face(e.Current()));
        if (auto t = Handle(Geom_RectangularTrimmedSurface)::DownCast(g); !t.IsNull())
            g = t->BasisSurface();
        EXPECT_FALSE(Handle(Geom_BSplineSurface)::DownCast(g).IsNull())
            << format_name(f) << " " << what << " surface " << k << ": not a B-spline surface";
        EXPECT_LE(surface_deviation(surfaces[k], g), 1e-9)
            << format_name(f) << " " << what << " surface " << k;
        // STEP faces carry isoparm's own edge loop: OCCT must find the face valid.
        if (f == Format::step) {
            EXPECT_TRUE(BRepCheck_Analyzer(e.Current()).IsValid())
                << "STEP " << what << " surface " << k << ": not a valid face";
        }
    }
    EXPECT_EQ(k, surfaces.size()) << format_name(f) << " " << what << ": faces read";
}

// The edges outside every face (the curves) against the curves, in order.
void expect_free_edges(Format f, const TopoDS_Shape& shape, const std::vector<geom::Curve>& curves,
                       const std::string& what) {
    // OCCT's IGES reader splits a curve that is only C0 at some knot into C1 pieces
    // (read.iges.bspline.continuity = 1, its default), keeping the parameters: curve k is the
    // run of edges that reaches the end of its domain.
    std::vector<Piece> edges;
    for (TopExp_Explorer e(shape, TopAbs_EDGE, TopAbs_FACE); e.More(); e.Next()) {
        Piece p;
        p.curve = BRep_Tool::Curve(TopoDS::Edge(e.Current()), p.first, p.last);
        ASSERT_FALSE(p.curve.IsNull());
        if (auto t = Handle(Geom_TrimmedCurve)::DownCast(p.curve); !t.IsNull())
            p.curve = t->BasisCurve();
        EXPECT_FALSE(Handle(Geom_BSplineCurve)::DownCast(p.curve).IsNull())
            << format_name(f) << " " << what << ": an edge that is not a B-spline curve";
        edges.push_back(p);
    }
    std::size_t next = 0;
    for (std::size_t k = 0; k < curves.size(); ++k) {
        const geom::Interval d = geom::domain(curves[k]);
        std::vector<Piece> pieces;
        while (next < edges.size() &&
               (pieces.empty() || pieces.back().last < d.hi - 1e-12 * (d.hi - d.lo)))
            pieces.push_back(edges[next++]);
        EXPECT_LE(curve_deviation(curves[k], pieces), 1e-9)
            << format_name(f) << " " << what << " curve " << k << " (" << pieces.size()
            << " edges)";
    }
    EXPECT_EQ(next, edges.size()) << format_name(f) << " " << what << ": edges left over";
}

// One file with the surfaces and then the curves (as `isoparm export` writes a scene), read
// back: faces in order, then the free edges in order.
void expect_read_back(Format f, const std::vector<geom::Surface>& surfaces,
                      const std::vector<geom::Curve>& curves, const std::string& what) {
    if (surfaces.empty() && curves.empty()) return;
    test::TempDir dir("isoparm-occt");
    std::vector<ExactShape> shapes(surfaces.begin(), surfaces.end());
    shapes.insert(shapes.end(), curves.begin(), curves.end());
    const TopoDS_Shape shape = read_back(f, write(dir, f, shapes));
    ASSERT_FALSE(shape.IsNull()) << format_name(f) << " " << what << ": nothing read";
    expect_faces(f, shape, surfaces, what);
    expect_free_edges(f, shape, curves, what);
}

void expect_surfaces_read_back(Format f, const std::vector<geom::Surface>& surfaces,
                               const std::string& what) {
    expect_read_back(f, surfaces, {}, what);
}

void expect_curves_read_back(Format f, const std::vector<geom::Curve>& curves,
                             const std::string& what) {
    expect_read_back(f, {}, curves, what);
}

TEST(OcctReadBack, EverySceneInTheGallery) {
    const std::filesystem::path scenes =
        std::filesystem::path(ISOPARM_SOURCE_DIR) / "assets/scenes";
    std::vector<std::filesystem::path> files;
    for (const auto& entry : std::filesystem::directory_iterator(scenes))
        if (entry.path().extension() == ".json") files.push_back(entry.path());
    std::sort(files.begin(), files.end());
    ASSERT_FALSE(files.empty());
    int surfaces_seen = 0;
    for (const auto& file : files) {
        const auto doc = scene::load_scene(file.string());
        ASSERT_TRUE(doc) << file << ": " << doc.error().message;
        std::vector<geom::Surface> surfaces;
        std::vector<geom::Curve> curves;
        for (const doc::Object& o : doc->objects) {
            if (const geom::Surface* s = o.surface()) {
                if (exchange::check_positive_weights(*s))
                    surfaces.push_back(*s);
                else
                    std::cout << file.filename() << ": " << o.name
                              << " has a non-positive weight (not an exact export)\n";
            }
            if (const geom::Curve* c = o.curve())
                if (exchange::check_positive_weights(*c)) curves.push_back(*c);
        }
        surfaces_seen += static_cast<int>(surfaces.size());
        for (Format f : {Format::iges, Format::step}) {
            // The whole scene in one file, and the surfaces and curves on their own.
            expect_read_back(f, surfaces, curves, file.filename().string());
            expect_surfaces_read_back(f, surfaces, file.filename().string());
            expect_curves_read_back(f, curves, file.filename().string());
        }
    }
    EXPECT_GT(surfaces_seen, 10);
}

TEST(OcctReadBack, RandomRationalSurfacesAndCurves) {
    isoparm::testing::RandomGeometry random(2026);
    std::vector<geom::Surface> surfaces;
    std::vector<geom::Curve> curves;
    for (int k = 0; k < 24; ++k) {
        const int p = random.integer(1, 5), q = random.integer(1, 5);
        const bool clamped = k % 3 != 2;
        surfaces.push_back(random.surface(p, q, p + random.integer(1, 6), q + random.integer(1, 6),
                                          true, clamped, clamped ? std::max(1, p - 1) : 1));
        curves.push_back(random.curve(p, p + random.integer(1, 8), true, clamped));
    }
    for (Format f : {Format::iges, Format::step}) {
        // One file each, and one surface per file (so no reader shares anything between them).
        expect_surfaces_read_back(f, surfaces, "random surfaces");
        expect_curves_read_back(f, curves, "random curves");
        expect_read_back(f, surfaces, curves, "random surfaces and curves");
        for (std::size_t k = 0; k < surfaces.size(); ++k)
            expect_surfaces_read_back(f, {surfaces[k]}, "random surface " + std::to_string(k));
    }
}

TEST(OcctReadBack, ClosedAndPolarSurfacesBecomeValidFaces) {
    // A band (one seam), a torus (two seams, one vertex) and a sphere (a seam and two poles):
    // the STEP face's loop must be one OCCT accepts as a valid face (BRepCheck_Analyzer).
    const auto circle = geom::full_circle({3, 0, 0}, 1, geom::Plane::xz);
    const auto half = geom::circular_arc({0, 0, 0}, 1, -90, 90, geom::Plane::xz);
    ASSERT_TRUE(circle && half);
    const std::pair<const char*, geom::Expected<geom::Surface>> cases[] = {
        {"band", geom::revolve(geom::line_segment({1, 0, 0}, {2, 0, 1}), 360)},
        {"torus", geom::revolve(*circle, 360)},
        {"sphere", geom::revolve(*half, 360)},
        {"quarter band", geom::revolve(geom::line_segment({1, 0, 0}, {2, 0, 1}), 90)}};
    for (const auto& [name, s] : cases) {
        ASSERT_TRUE(s) << name;
        test::TempDir dir("isoparm-occt");
        const TopoDS_Shape shape = read_back(Format::step, write(dir, Format::step, {*s}));
        ASSERT_FALSE(shape.IsNull()) << name;
        int faces = 0;
        for (TopExp_Explorer e(shape, TopAbs_FACE); e.More(); e.Next()) ++faces;
        EXPECT_EQ(faces, 1) << name;
        EXPECT_TRUE(BRepCheck_Analyzer(shape).IsValid()) << name << ": not a valid shape";
        expect_surfaces_read_back(Format::step, {*s}, name);
        expect_surfaces_read_back(Format::iges, {*s}, name);
    }
}

} // namespace
