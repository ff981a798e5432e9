// Trimmed surfaces in the protocol: `tessellate` with a `trim` (a mesh whose every boundary edge
// lies on a trim loop), `classify` (kept / cut / boundary), `area`, and the loops' errors, which
// are geom::validate_trim's own (same code, same message, the path under "/trim").
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <numbers>
#include <string>
#include <vector>

#include "core/geom/trim/trim.hpp"
#include "core/geom/trim/trim_validate.hpp"
#include "core/json/trim_json.hpp"
#include "core/protocol/protocol.hpp"

namespace {

using nlohmann::json;
using namespace isoparm;

// The unit square in z = 0: position (x, y) is parameter (u, v).
const json square = {{"type", "bspline"},
                     {"degree", {1, 1}},
                     {"knots", {{0, 0, 1, 1}, {0, 0, 1, 1}}},
                     {"points", {{{0, 0, 0}, {0, 1, 0}}, {{1, 0, 0}, {1, 1, 0}}}}};

json line(double u0, double v0, double u1, double v1) {
    return {{"type", "bspline"},
            {"degree", 1},
            {"knots", {0, 0, 1, 1}},
            {"points", {{u0, v0}, {u1, v1}}}};
}

// Outer: the square [0.05, 0.95]^2 written by hand, counter-clockwise; a round hole of radius
// 0.25 about (0.5, 0.5) (exact rational arcs, from core/geom/trim).
constexpr double r = 0.25;
json trim_json() {
    geom::Trim hole;
    hole.holes.push_back(*geom::circle_loop({0.5, 0.5}, r, true));
    json t = json_io::trim_to_json(hole);
    t["outer"] = {line(0.05, 0.05, 0.95, 0.05), line(0.95, 0.05, 0.95, 0.95),
                  line(0.95, 0.95, 0.05, 0.95), line(0.05, 0.95, 0.05, 0.05)};
    return t;
}

double on_square(double x, double y) {
    const double dx = std::min(std::abs(x - 0.05), std::abs(x - 0.95));
    const double dy = std::min(std::abs(y - 0.05), std::abs(y - 0.95));
    const bool inside_x = x >= 0.05 - 1e-12 && x <= 0.95 + 1e-12;
    const bool inside_y = y >= 0.05 - 1e-12 && y <= 0.95 + 1e-12;
    return std::min(inside_y ? dx : 1e300, inside_x ? dy : 1e300);
}

double on_circle(double x, double y) {
    return std::abs(std::hypot(x - 0.5, y - 0.5) - r);
}

struct BoundaryCheck {
    int boundary_edges = 0, off_loop = 0;
    double square_length = 0, circle_length = 0, worst_midpoint = 0, area = 0;
};

// Every edge used by one triangle only is a boundary edge: its ends must lie on a loop (to
// rounding) and its midpoint within the chord tolerance of the same loop.
BoundaryCheck check_mesh(const json& answer) {
    BoundaryCheck c;
    const json& P = answer["positions"];
    std::map<std::pair<int, int>, int> uses;
    for (const json& t : answer["triangles"]) {
        const int v[3] = {t[0].get<int>(), t[1].get<int>(), t[2].get<int>()};
        for (int k = 0; k < 3; ++k) {
            const int a = v[k], b = v[(k + 1) % 3];
            ++uses[{std::min(a, b), std::max(a, b)}];
        }
        const double ax = P[v[0]][0], ay = P[v[0]][1], bx = P[v[1]][0], by = P[v[1]][1],
                     cx = P[v[2]][0], cy = P[v[2]][1];
        c.area += 0.5 * ((bx - ax) * (cy - ay) - (by - ay) * (cx - ax));
    }
    for (const auto& [edge, n] : uses) {
        if (n != 1) continue;
        ++c.boundary_edges;
        const double x0 = P[edge.first][0], y0 = P[edge.first][1];
        const double x1 = P[edge.second][0], y1 = P[edge.second][1];
        const double mx = 0.5 * (x0 + x1), my = 0.5 * (y0 + y1);
        const double length = std::hypot(x1 - x0, y1 - y0);
        if (on_square(x0, y0) < 1e-12 && on_square(x1, y1) < 1e-12 && on_square(mx, my) < 1e-12) {
            c.square_length += length;
        } else if (on_circle(x0, y0) < 1e-12 && on_circle(x1, y1) < 1e-12) {
            c.circle_length += length;
            c.worst_midpoint = std::max(c.worst_midpoint, on_circle(mx, my));
        } else {
            ++c.off_loop;
        }
    }
    return c;
}

TEST(TrimOps, TessellateWithATrimIsWatertightAlongEveryLoop) {
    for (const json& extra : {json::object(), json{{"tolerance", 1e-5}}}) {
        json request = {
            {"op", "tessellate"}, {"surface", square}, {"trim", trim_json()}, {"samples", {9, 9}}};
        request.update(extra);
        const json a = protocol::handle_request(request);
        ASSERT_TRUE(a["ok"].get<bool>()) << a.dump().substr(0, 400);
        const BoundaryCheck c = check_mesh(a);
        SCOPED_TRACE(extra.dump());
        EXPECT_GT(c.boundary_edges, 16);
        EXPECT_EQ(c.off_loop, 0) << "boundary edges that lie on no trim loop";
        // The boundary runs round both loops whole: the square's 3.6 exactly, the circle's
        // 2 pi r to the chords' shortfall.
        EXPECT_NEAR(c.square_length, 3.6, 1e-12);
        const double tolerance = extra.contains("tolerance") ? 1e-5 : 1e-3;
        EXPECT_NEAR(c.circle_length, 2 * std::numbers::pi * r, 2 * std::numbers::pi * tolerance);
        EXPECT_LE(c.worst_midpoint, tolerance);
        // Counter-clockwise triangles covering the kept region (the hole's chords cut a little).
        EXPECT_NEAR(c.area, 0.81 - std::numbers::pi * r * r, 2 * std::numbers::pi * r * tolerance);
    }
}

TEST(TrimOps, ClassifyNamesKeptCutAndBoundary) {
    const json a = protocol::handle_request(
        {{"op", "classify"},
         {"surface", square},
         {"trim", trim_json()},
         {"params", {{0.1, 0.5}, {0.5, 0.5}, {0.02, 0.5}, {0.75, 0.5}, {0.05, 0.3}, {0.9, 0.9}}}});
    ASSERT_TRUE(a["ok"].get<bool>()) << a.dump();
    EXPECT_EQ(a["sides"], json({"kept", "cut", "cut", "boundary", "boundary", "kept"}));
    // Without a trim the whole domain is kept and its edge is the boundary.
    const json b = protocol::handle_request(
        {{"op", "classify"}, {"surface", square}, {"params", {{0.5, 0.5}, {0, 0.5}}}});
    ASSERT_TRUE(b["ok"].get<bool>()) << b.dump();
    EXPECT_EQ(b["sides"], json({"kept", "boundary"}));
}

TEST(TrimOps, AreaOfTheTrimmedSquare) {
    const json a =
        protocol::handle_request({{"op", "area"}, {"surface", square}, {"trim", trim_json()}});
    ASSERT_TRUE(a["ok"].get<bool>()) << a.dump();
    EXPECT_NEAR(a["area"].get<double>(), 0.81 - std::numbers::pi * r * r, 1e-9);
}

// Each bad trim answers geom::validate_trim's error, its path under "/trim".
TEST(TrimOps, LoopErrorsAreValidateTrimsOwn) {
    const geom::ParamRect unit{{0, 1}, {0, 1}};
    std::vector<std::pair<std::string, json>> cases;
    json open = trim_json();
    open["outer"][1] = line(0.95, 0.05, 0.95, 0.9); // ends short of the next line
    cases.push_back({"not closed", open});
    json wrong_way = trim_json();
    wrong_way["outer"] = {line(0.05, 0.05, 0.05, 0.95), line(0.05, 0.95, 0.95, 0.95),
                          line(0.95, 0.95, 0.95, 0.05), line(0.95, 0.05, 0.05, 0.05)};
    cases.push_back({"runs clockwise", wrong_way});
    json outside = trim_json();
    outside["outer"] = {line(-0.5, 0.05, 0.95, 0.05), line(0.95, 0.05, 0.95, 0.95),
                        line(0.95, 0.95, -0.5, 0.95), line(-0.5, 0.95, -0.5, 0.05)};
    cases.push_back({"leaves the domain", outside});
    json bow_tie = trim_json();
    bow_tie["outer"] = {line(0.1, 0.1, 0.9, 0.9), line(0.9, 0.9, 0.9, 0.1),
                        line(0.9, 0.1, 0.1, 0.9), line(0.1, 0.9, 0.1, 0.1)};
    cases.push_back({"self-intersecting", bow_tie});
    for (const auto& [says, trim] : cases) {
        const auto parsed = json_io::trim_from_json(trim);
        ASSERT_TRUE(parsed) << says;
        const geom::Status expected = geom::validate_trim(*parsed, unit);
        ASSERT_FALSE(expected) << says;
        EXPECT_NE(expected.error().message.find(says), std::string::npos)
            << expected.error().message;
        for (const char* op : {"tessellate", "classify", "area"}) {
            json request = {{"op", op}, {"surface", square}, {"trim", trim}};
            if (std::string(op) == "classify") request["params"] = {{0.5, 0.5}};
            const json a = protocol::handle_request(request);
            ASSERT_FALSE(a["ok"].get<bool>()) << op << " " << says;
            EXPECT_EQ(a["error"]["code"], geom::name_of(expected.error().code)) << op;
            EXPECT_EQ(a["error"]["message"], expected.error().message) << op;
            EXPECT_EQ(a["error"]["path"], "/trim" + expected.error().path) << op;
        }
    }
}

TEST(TrimOps, BadTrimMembersNameTheValue) {
    json bad_point = trim_json();
    bad_point["outer"][0]["points"][1] = {0.95, 0.05, 0};
    const json a =
        protocol::handle_request({{"op", "area"}, {"surface", square}, {"trim", bad_point}});
    ASSERT_FALSE(a["ok"].get<bool>());
    EXPECT_EQ(a["error"]["code"], "schema");
    EXPECT_EQ(a["error"]["path"], "/trim/outer/0/points/1");
    // A tolerance needs a trim, and must be positive.
    const json b = protocol::handle_request(
        {{"op", "tessellate"}, {"surface", square}, {"samples", {9, 9}}, {"tolerance", 1e-3}});
    ASSERT_FALSE(b["ok"].get<bool>());
    EXPECT_EQ(b["error"]["path"], "/tolerance");
    const json c = protocol::handle_request({{"op", "tessellate"},
                                             {"surface", square},
                                             {"trim", trim_json()},
                                             {"samples", {9, 9}},
                                             {"tolerance", -1}});
    ASSERT_FALSE(c["ok"].get<bool>());
    EXPECT_EQ(c["error"]["path"], "/tolerance");
    // classify and area take a surface.
    const json d = protocol::handle_request({{"op", "area"},
                                             {"curve",
                                              {{"type", "bspline"},
                                               {"degree", 1},
                                               {"knots", {0, 0, 1, 1}},
                                               {"points", {{0, 0, 0}, {1, 0, 0}}}}}});
    ASSERT_FALSE(d["ok"].get<bool>());
    EXPECT_EQ(d["error"]["path"], "/curve");
}

} // namespace
