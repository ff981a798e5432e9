// Real files written by other CAD systems (../shared/cad, never committed; skipped with a
// message where absent) import as trimmed faces: each face's wires become trim loops on its
// NURBS surface (occt_trim.hpp), and the trimmed area (core/geom/trim/trim_area.hpp) must match
// OpenCASCADE's own area of the face (BRepGProp) within 1e-4 relative, or, where the file's
// wires have 2D gaps (which BRepGProp's integral leaves out), OCCT's area of the same face with
// the gaps closed by ShapeFix within 1e-4; the two kinds are counted and printed apart. Faces whose
// loops could not be built come in untrimmed with a note; they are counted and named, never
// compared. Each file must keep at least the number of matching faces measured when the test was
// written.
#include <gtest/gtest.h>

#include <BRepGProp.hxx>
#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <GProp_GProps.hxx>
#include <IGESControl_Reader.hxx>
#include <Interface_Static.hxx>
#include <STEPControl_Reader.hxx>
#include <ShapeExtend_Status.hxx>
#include <ShapeFix_Wire.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>

#include "core/exchange/iges_writer.hpp"
#include "core/exchange/step_writer.hpp"
#include "core/exchange_occt/occt_convert.hpp"
#include "core/geom/knots.hpp"
#include "core/geom/trim/trim.hpp"
#include "core/geom/trim/trim_area.hpp"
#include "tests/exchange_occt/real_cad_files.hpp"
#include "tests/support/temp_dir.hpp"

using namespace isoparm;

namespace {

using test::cad_dir;
using test::cad_files;

// How many faces of each file import trimmed with OCCT's area (as read, or once the wires' 2D
// gaps are closed: occt_area_gaps_closed), as measured (2026-11-28, 1221 of 1222): a file that
// drops below its count fails. Faces whose p-curves leave their B-spline surface's range come
// in on the surface extended to hold them (occt_convert.cpp, extend_to_pcurves): hammer.iges
// faces 13, 18, 33, 44 (bilinear planes, circles 1e-5 to 2e-5 past the range, 0.037 to 0.115
// in space) match within 5.0e-7, 9.2e-14, 1.0e-13, 6.4e-14; trj7 faces 7 and 8 (an edge of 69
// poles wandering from u = -3.1e-4 to +1.0e-4 about u = 0) within 9.1e-5: BRepGProp integrates
// such a face as if cut to the surface's range (Green's integral of that edge alone: -0.00202
// over the extended surface, +0.000199 with u cut at 0; box 24.40400, isoparm 24.40602, OCCT
// 24.40381). bug23171_tube_surf.igs's 2 faces are offsets of a revolved line, converted exactly as
// the revolution of the moved line (occt_convert.cpp exact_offset): 397270.6723 as OCCT (a domain
// 430 times longer than wide: trim_area.cpp). ec_turbine-A face 1, a plane whose circular hole
// starts where it touches the outer circle, trims now that loops may touch at a point:
// 629.4008312 as OCCT (5e-15). bug32596 faces 4, 13, 65 and bug22869_Spring faces 0 and 5 have
// p-curves that cross within the file's loose tolerance: their wires mended by ShapeFix_Wire on a
// copy (occt_convert.cpp fixed_wires) trim, and match OCCT's area of the face as the file has it
// (Spring face 0: 5655.90742 against 5655.90281, 8.2e-7; its box ends 8.6e-17 past its segmented
// surface's domain, which occt_trim.cpp's Mapper now takes as the domain: before, its parameters
// were taken as not OCCT's and one of its edges, tolerance 0.079, went through a fit that failed).
// The face that does not match is printed with the reason: face 10 of catiav5_Ventilator.stp, a
// hexagon (with a round hole) of six lines that miss their corners: at each corner one line ends
// on the vertex and the other 0.014 from it, sideways (vertex tolerances 0.014, one 0.028). Its
// area is defined only to about its perimeter times that, 1e-2 relative: the vertices as corners
// give 67.573 (BRepMesh 67.57 to 67.59), the midpoints of the line ends 67.876, BRepGProp as read
// (which leaves the gaps out) 67.872, ShapeFix_Wire::FixGaps2d (each line made a quadratic
// B-spline with its end poles moved to those midpoints: bent sides) 67.910, and isoparm (the lines
// joined where they cross, 0.016 from the vertices) 67.977. OCCT's reader leaves the gaps open,
// so none of these is OCCT's face; picking the rule that lands on a reference would not make the
// face better defined, so it is left unmatched.
const std::map<std::string, int> measured_matches = {
    {"BUC50025.igs", 7},
    {"OCC8842_cone_CATIA.igs", 3},
    {"bug22566_test_Bad.igs", 9},
    {"bug22869_Spring.igs", 6},
    {"bug23171_tube_surf.igs", 2},
    {"bug24283_spheres.stp", 2},
    {"bug24595_281390.stp", 21},
    {"bug32596_abc_0_13.step", 99},
    {"catiav5_Ventilator.stp", 304},
    {"ec_turbine-A.stp", 53},
    {"hammer.iges", 45},
    {"nx9_face_recognition_sample_part.stp", 23},
    {"occ22470.igs", 18},
    {"splinecage.stp", 4},
    {"sw2013_featuretype.STEP", 96},
    {"trj2_as1-tc-214.stp", 160},
    {"trj3_s1-ct-214.stp", 178},
    {"trj3_s1-id-203.stp", 134},
    {"trj7_k1-al-214.stp", 57},
};

struct FileAreas {
    int faces = 0, trimmed = 0, untrimmed = 0, skipped = 0, match = 0, match_closed = 0;
    std::vector<std::string> mismatches, gap_matches, notes;
};

double occt_area(const TopoDS_Face& face) {
    GProp_GProps props;
    BRepGProp::SurfaceProperties(face, props, 1e-10);
    return props.Mass();
}

// OCCT's area of the face with the 2D gaps of its wires closed (ShapeFix_Wire::FixGaps2d, each
// wire at its face's tolerance), or NaN where no wire has one. BRepGProp integrates along each
// edge's p-curve on its own (Green's theorem), so a gap between two p-curves' ends is a piece of
// the boundary it leaves out: its area is then off by about the gap times the distance to the
// parameters' origin. trj3_s1-ct-214.stp's three ring-shaped planes (faces 78, 83, 103) have
// two such gaps of 0.003 at u = +-23 (within the vertices' tolerance 0.0015): BRepGProp gives
// 276.3215, the same face with its gaps closed 276.45058, and isoparm's loops (the ends joined)
// 276.45058; the ring between the circles of radius 23 and 21 the curves approximate is
// pi * 88 = 276.460.
double occt_area_gaps_closed(const TopoDS_Face& face) {
    TopoDS_Face closed = TopoDS::Face(face.EmptyCopied());
    BRep_Builder builder;
    bool fixed = false;
    for (TopExp_Explorer w(face, TopAbs_WIRE); w.More(); w.Next()) {
        ShapeFix_Wire fix(TopoDS::Wire(w.Current()), face, BRep_Tool::Tolerance(face));
        fix.FixGaps2dMode() = 1;
        fixed = fix.FixGaps2d() || fixed;
        builder.Add(closed, fix.Wire());
    }
    return fixed ? occt_area(closed) : NAN;
}

FileAreas check_areas(const std::filesystem::path& file) {
    FileAreas r;
    const TopoDS_Shape shape = test::read_cad_shape(file);
    int index = 0;
    for (TopExp_Explorer e(shape, TopAbs_FACE); e.More(); e.Next(), ++index) {
        const TopoDS_Face face = TopoDS::Face(e.Current());
        ++r.faces;
        const exchange_occt::Converted c = exchange_occt::convert_face(face);
        if (!c.shape) {
            ++r.skipped;
            continue;
        }
        const auto* t = std::get_if<geom::TrimmedSurface>(&*c.shape);
        const auto* whole = std::get_if<geom::Surface>(&*c.shape);
        if (!t && !(whole && c.note.empty())) {
            ++r.untrimmed;
            r.notes.push_back("face " + std::to_string(index) + ": " + c.note);
            continue;
        }
        ++r.trimmed;
        // A face bounded by its surface's own domain comes in as the surface alone
        // (exchange_occt::is_whole_domain): its area is the whole domain's.
        geom::Trim domain_trim;
        if (!t) domain_trim.outer = geom::rectangle_loop(geom::domain(*whole));
        const double occt = occt_area(face);
        const double ours =
            t ? geom::trimmed_area(t->surface, t->trim) : geom::trimmed_area(*whole, domain_trim);
        const double rel = std::abs(ours - occt) / std::max(std::abs(occt), 1e-300);
        if (rel <= 1e-4) {
            ++r.match;
            continue;
        }
        std::string text = "face " + std::to_string(index) + ": area " + std::to_string(ours) +
                           ", OCCT " + std::to_string(occt) + " (" + std::to_string(rel) +
                           " relative)";
        if (const double closed = occt_area_gaps_closed(face); !std::isnan(closed)) {
            const double rel_closed = std::abs(ours - closed) / std::abs(closed);
            text += "; OCCT with the wires' 2D gaps closed " + std::to_string(closed) + " (" +
                    std::to_string(rel_closed) + " relative)";
            if (rel_closed <= 1e-4) {
                ++r.match_closed;
                r.gap_matches.push_back(text);
                continue;
            }
        }
        r.mismatches.push_back(text);
    }
    return r;
}

TEST(RealCadFilesTrimmed, FacesImportTrimmedWithOcctsAreas) {
    const auto files = cad_files();
    if (files.empty())
        GTEST_SKIP() << "skipped: no real CAD files in " << cad_dir << " (../shared/cad)";
    int faces = 0, trimmed = 0, match = 0, match_closed = 0;
    for (const auto& file : files) {
        const auto start = std::chrono::steady_clock::now();
        const FileAreas r = check_areas(file);
        const double seconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        const std::string name = file.filename().string();
        faces += r.faces;
        trimmed += r.trimmed;
        match += r.match;
        match_closed += r.match_closed;
        std::cout << name << ": " << r.match << " of " << r.faces
                  << " faces trimmed with OCCT's area within 1e-4";
        if (r.match_closed > 0)
            std::cout << " and " << r.match_closed << " with its area once the gaps are closed";
        std::cout << " (" << r.trimmed << " trimmed, " << r.untrimmed << " without their loops, "
                  << r.skipped << " not converted; " << seconds << " s)\n";
        for (const std::string& m : r.gap_matches) std::cout << "  gaps closed: " << m << "\n";
        for (const std::string& m : r.mismatches) std::cout << "  area differs: " << m << "\n";
        if (const auto it = measured_matches.find(name); it != measured_matches.end()) {
            EXPECT_GE(r.match + r.match_closed, it->second)
                << name << ": fewer faces match OCCT's area than the " << it->second << " measured";
        }
        for (const std::string& n : r.notes) std::cout << "  untrimmed: " << n << "\n";
    }
    std::cout << "all files: " << match + match_closed << " of " << faces
              << " faces trimmed and matching (" << match << " OCCT's area as read, "
              << match_closed << " OCCT's area once the wires' 2D gaps are closed)\n";
    if (!test::every_cad_file()) return; // the totals need every file (real_cad_files.hpp)
    EXPECT_GT(faces, 1000);
    EXPECT_GE(match + match_closed, 1221) << "of " << faces << " faces (" << trimmed << " trimmed)";
}

// Imported trimmed faces written again by isoparm (STEP and IGES, all faces of a file in one
// file) and read back by OCCT: the same number of faces, in order, each with isoparm's trimmed
// area within 1e-6 relative (the round trip on real parts, four files to keep it short).
TEST(RealCadFilesTrimmed, ImportedFacesGoOutAndComeBackTheSame) {
    const test::TempDir dir("isoparm-trimmed-real");
    int checked = 0;
    const std::vector<std::string> names = test::sampled(
        {"nx9_face_recognition_sample_part.stp", "occ22470.igs", "BUC50025.igs", "splinecage.stp"});
    for (const std::string& name : names) {
        const auto path = cad_dir / name;
        if (!std::filesystem::exists(path)) GTEST_SKIP() << "skipped: " << path << " is absent";
        std::vector<exchange::ExactShape> faces;
        std::vector<double> areas;
        const TopoDS_Shape shape = test::read_cad_shape(path);
        for (TopExp_Explorer e(shape, TopAbs_FACE); e.More(); e.Next()) {
            const exchange_occt::Converted c =
                exchange_occt::convert_face(TopoDS::Face(e.Current()));
            const auto* t = c.shape ? std::get_if<geom::TrimmedSurface>(&*c.shape) : nullptr;
            // A face bounded by its surface's whole domain comes in as the surface alone.
            const auto* whole =
                c.shape && c.note.empty() ? std::get_if<geom::Surface>(&*c.shape) : nullptr;
            if (!t && !whole) continue;
            geom::Trim domain_trim;
            if (whole) domain_trim.outer = geom::rectangle_loop(geom::domain(*whole));
            if (t)
                faces.push_back(*t);
            else
                faces.push_back(*whole);
            // 384 pieces a direction: the quadrature's own error on nx9's largest face is 6e-6 at
            // the default 96 and 7e-7 at 192, too close to the 1e-6 compared here.
            areas.push_back(t ? geom::trimmed_area(t->surface, t->trim, 384)
                              : geom::trimmed_area(*whole, domain_trim, 384));
        }
        ASSERT_FALSE(faces.empty()) << name;
        for (const bool step : {true, false}) {
            const auto text =
                step ? exchange::step_text(faces, name) : exchange::iges_text(faces, name);
            ASSERT_TRUE(text) << name << ": " << text.error().message;
            const std::string out = dir.path(step ? "out.stp" : "out.igs");
            std::ofstream(out, std::ios::binary) << *text;
            const TopoDS_Shape back = test::read_cad_shape(out);
            std::size_t k = 0;
            double worst = 0;
            for (TopExp_Explorer e(back, TopAbs_FACE); e.More(); e.Next(), ++k) {
                if (k >= areas.size()) break;
                GProp_GProps props;
                BRepGProp::SurfaceProperties(TopoDS::Face(e.Current()), props, 1e-10);
                const double rel = std::abs(props.Mass() - areas[k]) / areas[k];
                worst = std::max(worst, rel);
                EXPECT_LE(rel, 1e-6)
                    << name << (step ? " STEP" : " IGES") << " face " << k
                    << ": OCCT reads back area " << props.Mass() << ", isoparm wrote " << areas[k];
            }
            EXPECT_EQ(k, areas.size()) << name << (step ? " STEP" : " IGES");
            std::cout << name << (step ? " as STEP: " : " as IGES: ") << k << " of " << areas.size()
                      << " trimmed faces read back, largest area difference " << worst
                      << " relative\n";
            ++checked;
        }
    }
    EXPECT_EQ(checked, 2 * static_cast<int>(names.size()));
}

} // namespace
