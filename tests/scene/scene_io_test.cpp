// Scene files: exact round trips, errors with the right code and path, atomic saving.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <limits>
#include <random>
#include <sstream>
#include <sys/stat.h>
#include <unistd.h>

#include <nlohmann/json.hpp>

#include "core/scene/scene_io.hpp"
#include "tests/doc/doc_fixtures.hpp"

using namespace isoparm;
using namespace isoparm::doc;
using namespace isoparm::scene;
using namespace isoparm::doc::testing;
using geom::ErrorCode;
using nlohmann::json;
namespace fs = std::filesystem;

namespace {

// A fresh directory per test, removed afterwards.
class TempDir {
public:
    TempDir() {
        const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
        path_ = fs::temp_directory_path() /
                ("isoparm-scene-" + std::to_string(::getpid()) + "-" + info->name());
        fs::remove_all(path_);
        fs::create_directories(path_);
    }
    ~TempDir() {
        std::error_code ec;
        fs::remove_all(path_, ec);
    }
    std::string file(const std::string& name) const { return (path_ / name).string(); }
    const fs::path& path() const { return path_; }
    std::vector<std::string> entries() const {
        std::vector<std::string> out;
        for (const auto& e : fs::directory_iterator(path_)) out.push_back(e.path().filename());
        std::sort(out.begin(), out.end());
        return out;
    }

private:
    fs::path path_;
};

std::string read_file(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

void write_file(const std::string& path, const std::string& text) {
    std::ofstream out(path, std::ios::binary);
    out << text;
}

Document round_trip(const Document& doc) {
    auto back = scene_from_text(scene_to_text(doc));
    EXPECT_TRUE(back.ok()) << (back.ok() ? "" : back.error().path + ": " + back.error().message);
    return back.ok() ? std::move(back).value() : Document{};
}

void expect_error(const std::string& text, ErrorCode code, const std::string& path) {
    auto doc = scene_from_text(text);
    ASSERT_FALSE(doc.ok()) << text;
    EXPECT_EQ(std::string(geom::name_of(doc.error().code)), geom::name_of(code))
        << doc.error().path << ": " << doc.error().message;
    EXPECT_TRUE(doc.error().has_path);
    EXPECT_EQ(doc.error().path, path) << doc.error().message;
    EXPECT_FALSE(doc.error().message.empty());
}

// A valid scene with one object, to be broken in one place by each test.
std::string scene_with(const std::string& object, const std::string& extra = "") {
    return R"({"format": "isoparm-scene", "version": 1, "objects": [)" + object + "]" + extra + "}";
}

const std::string good_surface =
    R"({"name": "s", "kind": "surface", "surface": {"type": "nurbs", "degree": [1, 1],
        "knots": [[0, 0, 1, 1], [0, 0, 1, 1]],
        "points": [[[0, 0, 0], [0, 1, 0]], [[1, 0, 0], [1, 1, 1]]],
        "weights": [[1, 1], [1, 2]]}})";

TEST(SceneRoundTrip, DefaultDocumentIsBitIdentical) {
    const Document doc = default_document();
    const Document back = round_trip(doc);
    EXPECT_TRUE(same_document(doc, back));
    EXPECT_EQ(back.next_id, doc.next_id);
}

TEST(SceneRoundTrip, EveryKindOfObject) {
    Document doc = sample_document();
    doc.view.selection = Selection{curve_id, 3, -1};
    doc.view.indicator = {0.25, 1.0};
    doc.view.display.style = DisplayStyle::wireframe;
    doc.view.display.point_ids = true;
    doc.view.display.density = 7;
    doc.objects[1].name = "prof\"ile / ~ é";
    std::get<CurveObject>(doc.objects[1].shape).plane = CurvePlane::free3d;
    const Document back = round_trip(doc);
    EXPECT_TRUE(same_document(doc, back));
    EXPECT_EQ(back.next_id, 6u);
}

TEST(SceneRoundTrip, AwkwardNumbersSurviveExactly) {
    Document doc = sample_document();
    auto& s = std::get<SurfaceObject>(doc.objects[0].shape).surface;
    s.point(0, 0) = {-0.0, 0.1 + 0.2, 5e-324};
    s.point(0, 1) = {1e-300, -1.7976931348623157e308, 123456789.123456789};
    s.point(0, 2) = {1e16, 1e22, 2.5e-5};
    s.weight(0, 0) = -0.0;
    s.weight(0, 1) = -3e-310;
    s.weight(4, 4) = 1.0 / 3.0;
    std::mt19937_64 rng(42);
    std::uniform_real_distribution<double> d(-10, 10);
    for (int j = 0; j < 5; ++j) s.point(3, j) = {d(rng), d(rng), std::ldexp(d(rng), -40)};
    auto& f = std::get<ImplicitObject>(doc.objects[4].shape);
    f.parameter_values[0] = 0.1 + 0.7;
    const Document back = round_trip(doc);
    EXPECT_TRUE(same_document(doc, back));
    EXPECT_TRUE(std::signbit(std::get<SurfaceObject>(back.objects[0].shape).surface.point(0, 0).x));
}

TEST(SceneRoundTrip, ColoursAreExactFloatsWrittenShort) {
    Document doc = default_document();
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> d(0.0f, 1.0f);
    for (int k = 0; k < 2000; ++k) {
        doc.colors.background = {d(rng), d(rng), d(rng), d(rng)};
        doc.colors.indicator = {d(rng), 0.0f, 1.0f, d(rng)};
        ASSERT_TRUE(same_document(doc, round_trip(doc))) << k;
    }
    // Default colours are written as their short decimals, not as widened floats.
    const std::string text = scene_to_text(default_document());
    EXPECT_NE(text.find("0.13"), std::string::npos);
    EXPECT_EQ(text.find("0.129999"), std::string::npos);
}

TEST(SceneRoundTrip, SaveAndLoadFile) {
    TempDir dir;
    const Document doc = sample_document();
    ASSERT_TRUE(save_scene(doc, dir.file("scene.json")).ok());
    auto back = load_scene(dir.file("scene.json"));
    ASSERT_TRUE(back.ok()) << back.error().message;
    EXPECT_TRUE(same_document(doc, *back));
    EXPECT_EQ(read_file(dir.file("scene.json")), scene_to_text(doc));
}

TEST(SceneRoundTrip, AfterEditsAndSplits) {
    Document doc = sample_document();
    History h;
    ASSERT_TRUE(h.execute(doc, split_object(hill_id, geom::Dir::u, 0.75)).ok());
    ASSERT_TRUE(h.execute(doc, insert_knot(grid_id, geom::Dir::v, 0.3, 2)).ok());
    ASSERT_TRUE(h.execute(doc, elevate_degree(curve_id, geom::Dir::u)).ok());
    ASSERT_TRUE(h.execute(doc, set_weight(6, 1, 1, -0.0)).ok());
    const Document back = round_trip(doc);
    EXPECT_TRUE(same_document(doc, back));
    EXPECT_EQ(back.next_id, doc.next_id);
}

TEST(SceneRead, OptionalMembersTakeDefaults) {
    auto doc = scene_from_text(scene_with(good_surface));
    ASSERT_TRUE(doc.ok()) << doc.error().message;
    EXPECT_EQ(doc->objects.size(), 1u);
    EXPECT_EQ(doc->objects[0].id, 1u);
    EXPECT_TRUE(doc->objects[0].visible);
    EXPECT_EQ(doc->colors, Colors{});
    EXPECT_EQ(doc->view.display, DisplaySettings{});
    EXPECT_EQ(doc->view.selection, Selection{});
    EXPECT_EQ(doc->next_id, 2u);
}

TEST(SceneRead, MissingIdsComeAfterTheLargestGiven) {
    const std::string a = good_surface;
    std::string b = good_surface;
    b.insert(1, R"("id": 40, )");
    auto doc = scene_from_text(scene_with(a + ", " + b + ", " + a));
    ASSERT_TRUE(doc.ok()) << doc.error().message;
    EXPECT_EQ(doc->objects[0].id, 41u);
    EXPECT_EQ(doc->objects[1].id, 40u);
    EXPECT_EQ(doc->objects[2].id, 42u);
    EXPECT_EQ(doc->next_id, 43u);
}

TEST(SceneRead, BezierMayOmitKnots) {
    auto doc = scene_from_text(scene_with(
        R"({"name": "b", "kind": "curve", "curve": {"type": "bezier", "degree": 2,
            "points": [[0, 0], [1, 1], [2, 0]]}})"));
    ASSERT_TRUE(doc.ok()) << doc.error().message;
    EXPECT_EQ(curve_of(*doc, 1).knots, (geom::Knots{0, 0, 0, 1, 1, 1}));
}

TEST(SceneRead, TopLevelErrors) {
    expect_error("[]", ErrorCode::schema, "");
    expect_error(R"({"version": 1, "objects": []})", ErrorCode::schema, "/format");
    expect_error(R"({"format": "obj", "version": 1, "objects": []})", ErrorCode::schema, "/format");
    expect_error(R"({"format": "isoparm-scene", "objects": []})", ErrorCode::schema, "/version");
    expect_error(R"({"format": "isoparm-scene", "version": "1", "objects": []})", ErrorCode::schema,
                 "/version");
    expect_error(R"({"format": "isoparm-scene", "version": 0, "objects": []})", ErrorCode::schema,
                 "/version");
    expect_error(R"({"format": "isoparm-scene", "version": 1})", ErrorCode::schema, "/objects");
    expect_error(R"({"format": "isoparm-scene", "version": 1, "objects": {}})", ErrorCode::schema,
                 "/objects");
    expect_error(scene_with("", R"(, "camera": [0, 0, 1])"), ErrorCode::schema, "/camera");
}

TEST(SceneRead, NewerVersionIsRefusedBeforeItsNewMembers) {
    auto doc = scene_from_text(
        R"({"format": "isoparm-scene", "version": 4, "objects": [], "patches": []})");
    ASSERT_FALSE(doc.ok());
    EXPECT_EQ(doc.error().path, "/version");
    EXPECT_NE(doc.error().message.find("version 4"), std::string::npos) << doc.error().message;
}

// good_surface's domain [0, 1]^2 kept inside a square, less a square hole (clockwise).
const std::string good_trim =
    R"("trim": {"outer": [{"type": "bspline", "degree": 1, "knots": [0, 0, 1, 2, 3, 4, 4],
                          "points": [[0.1, 0.1], [0.9, 0.1], [0.9, 0.9], [0.1, 0.9], [0.1, 0.1]]}],
                "holes": [[{"type": "bspline", "degree": 1, "knots": [0, 0, 1, 2, 3, 4, 4],
                          "points": [[0.4, 0.4], [0.4, 0.6], [0.6, 0.6], [0.6, 0.4], [0.4, 0.4]]}]]})";

std::string trimmed_surface(const std::string& trim) {
    return good_surface.substr(0, good_surface.size() - 1) + ", " + trim + "}";
}

TEST(SceneTrim, ATrimmedSurfaceRoundTripsAsVersionThreeAndAnUntrimmedOneAsBefore) {
    auto doc = scene_from_text(R"({"format": "isoparm-scene", "version": 3, "objects": [)" +
                               trimmed_surface(good_trim) + "]}");
    ASSERT_TRUE(doc.ok()) << doc.error().path << ": " << doc.error().message;
    const geom::Trim* trim = trim_of(doc->objects[0].shape);
    ASSERT_NE(trim, nullptr);
    EXPECT_TRUE(trim->outer.has_value());
    EXPECT_EQ(trim->holes.size(), 1u);
    const json written = json::parse(scene_to_text(*doc));
    EXPECT_EQ(written.at("version"), 3);
    EXPECT_TRUE(written.at("objects").at(0).contains("trim"));
    EXPECT_TRUE(same_document(*doc, round_trip(*doc)));
    // Without the trim the same scene writes version 1 and no "trim" member.
    std::get<SurfaceObject>(doc->objects[0].shape).trim = {};
    const json plain = json::parse(scene_to_text(*doc));
    EXPECT_EQ(plain.at("version"), 1);
    EXPECT_FALSE(plain.at("objects").at(0).contains("trim"));
}

TEST(SceneTrim, ATrimNeedsVersionThreeAndValidLoops) {
    expect_error(scene_with(trimmed_surface(good_trim)), ErrorCode::schema, "/objects/0/trim");
    const auto v3 = [](const std::string& object) {
        return R"({"format": "isoparm-scene", "version": 3, "objects": [)" + object + "]}";
    };
    // The outer loop run clockwise: named at the loop.
    std::string clockwise = good_trim;
    const std::string ccw = "[[0.1, 0.1], [0.9, 0.1], [0.9, 0.9], [0.1, 0.9], [0.1, 0.1]]";
    clockwise.replace(clockwise.find(ccw), ccw.size(),
                      "[[0.1, 0.1], [0.1, 0.9], [0.9, 0.9], [0.9, 0.1], [0.1, 0.1]]");
    auto doc = scene_from_text(v3(trimmed_surface(clockwise)));
    ASSERT_FALSE(doc.ok());
    EXPECT_EQ(doc.error().path.rfind("/objects/0/trim/outer", 0), 0u) << doc.error().path;
    EXPECT_NE(doc.error().message.find("outer loop"), std::string::npos) << doc.error().message;
    // A hole that is not closed.
    std::string open = good_trim;
    open.replace(open.rfind("[0.4, 0.4]]"), 11, "[0.45, 0.4]]");
    doc = scene_from_text(v3(trimmed_surface(open)));
    ASSERT_FALSE(doc.ok());
    EXPECT_EQ(doc.error().path.rfind("/objects/0/trim/holes/0", 0), 0u) << doc.error().path;
    // A trim on another kind of object is an unknown member there.
    const std::string curve =
        R"({"name": "c", "kind": "curve", "curve": {"type": "bspline", "degree": 1,
            "knots": [0, 0, 1, 1], "points": [[0, 0, 0], [1, 0, 0]]}, )" +
        good_trim + "}";
    doc = scene_from_text(v3(curve));
    ASSERT_FALSE(doc.ok());
}

TEST(SceneRead, ObjectErrors) {
    expect_error(scene_with("3"), ErrorCode::schema, "/objects/0");
    expect_error(scene_with(R"({"name": "a", "surface": {}})"), ErrorCode::schema,
                 "/objects/0/kind");
    expect_error(scene_with(R"({"name": "a", "kind": "mesh"})"), ErrorCode::schema,
                 "/objects/0/kind");
    expect_error(scene_with(R"({"name": "a", "kind": "surface"})"), ErrorCode::schema,
                 "/objects/0/surface");
    expect_error(scene_with(R"({"kind": "surface", "surface": {}})"), ErrorCode::schema,
                 "/objects/0/name");
    expect_error(scene_with(R"({"name": "", "kind": "implicit", "implicit": {"expression": "x"}})"),
                 ErrorCode::schema, "/objects/0/name");
    expect_error(scene_with(R"({"name": 5, "kind": "implicit", "implicit": {"expression": "x"}})"),
                 ErrorCode::schema, "/objects/0/name");
    // A member of another kind is a typo here.
    expect_error(scene_with(R"({"name": "a", "kind": "surface", "curve": {}})"), ErrorCode::schema,
                 "/objects/0/curve");
    expect_error(scene_with(R"({"name": "a", "kind": "surface", "plane": "xy"})"),
                 ErrorCode::schema, "/objects/0/plane");
    std::string s = good_surface;
    s.insert(1, R"("visible": "yes", )");
    expect_error(scene_with(s), ErrorCode::schema, "/objects/0/visible");
    s = good_surface;
    s.insert(1, R"("id": 0, )");
    expect_error(scene_with(s), ErrorCode::schema, "/objects/0/id");
    s = good_surface;
    s.insert(1, R"("id": 1.5, )");
    expect_error(scene_with(s), ErrorCode::schema, "/objects/0/id");
    s = good_surface;
    s.insert(1, R"("id": 3, )");
    expect_error(scene_with(s + ", " + s), ErrorCode::schema, "/objects/1/id");
    expect_error(scene_with(R"({"name": "c", "kind": "curve", "plane": "uv", "curve": {"degree": 1,
                 "knots": [0, 0, 1, 1], "points": [[0, 0], [1, 1]]}})"),
                 ErrorCode::schema, "/objects/0/plane");
}

TEST(SceneRead, GeometryErrorsCarryTheScenePath) {
    // Knot vector u decreasing at knot 3.
    expect_error(scene_with(good_surface + ", " +
                            R"({"name": "t", "kind": "surface", "surface": {"degree": [1, 1],
        "knots": [[0, 0, 0.5, 0.4, 1, 1], [0, 0, 1, 1]],
        "points": [[[0, 0, 0], [0, 1, 0]], [[1, 0, 0], [1, 1, 1]], [[2, 0, 0], [2, 1, 0]],
                   [[3, 0, 0], [3, 1, 0]]]}})"),
                 ErrorCode::knots, "/objects/1/surface/knots/0/3");
    // A weight that overflows to infinity is a weights error at that weight.
    std::string s = good_surface;
    s.replace(s.find("[1, 2]"), 6, "[1, 1e999]");
    expect_error(scene_with(s), ErrorCode::weights, "/objects/0/surface/weights/1/1");
    // A B-spline takes no weights.
    s = good_surface;
    s.replace(s.find("nurbs"), 5, "bspline");
    expect_error(scene_with(s), ErrorCode::schema, "/objects/0/surface/weights");
    s = good_surface;
    s.replace(s.find("\"points\""), 8, "\"pts\"");
    expect_error(scene_with(s), ErrorCode::schema, "/objects/0/surface/pts");
    expect_error(scene_with(R"({"name": "c", "kind": "curve", "curve": {"degree": 3,
                 "knots": [0, 0, 1, 1], "points": [[0, 0], [1, 1]]}})"),
                 ErrorCode::degree, "/objects/0/curve/degree");
}

TEST(SceneRead, ImplicitErrors) {
    auto implicit = [](const std::string& body) {
        return scene_with(R"({"name": "f", "kind": "implicit", "implicit": )" + body + "}");
    };
    expect_error(implicit("{}"), ErrorCode::schema, "/objects/0/implicit/expression");
    expect_error(implicit(R"({"expression": 3})"), ErrorCode::schema,
                 "/objects/0/implicit/expression");
    expect_error(implicit(R"({"expression": "  "})"), ErrorCode::parse,
                 "/objects/0/implicit/expression");
    expect_error(implicit(R"({"expression": "x + (y"})"), ErrorCode::parse,
                 "/objects/0/implicit/expression");
    expect_error(implicit(R"({"expression": "x + a"})"), ErrorCode::parse,
                 "/objects/0/implicit/expression");
    expect_error(implicit(R"({"expression": "x", "cell": 0})"), ErrorCode::schema,
                 "/objects/0/implicit/cell");
    expect_error(implicit(R"({"expression": "x", "cell": 1e999})"), ErrorCode::schema,
                 "/objects/0/implicit/cell");
    expect_error(implicit(R"({"expression": "x", "bounds": [[0, 0, 0], [1, 1]]})"),
                 ErrorCode::schema, "/objects/0/implicit/bounds/1");
    expect_error(implicit(R"({"expression": "x", "bounds": [[0, 0, 0], [1, -1, 1]]})"),
                 ErrorCode::schema, "/objects/0/implicit/bounds/1/1");
    expect_error(implicit(R"({"expression": "x", "parameters": [{"name": "a"}]})"),
                 ErrorCode::schema, "/objects/0/implicit/parameters/0/value");
    expect_error(implicit(R"({"expression": "x", "parameters": [{"name": "a", "value": 1},
                 {"name": "a", "value": 2}]})"),
                 ErrorCode::schema, "/objects/0/implicit/parameters/1/name");
    expect_error(implicit(R"({"expression": "x", "parameters": [{"name": "sin", "value": 1}]})"),
                 ErrorCode::schema, "/objects/0/implicit/parameters/0/name");
    expect_error(implicit(R"({"expression": "x", "colour": 1})"), ErrorCode::schema,
                 "/objects/0/implicit/colour");
}

TEST(SceneRead, ViewStateErrors) {
    expect_error(scene_with(good_surface, R"(, "indicator": [0.5])"), ErrorCode::schema,
                 "/indicator");
    expect_error(scene_with(good_surface, R"(, "indicator": [1.5, 0])"), ErrorCode::schema,
                 "/indicator/0");
    expect_error(scene_with(good_surface, R"(, "indicator": [0, 1e999])"), ErrorCode::schema,
                 "/indicator/1");
    expect_error(scene_with(good_surface, R"(, "colors": {"background": [2, 0, 0]})"),
                 ErrorCode::schema, "/colors/background/0");
    expect_error(scene_with(good_surface, R"(, "colors": {"background": [0, 0]})"),
                 ErrorCode::schema, "/colors/background");
    expect_error(scene_with(good_surface, R"(, "colors": {"foreground": [0, 0, 0]})"),
                 ErrorCode::schema, "/colors/foreground");
    expect_error(scene_with(good_surface, R"(, "display": {"density": 0})"), ErrorCode::schema,
                 "/display/density");
    expect_error(scene_with(good_surface, R"(, "display": {"style": "toon"})"), ErrorCode::schema,
                 "/display/style");
    expect_error(scene_with(good_surface, R"(, "display": {"wire": true})"), ErrorCode::schema,
                 "/display/wire");
    expect_error(scene_with(good_surface, R"(, "display": {"deboor": 1})"), ErrorCode::schema,
                 "/display/deboor");
    expect_error(scene_with(good_surface, R"(, "selection": {"object": 9})"), ErrorCode::schema,
                 "/selection/object");
    expect_error(scene_with(good_surface, R"(, "selection": {"object": 1, "point": [0, 2]})"),
                 ErrorCode::schema, "/selection/point/1");
    expect_error(scene_with(good_surface, R"(, "selection": {"object": 1, "point": [0]})"),
                 ErrorCode::schema, "/selection/point");
    expect_error(scene_with(good_surface, R"(, "selection": {"object": 1, "i": 0})"),
                 ErrorCode::schema, "/selection/i");
    auto ok = scene_from_text(scene_with(good_surface, R"(, "selection": null,
                              "colors": {"surface": [0.5, 0.5, 0.5]})"));
    ASSERT_TRUE(ok.ok()) << ok.error().message;
    EXPECT_EQ(ok->colors.surface, (Rgba{0.5f, 0.5f, 0.5f, 1.0f}));
}

TEST(SceneRead, TextProblems) {
    auto doc = scene_from_text("{\"format\": \"isoparm-scene\",\n  \"version\": 1,, }");
    ASSERT_FALSE(doc.ok());
    EXPECT_EQ(doc.error().code, ErrorCode::parse);
    EXPECT_FALSE(doc.error().has_path);
    EXPECT_NE(doc.error().message.find("line 2"), std::string::npos) << doc.error().message;
    EXPECT_NE(doc.error().message.find("column"), std::string::npos) << doc.error().message;
    EXPECT_FALSE(scene_from_text("").ok());
    EXPECT_FALSE(scene_from_text("\xff\xfe").ok());
    // Duplicate keys are refused, not silently resolved.
    expect_error(scene_with(good_surface, R"(, "indicator": [0, 0], "indicator": [1, 1])"),
                 ErrorCode::schema, "/indicator");
    // Hostile nesting is a limit, not a stack overflow.
    const std::string deep = std::string(100000, '[') + std::string(100000, ']');
    auto d = scene_from_text(scene_with("", R"(, "x": )" + deep));
    ASSERT_FALSE(d.ok());
    EXPECT_EQ(d.error().code, ErrorCode::limit);
}

// Damaged scenes (deterministic random edits of a valid one) never crash the reader; whatever
// still loads saves and loads again to the same document.
TEST(SceneRead, DamagedScenesAreRefusedOrLoadConsistently) {
    Document base = sample_document();
    base.view.selection = Selection{curve_id, 2, -1};
    const std::string text = scene_to_text(base);
    const std::vector<std::string> tokens = {"1e999",
                                             "-1e999",
                                             "-0",
                                             "null",
                                             "[]",
                                             "{}",
                                             "\"",
                                             ",",
                                             "]",
                                             "}",
                                             "0",
                                             "-1",
                                             "2",
                                             "1.5",
                                             "true",
                                             "9e18",
                                             "18446744073709551616",
                                             "\"x\"",
                                             "[[0, 0, 0]]",
                                             "\"nurbs\"",
                                             "\"bezier\"",
                                             "4097"};
    std::mt19937 rng(2024);
    int loaded = 0;
    for (int round = 0; round < 3000; ++round) {
        std::string t = text;
        const int edits = 1 + static_cast<int>(rng() % 3);
        for (int e = 0; e < edits && !t.empty(); ++e) {
            const std::size_t at = rng() % t.size();
            const std::size_t len = 1 + rng() % 12;
            switch (rng() % 4) {
            case 0:
                t.erase(at, len);
                break;
            case 1:
                t.insert(at, tokens[rng() % tokens.size()]);
                break;
            case 2:
                t.replace(at, std::min(len, t.size() - at), tokens[rng() % tokens.size()]);
                break;
            default:
                t[at] = static_cast<char>(rng() % 256);
                break;
            }
        }
        auto doc = scene_from_text(t);
        if (!doc) {
            EXPECT_FALSE(doc.error().message.empty());
            continue;
        }
        ++loaded;
        auto again = scene_from_text(scene_to_text(*doc));
        ASSERT_TRUE(again.ok()) << again.error().path << ": " << again.error().message << "\n" << t;
        EXPECT_TRUE(same_document(*doc, *again)) << t;
    }
    EXPECT_GT(loaded, 0); // some edits (inside numbers, names) leave a valid scene
}

TEST(SceneFile, LoadReportsUnreadableAndNonJsonFiles) {
    TempDir dir;
    auto missing = load_scene(dir.file("nope.json"));
    ASSERT_FALSE(missing.ok());
    EXPECT_FALSE(missing.error().has_path);
    EXPECT_NE(missing.error().message.find("nope.json"), std::string::npos);
    auto directory = load_scene(dir.path().string());
    ASSERT_FALSE(directory.ok());
    write_file(dir.file("bad.json"), "{\n\n  oops }");
    auto bad = load_scene(dir.file("bad.json"));
    ASSERT_FALSE(bad.ok());
    EXPECT_EQ(bad.error().code, ErrorCode::parse);
    EXPECT_NE(bad.error().message.find("bad.json"), std::string::npos) << bad.error().message;
    EXPECT_NE(bad.error().message.find("line 3"), std::string::npos) << bad.error().message;
    write_file(dir.file("sem.json"), scene_with(R"({"name": "a", "kind": "mesh"})"));
    auto sem = load_scene(dir.file("sem.json"));
    ASSERT_FALSE(sem.ok());
    EXPECT_EQ(sem.error().path, "/objects/0/kind");
}

TEST(SceneFile, SaveReplacesAtomicallyAndLeavesNoTemporaryFile) {
    TempDir dir;
    const std::string path = dir.file("scene.json");
    Document doc = default_document();
    ASSERT_TRUE(save_scene(doc, path).ok());
    EXPECT_EQ(dir.entries(), std::vector<std::string>{"scene.json"});
    doc.objects[0].name = "second";
    ASSERT_TRUE(save_scene(doc, path).ok());
    EXPECT_EQ(dir.entries(), std::vector<std::string>{"scene.json"});
    auto back = load_scene(path);
    ASSERT_TRUE(back.ok());
    EXPECT_EQ(back->objects[0].name, "second");
}

TEST(SceneFile, FailedSaveKeepsTheOldFileAndRemovesTheTemporary) {
    TempDir dir;
    // The target is a directory: the rename fails after the temporary file was written.
    fs::create_directory(dir.file("scene.json"));
    write_file(dir.file("scene.json") + "/keep", "old");
    auto st = save_scene(default_document(), dir.file("scene.json"));
    ASSERT_FALSE(st.ok());
    EXPECT_EQ(st.error().code, ErrorCode::internal);
    EXPECT_NE(st.error().message.find("scene.json"), std::string::npos) << st.error().message;
    EXPECT_EQ(dir.entries(), std::vector<std::string>{"scene.json"});
    EXPECT_EQ(read_file(dir.file("scene.json") + "/keep"), "old");
    // A directory that does not exist: nothing is created.
    st = save_scene(default_document(), dir.file("missing/scene.json"));
    ASSERT_FALSE(st.ok());
    EXPECT_EQ(dir.entries(), std::vector<std::string>{"scene.json"});
}

TEST(SceneFile, SaveKeepsPermissionsAndFollowsSymlinks) {
    TempDir dir;
    const std::string real = dir.file("real.json");
    ASSERT_TRUE(save_scene(default_document(), real).ok());
    ASSERT_EQ(::chmod(real.c_str(), 0640), 0);
    fs::create_symlink("real.json", dir.file("link.json"));
    Document doc = default_document();
    doc.objects[0].name = "through the link";
    ASSERT_TRUE(save_scene(doc, dir.file("link.json")).ok());
    EXPECT_TRUE(fs::is_symlink(dir.file("link.json")));
    auto back = load_scene(real);
    ASSERT_TRUE(back.ok());
    EXPECT_EQ(back->objects[0].name, "through the link");
    struct stat st {};
    ASSERT_EQ(::stat(real.c_str(), &st), 0);
    EXPECT_EQ(st.st_mode & 0777, 0640u);
    EXPECT_EQ(dir.entries(), (std::vector<std::string>{"link.json", "real.json"}));
}

// Every ```json example in docs/scene-format.md loads, so the documentation stays true.
TEST(SceneFormatDoc, ExamplesLoad) {
    const std::string doc_text =
        read_file(std::string(ISOPARM_SOURCE_DIR) + "/docs/scene-format.md");
    ASSERT_FALSE(doc_text.empty());
    int examples = 0;
    std::size_t at = 0;
    while ((at = doc_text.find("```json\n", at)) != std::string::npos) {
        const std::size_t start = at + 8;
        const std::size_t end = doc_text.find("```", start);
        ASSERT_NE(end, std::string::npos);
        const std::string block = doc_text.substr(start, end - start);
        at = end + 3;
        if (block.find("\"format\"") == std::string::npos) continue; // fragments
        ++examples;
        auto scene = scene_from_text(block);
        EXPECT_TRUE(scene.ok()) << (scene.ok() ? ""
                                               : scene.error().path + ": " + scene.error().message)
                                << "\n"
                                << block;
    }
    EXPECT_GE(examples, 3);
}

} // namespace

TEST(SceneObjectDisplay, AnObjectsOwnTogglesRoundTripInVersionTwo) {
    Document doc = sample_document();
    // A scene without own displays stays version 1, as older builds wrote it.
    EXPECT_NE(scene_to_text(doc).find("\"version\": 1"), std::string::npos);
    doc.view.display.control_points = true;
    doc.view.object_display[doc.objects[0].id] = ObjectDisplay{false, true, true, false};
    const std::string text = scene_to_text(doc);
    EXPECT_NE(text.find("\"version\": 2"), std::string::npos);
    const Document back = round_trip(doc);
    EXPECT_TRUE(same_document(doc, back));
    EXPECT_FALSE(display_of(back.view, doc.objects[0].id).control_points);
    EXPECT_TRUE(display_of(back.view, doc.objects[0].id).point_ids);
    // The others take the scene's defaults.
    EXPECT_TRUE(display_of(back.view, doc.objects[1].id).control_points);
}

TEST(SceneObjectDisplay, VersionOneOrBadMembersAreRefusedWithTheirPath) {
    const std::string object = R"({"name": "s", "kind": "surface", "display": {"point_ids": true},
        "surface": {"type": "nurbs", "degree": [1, 1], "knots": [[0, 0, 1, 1], [0, 0, 1, 1]],
        "points": [[[0, 0, 0], [0, 1, 0]], [[1, 0, 0], [1, 1, 1]]],
        "weights": [[1, 1], [1, 2]]}})";
    auto scene = [&](int version, const std::string& o) {
        return R"({"format": "isoparm-scene", "version": )" + std::to_string(version) +
               R"(, "objects": [)" + o + "]}";
    };
    const auto v1 = scene_from_text(scene(1, object));
    ASSERT_FALSE(v1);
    EXPECT_EQ(v1.error().path, "/objects/0/display");
    const auto v2 = scene_from_text(scene(2, object));
    ASSERT_TRUE(v2) << v2.error().message;
    EXPECT_TRUE(display_of(v2->view, v2->objects[0].id).point_ids);
    std::string bad = object;
    bad.replace(bad.find("point_ids"), 9, "point_idz");
    const auto wrong = scene_from_text(scene(2, bad));
    ASSERT_FALSE(wrong);
    EXPECT_EQ(wrong.error().path.rfind("/objects/0/display", 0), 0u) << wrong.error().path;
    const auto newer = scene_from_text(scene(4, object));
    ASSERT_FALSE(newer);
    EXPECT_EQ(newer.error().path, "/version");
}

TEST(SceneObjectDisplay, OneObjectHoldsItsRecipeAndItsTogglesInVersionTwo) {
    // fig8's vase is constructed (a revolve of the profile): both version 2 members together.
    auto loaded =
        load_scene(std::string(ISOPARM_SOURCE_DIR) + "/assets/scenes/fig8-revolution.json");
    ASSERT_TRUE(loaded) << loaded.error().message;
    Document doc = std::move(loaded).value();
    const Object& vase = doc.objects.front();
    ASSERT_TRUE(vase.construction.has_value());
    doc.view.object_display[vase.id] = ObjectDisplay{false, false, true, true};
    const nlohmann::json j = scene_to_json(doc);
    EXPECT_EQ(j.at("version"), 2);
    const nlohmann::json& oj = j.at("objects").at(0);
    EXPECT_TRUE(oj.contains("construction"));
    EXPECT_TRUE(oj.contains("display"));
    auto back = scene_from_text(scene_to_text(doc));
    ASSERT_TRUE(back) << back.error().path << ": " << back.error().message;
    const Object& again = back->objects.front();
    ASSERT_TRUE(again.construction.has_value());
    EXPECT_TRUE(same_recipe(*again.construction, *vase.construction));
    EXPECT_FALSE(display_of(back->view, again.id).control_points);
    EXPECT_TRUE(display_of(back->view, again.id).point_ids);
    // Without its own toggles the vase still needs version 2 for its recipe.
    doc.view.object_display.clear();
    EXPECT_EQ(scene_to_json(doc).at("version"), 2);
}
