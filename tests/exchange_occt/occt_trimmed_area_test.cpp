// Real files written by other CAD systems (../shared/cad, never committed; skipped with a
// message where absent) import as trimmed faces: each face's wires become trim loops on its
// NURBS surface (occt_trim.hpp), and the trimmed area (core/geom/trim/trim_area.hpp) must match
// OpenCASCADE's own area of the face (BRepGProp) within 1e-4 relative. Faces whose loops could
// not be built come in untrimmed with a note; they are counted and named, never compared. Each
// file must keep at least the number of matching faces measured when the test was written.
#include <gtest/gtest.h>

#include <BRepGProp.hxx>
#include <GProp_GProps.hxx>
#include <IGESControl_Reader.hxx>
#include <Interface_Static.hxx>
#include <STEPControl_Reader.hxx>
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
#include "core/geom/trim/trim_area.hpp"
#include "tests/exchange_occt/real_cad_files.hpp"
#include "tests/support/temp_dir.hpp"

using namespace isoparm;

namespace {

using test::cad_dir;
using test::cad_files;

// How many faces of each file import trimmed with OCCT's area, as measured when the test was
// written (2026-11-27, 1172 of 1222): a file that drops below its count fails. The faces that do
// not are printed with the reason: 45 whose loops could not be built (open wires beyond 1e-4 of
// the domain, loops that leave the domain or cross, edges no fit follows), 2 offset faces not
// converted, and 3 planes of trj3 whose area differs by 4.7e-4: there OCCT's BRepGProp is
// itself off (the p-curves' own enclosed area is isoparm's; OCCT's mesher is nearer it).
const std::map<std::string, int> measured_matches = {
    {"BUC50025.igs", 7},
    {"OCC8842_cone_CATIA.igs", 3},
    {"bug22566_test_Bad.igs", 7},
    {"bug22869_Spring.igs", 3},
    {"bug24283_spheres.stp", 1},
    {"bug24595_281390.stp", 19},
    {"bug32596_abc_0_13.step", 91},
    {"catiav5_Ventilator.stp", 285},
    {"ec_turbine-A.stp", 50},
    {"hammer.iges", 41},
    {"nx9_face_recognition_sample_part.stp", 23},
    {"occ22470.igs", 18},
    {"splinecage.stp", 4},
    {"sw2013_featuretype.STEP", 96},
    {"trj2_as1-tc-214.stp", 160},
    {"trj3_s1-ct-214.stp", 175},
    {"trj3_s1-id-203.stp", 134},
    {"trj7_k1-al-214.stp", 55},
};

struct FileAreas {
    int faces = 0, trimmed = 0, untrimmed = 0, skipped = 0, match = 0;
    std::vector<std::string> mismatches, notes;
};

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
        if (!t) {
            ++r.untrimmed;
            r.notes.push_back("face " + std::to_string(index) + ": " + c.note);
            continue;
        }
        ++r.trimmed;
        GProp_GProps props;
        BRepGProp::SurfaceProperties(face, props, 1e-10);
        const double occt = props.Mass();
        const double ours = geom::trimmed_area(t->surface, t->trim);
        const double rel = std::abs(ours - occt) / std::max(std::abs(occt), 1e-300);
        if (rel <= 1e-4)
            ++r.match;
        else
            r.mismatches.push_back("face " + std::to_string(index) + ": area " +
                                   std::to_string(ours) + ", OCCT " + std::to_string(occt) + " (" +
                                   std::to_string(rel) + " relative)");
    }
    return r;
}

TEST(RealCadFilesTrimmed, FacesImportTrimmedWithOcctsAreas) {
    const auto files = cad_files();
    if (files.empty())
        GTEST_SKIP() << "skipped: no real CAD files in " << cad_dir << " (../shared/cad)";
    int faces = 0, trimmed = 0, match = 0;
    for (const auto& file : files) {
        const auto start = std::chrono::steady_clock::now();
        const FileAreas r = check_areas(file);
        const double seconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        const std::string name = file.filename().string();
        faces += r.faces;
        trimmed += r.trimmed;
        match += r.match;
        std::cout << name << ": " << r.match << " of " << r.faces
                  << " faces trimmed with OCCT's area within 1e-4 (" << r.trimmed << " trimmed, "
                  << r.untrimmed << " without their loops, " << r.skipped << " not converted; "
                  << seconds << " s)\n";
        for (const std::string& m : r.mismatches) std::cout << "  area differs: " << m << "\n";
        if (const auto it = measured_matches.find(name); it != measured_matches.end()) {
            EXPECT_GE(r.match, it->second)
                << name << ": fewer faces match OCCT's area than the " << it->second << " measured";
        }
        for (const std::string& n : r.notes) std::cout << "  untrimmed: " << n << "\n";
    }
    std::cout << "all files: " << match << " of " << faces << " faces trimmed and matching\n";
    if (!test::every_cad_file()) return; // the totals need every file (real_cad_files.hpp)
    EXPECT_GT(faces, 1000);
    EXPECT_GE(match, 1172) << "of " << faces << " faces (" << trimmed << " trimmed)";
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
            if (!t) continue;
            faces.push_back(*t);
            // 384 pieces a direction: the quadrature's own error on nx9's largest face is 6e-6 at
            // the default 96 and 7e-7 at 192, too close to the 1e-6 compared here.
            areas.push_back(geom::trimmed_area(t->surface, t->trim, 384));
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
