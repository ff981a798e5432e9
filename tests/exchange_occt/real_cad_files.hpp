// The real files written by other CAD systems that the OCCT tests read (../shared/cad beside
// the checkout, never committed; tests skip with a message where the folder is absent).
#pragma once

#include <IGESControl_Reader.hxx>
#include <Interface_Static.hxx>
#include <STEPControl_Reader.hxx>
#include <TopoDS_Shape.hxx>
#include <algorithm>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

namespace isoparm::test {

inline const std::filesystem::path cad_dir = ISOPARM_CAD_DIR;

inline bool is_iges(const std::filesystem::path& p) {
    std::string e = p.extension().string();
    std::transform(e.begin(), e.end(), e.begin(), ::tolower);
    return e == ".igs" || e == ".iges";
}

// The STEP and IGES files of cad_dir in name order (none where it is absent).
inline std::vector<std::filesystem::path> cad_files() {
    std::vector<std::filesystem::path> out;
    if (!std::filesystem::is_directory(cad_dir)) return out;
    for (const auto& e : std::filesystem::directory_iterator(cad_dir)) {
        std::string ext = e.path().extension().string();
        std::transform(ext.begin(), ext.end(), ext.begin(), ::tolower);
        if (ext == ".igs" || ext == ".iges" || ext == ".stp" || ext == ".step")
            out.push_back(e.path());
    }
    std::sort(out.begin(), out.end());
    return out;
}

// The file read by OCCT here in the test (these files are known to read), as one shape.
inline TopoDS_Shape read_cad_shape(const std::filesystem::path& file) {
    std::unique_ptr<XSControl_Reader> reader;
    if (is_iges(file)) {
        reader = std::make_unique<IGESControl_Reader>();
        Interface_Static::SetIVal("read.iges.bspline.continuity", 0);
    } else {
        reader = std::make_unique<STEPControl_Reader>();
    }
    if (reader->ReadFile(file.c_str()) != IFSelect_RetDone) return {};
    reader->TransferRoots();
    return reader->OneShape();
}

} // namespace isoparm::test
