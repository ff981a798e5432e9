// The `import` op (geom-protocol-2.md, Exchange): OBJ free-form text to curves and surfaces;
// errors at /text (with the line) and /format. The core tests have no OCCT reader installed,
// so IGES and STEP answer that this build cannot read them.
#include <gtest/gtest.h>

#include "core/protocol/protocol.hpp"

using nlohmann::json;

namespace {

json request(const std::string& text, const std::string& format) {
    return {{"op", "import"}, {"text", text}, {"format", format}};
}

TEST(ImportOp, ObjFreeFormGivesCurvesAndSurfacesInFileOrderAndTheSkippedList) {
    const std::string text = "v 0 0 0\nv 1 0 0\nv 2 1 0\nv 3 1 1\n"
                             "cstype bspline\ndeg 1 1\n"
                             "surf 0 1 0 1 1 2 3 4\nparm u 0 0 1 1\nparm v 0 0 1 1\nend\n"
                             "deg 2\ncurv 0 1 1 2 3\nparm u 0 0 0 1 1 1\nend\n"
                             "f 1 2 3\n";
    const json answer = isoparm::protocol::handle_request(request(text, "obj"));
    ASSERT_TRUE(answer.at("ok").get<bool>()) << answer.dump();
    const json& objects = answer.at("objects");
    ASSERT_EQ(objects.size(), 2u);
    EXPECT_TRUE(objects[0].contains("surface"));
    EXPECT_EQ(objects[0]["surface"]["type"], "bspline");
    EXPECT_TRUE(objects[1].contains("curve"));
    EXPECT_EQ(objects[1]["curve"]["degree"], 2);
    const json& skipped = answer.at("skipped");
    ASSERT_EQ(skipped.size(), 1u);
    EXPECT_EQ(skipped[0]["entity"], "1 'f' statement (first at line 15)");
}

TEST(ImportOp, ErrorsNameTheLineOrTheField) {
    json a = isoparm::protocol::handle_request(request("v 0 0 q\n", "obj"));
    ASSERT_FALSE(a.at("ok").get<bool>());
    EXPECT_EQ(a["error"]["code"], "parse");
    EXPECT_EQ(a["error"]["path"], "/text");
    EXPECT_NE(a["error"]["message"].get<std::string>().find("line 1: z 'q'"), std::string::npos);

    a = isoparm::protocol::handle_request(request("", "dxf"));
    EXPECT_EQ(a["error"]["code"], "schema");
    EXPECT_EQ(a["error"]["path"], "/format");

    a = isoparm::protocol::handle_request({{"op", "import"}, {"text", 3}, {"format", "obj"}});
    EXPECT_EQ(a["error"]["path"], "/text");

    a = isoparm::protocol::handle_request(
        {{"op", "import"}, {"text", ""}, {"format", "obj"}, {"name", "x"}});
    EXPECT_EQ(a["error"]["code"], "schema");
    EXPECT_EQ(a["error"]["path"], "/name");

    for (const char* format : {"iges", "step"}) {
        a = isoparm::protocol::handle_request(request("anything", format));
        ASSERT_FALSE(a.at("ok").get<bool>()) << format;
        EXPECT_EQ(a["error"]["path"], "/format") << format;
        EXPECT_NE(a["error"]["message"].get<std::string>().find("without OpenCASCADE"),
                  std::string::npos);
    }
}

} // namespace
