// The real files written by other CAD systems that the OCCT tests read (../shared/cad beside
// the checkout, never committed; tests skip with a message where the folder is absent).
#pragma once

#include <IGESControl_Reader.hxx>
#include <Interface_Static.hxx>
#include <STEPControl_Reader.hxx>
#include <TopoDS_Shape.hxx>
#include <algorithm>
#include <cstdlib>
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

// Under the sanitizers CTest sets ISOPARM_CAD_FILES_EVERY=N (tests/exchange_occt/CMakeLists.txt)
// and the real-file tests read every Nth file only: the sanitizers look for memory and undefined
// behaviour errors along the same code paths at four to six times the cost, while the normal
// build checks every file's figures. 1 (every file) where the variable is absent.
inline std::size_t cad_file_stride() {
    const char* every = std::getenv("ISOPARM_CAD_FILES_EVERY");
    const long n = every ? std::strtol(every, nullptr, 10) : 1;
    return n > 1 ? static_cast<std::size_t>(n) : 1;
}

// While working on one file: ISOPARM_CAD_FILES_ONLY=TEXT keeps the files whose names contain
// TEXT (totals over all files are then not checked: every_cad_file() is false).
inline const char* cad_files_only() {
    const char* only = std::getenv("ISOPARM_CAD_FILES_ONLY");
    return only && *only ? only : nullptr;
}

// True when the tests see every file, so totals over all files can be checked.
inline bool every_cad_file() {
    return cad_file_stride() == 1 && !cad_files_only();
}

// Every cad_file_stride()th name of a list (all of them in the normal build).
inline std::vector<std::string> sampled(const std::vector<std::string>& names) {
    std::vector<std::string> out;
    for (std::size_t i = 0; i < names.size(); i += cad_file_stride()) out.push_back(names[i]);
    return out;
}

// The STEP and IGES files of cad_dir in name order (none where it is absent), every
// cad_file_stride()th under the sanitizers, only those named by ISOPARM_CAD_FILES_ONLY where set.
inline std::vector<std::filesystem::path> cad_files() {
    std::vector<std::filesystem::path> out;
    if (!std::filesystem::is_directory(cad_dir)) return out;
    for (const auto& e : std::filesystem::directory_iterator(cad_dir)) {
        std::string ext = e.path().extension().string();
        std::transform(ext.begin(), ext.end(), ext.begin(), ::tolower);
        const bool named = !cad_files_only() ||
                           e.path().filename().string().find(cad_files_only()) != std::string::npos;
        if (named && (ext == ".igs" || ext == ".iges" || ext == ".stp" || ext == ".step"))
            out.push_back(e.path());
    }
    std::sort(out.begin(), out.end());
    std::vector<std::filesystem::path> kept;
    for (std::size_t i = 0; i < out.size(); i += cad_file_stride()) kept.push_back(out[i]);
    return kept;
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
