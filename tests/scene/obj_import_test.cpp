// A scene's splines through OBJ free-form and back (core/scene/import_document.hpp on
// core/exchange's OBJ reader and writer): byte for byte, and a file with nothing importable is an
// error that says why.
#include <gtest/gtest.h>

#include "core/scene/import_document.hpp"
#include "tests/scene/import_round_trip.hpp"

using namespace isoparm;

namespace {

TEST(ObjImport, AFileWithNothingImportableIsAnErrorThatSaysWhy) {
    const char* text = "v 0 0 0\nv 1 0 0\nv 2 1 0\n"
                       "cstype bezier\ndeg 2\ncurv 0 1 1 2 3\nparm u 0 1\nend\n"
                       "cstype bspline\ncurv 0 0.5 1 2 3\nparm u 0 0 0 1 1 1\nend\n";
    const auto objects = scene::import_text(text, scene::ImportFormat::obj);
    ASSERT_FALSE(objects);
    EXPECT_NE(objects.error().message.find("no curve or surface"), std::string::npos);
}

TEST(ObjImport, EveryGallerySplineGoesOutAndComesBackByteForByte) {
    const int identical =
        test::expect_round_trips(scene::ExportFormat::obj, scene::ImportFormat::obj, true);
    EXPECT_GT(identical, 5);
}

} // namespace
