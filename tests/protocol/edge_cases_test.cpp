// Numerical edge cases through the geometry functions and the protocol: zero, negative and
// zero-sum weights, coincident points, full-multiplicity knots, degrees 1..15, parameters at
// every knot, tiny and huge coordinates. No NaN or inf ever comes out, and every operation
// answers (a result, or an error with a code that names the user's problem).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <initializer_list>
#include <set>
#include <string>
#include <vector>

#include "core/geom/basis.hpp"
#include "core/geom/evaluate.hpp"
#include "core/geom/knots.hpp"
#include "core/geom/refine.hpp"
#include "core/geom/tessellate.hpp"
#include "core/geom/validate.hpp"
#include "core/json/shapes.hpp"
#include "core/protocol/protocol.hpp"
#include "tests/support/random_geometry.hpp"

using namespace isoparm;
using geom::Curve;
using geom::Dir;
using geom::Surface;
using nlohmann::json;
using Random = isoparm::testing::RandomGeometry;

namespace {

// The JSON Pointer of the first non-finite number in v ("" when there is none).
std::string first_non_finite(const json& v, const std::string& at = "") {
    if (v.is_array()) {
        for (std::size_t k = 0; k < v.size(); ++k) {
            auto bad = first_non_finite(v[k], at + "/" + std::to_string(k));
            if (!bad.empty()) return bad;
        }
    } else if (v.is_object()) {
        for (auto it = v.begin(); it != v.end(); ++it) {
            auto bad = first_non_finite(it.value(), at + "/" + it.key());
            if (!bad.empty()) return bad;
        }
    } else if (v.is_number_float() && !std::isfinite(v.get<double>())) {
        return at.empty() ? "(the root)" : at;
    }
    return "";
}

std::string brief(const json& j) {
    std::string s = j.dump();
    return s.size() > 400 ? s.substr(0, 400) + "..." : s;
}

// Sends one request. Every answer is an object with a boolean `ok` and only finite numbers;
// a failure has one of `allowed` codes (never `internal`) and a message.
json ask(const json& request, std::initializer_list<const char*> allowed = {}) {
    const json r = protocol::handle_request(request);
    EXPECT_TRUE(r.is_object() && r.contains("ok") && r["ok"].is_boolean())
        << "no answer to " << brief(request) << ": " << brief(r);
    if (!r.is_object() || !r.contains("ok")) return r;
    const std::string bad = first_non_finite(r);
    EXPECT_TRUE(bad.empty()) << "a non-finite number at " << bad << " answering " << brief(request);
    if (!r["ok"].get<bool>()) {
        const std::string code = r["error"].value("code", "");
        const bool expected =
            std::any_of(allowed.begin(), allowed.end(), [&](const char* c) { return code == c; });
        EXPECT_TRUE(expected) << "unexpected error " << brief(r["error"]) << " answering "
                              << brief(request);
        EXPECT_FALSE(r["error"].value("message", "").empty());
    }
    return r;
}

bool ok(const json& r) {
    return r.is_object() && r.value("ok", false);
}

// Distinct knots in the domain [U[p], U[n]] (ends included) and the midpoints between them.
std::vector<double> knots_in_domain(const geom::Knots& U, int p, int n) {
    std::vector<double> out;
    for (int k = p; k <= n; ++k)
        if (out.empty() || U[k] != out.back()) out.push_back(U[k]);
    return out;
}
std::vector<double> midpoints(const std::vector<double>& ts) {
    std::vector<double> out;
    for (std::size_t k = 0; k + 1 < ts.size(); ++k) out.push_back(0.5 * (ts[k] + ts[k + 1]));
    return out;
}
std::vector<double> samples(const geom::Knots& U, int p, int n) {
    auto ts = knots_in_domain(U, p, n);
    const auto mids = midpoints(ts);
    ts.insert(ts.end(), mids.begin(), mids.end());
    std::sort(ts.begin(), ts.end());
    return ts;
}
std::vector<double> interior(const std::vector<double>& ts) {
    if (ts.size() < 2) return {};
    std::vector<double> out;
    for (double t : ts)
        if (t > ts.front() && t < ts.back()) out.push_back(t);
    return out;
}

// The rational denominator sum N_i(t) w_i, and the size of its terms (for "is it zero").
struct Denominator {
    double value = 0, scale = 0;
    bool vanishes() const { return std::abs(value) <= 1e-12 * scale; }
};
Denominator curve_denominator(const Curve& c, double t) {
    const auto N = geom::all_basis(c.knots, c.degree, c.count(), t)[0];
    Denominator d;
    for (int i = 0; i < c.count(); ++i) {
        d.value += N[i] * c.weights[i];
        d.scale += std::abs(N[i] * c.weights[i]);
    }
    return d;
}
Denominator surface_denominator(const Surface& s, double u, double v) {
    const auto Nu = geom::all_basis(s.knots_u, s.degree_u, s.n_u, u)[0];
    const auto Nv = geom::all_basis(s.knots_v, s.degree_v, s.n_v, v)[0];
    Denominator d;
    for (int i = 0; i < s.n_u; ++i)
        for (int j = 0; j < s.n_v; ++j) {
            d.value += Nu[i] * Nv[j] * s.weight(i, j);
            d.scale += std::abs(Nu[i] * Nv[j] * s.weight(i, j));
        }
    return d;
}

double extent(const std::vector<glm::dvec3>& points) {
    double m = 0;
    for (const auto& p : points) m = std::max({m, std::abs(p.x), std::abs(p.y), std::abs(p.z)});
    return m;
}

// How a battery treats its object: positive weights must refine without error and keep the
// shape; zero or negative weights may meet a point at infinity (`weights`).
struct Expect {
    bool positive_weights = true;
    double shape_tolerance = 1e-9; // relative to the control points' extent
};

std::vector<glm::dvec3> curve_points_of(const json& c, const std::vector<double>& ts) {
    const json r = ask({{"op", "evaluate"}, {"curve", c}, {"params", ts}});
    std::vector<glm::dvec3> out;
    if (!ok(r)) {
        ADD_FAILURE() << "a refined curve does not evaluate: " << brief(r);
        return out;
    }
    for (const auto& p : r["points"])
        out.push_back(p.is_null() ? glm::dvec3(NAN) : glm::dvec3(p[0], p[1], p[2]));
    return out;
}

void expect_same_curve(const Curve& c, const json& result, const std::vector<double>& ts,
                       const Expect& e, const char* what) {
    const auto got = curve_points_of(result, ts);
    if (got.size() != ts.size() || !e.positive_weights) return;
    const double tol = e.shape_tolerance * std::max(extent(c.points), 1e-300);
    for (std::size_t k = 0; k < ts.size(); ++k) {
        const auto want = geom::curve_point(c, ts[k]);
        ASSERT_TRUE(want.has_value());
        EXPECT_LE(glm::length(got[k] - *want), tol) << what << " moved C(" << ts[k] << ")";
    }
}

// Every operation on a curve, at every knot and between knots.
void curve_battery(const Curve& c, const Expect& e = {}) {
    ASSERT_TRUE(geom::validate_curve(c).ok()) << geom::validate_curve(c).error().message;
    const json cj = json_io::curve_to_json(c);
    const int p = c.degree, n = c.count();
    const auto ts = samples(c.knots, p, n);
    const auto inner = interior(ts);

    // evaluate: always answers; a null point only where the denominator vanishes.
    const json r = ask({{"op", "evaluate"}, {"curve", cj}, {"params", ts}, {"derivatives", 3}});
    ASSERT_TRUE(ok(r)) << brief(r);
    for (std::size_t k = 0; k < ts.size(); ++k) {
        const bool missing = r["points"][k].is_null();
        if (missing) {
            const auto d = curve_denominator(c, ts[k]);
            EXPECT_TRUE(d.vanishes()) << "C(" << ts[k] << ") is null, denominator " << d.value;
            EXPECT_TRUE(r["derivatives"][k].is_null());
        }
        if (e.positive_weights) {
            EXPECT_FALSE(missing) << "C(" << ts[k] << ")";
        }
        // The geometry functions agree and give only finite numbers.
        const auto ders = geom::curve_derivatives(c, ts[k], 3);
        EXPECT_EQ(ders.has_value(), !missing);
        if (ders) {
            for (const auto& d : *ders)
                EXPECT_TRUE(std::isfinite(d.x) && std::isfinite(d.y) && std::isfinite(d.z));
        }
    }

    // basis and deboor at every knot (with and without weights).
    for (double t : ts) {
        const json b = ask({{"op", "basis"},
                            {"degree", p},
                            {"knots", c.knots},
                            {"param", t},
                            {"derivatives", std::min(p, 3)}});
        ASSERT_TRUE(ok(b)) << brief(b);
        double sum = 0;
        for (const auto& x : b["values"]) sum += x.get<double>();
        EXPECT_NEAR(sum, 1.0, 1e-12 * n) << "partition of unity at " << t;
        ask({{"op", "basis"},
             {"degree", p},
             {"knots", c.knots},
             {"param", t},
             {"weights", c.weights}},
            {"weights"});
        EXPECT_TRUE(ok(ask({{"op", "deboor"}, {"curve", cj}, {"param", t}})));
    }

    const std::initializer_list<const char*> refine_errors = {"weights", "multiplicity"};
    // insert_knot at every knot of the domain and between knots.
    for (double t : ts) {
        const int room = p - geom::multiplicity(c.knots, t);
        const json r2 = ask({{"op", "insert_knot"}, {"curve", cj}, {"knot", t}}, refine_errors);
        if (room <= 0) {
            EXPECT_FALSE(ok(r2)) << "inserting " << t << " beyond the degree";
            if (!ok(r2)) {
                EXPECT_EQ(r2["error"]["code"], "multiplicity");
            }
        } else if (e.positive_weights) {
            ASSERT_TRUE(ok(r2)) << "insert " << t << ": " << brief(r2);
        }
        if (ok(r2)) expect_same_curve(c, r2["curve"], ts, e, "insert_knot");
    }
    // elevate_degree once and twice.
    for (int times : {1, 2}) {
        const json r2 =
            ask({{"op", "elevate_degree"}, {"curve", cj}, {"times", times}}, {"weights", "limit"});
        if (e.positive_weights) {
            ASSERT_TRUE(ok(r2)) << "elevate: " << brief(r2);
        }
        if (ok(r2)) {
            EXPECT_EQ(r2["curve"]["degree"], p + times);
            expect_same_curve(c, r2["curve"], ts, e, "elevate_degree");
        }
    }
    // split at every interior knot and between knots.
    for (double t : inner) {
        const json r2 = ask({{"op", "split"}, {"curve", cj}, {"param", t}}, {"weights"});
        if (e.positive_weights) {
            ASSERT_TRUE(ok(r2)) << "split " << t << ": " << brief(r2);
        }
        if (!ok(r2)) continue;
        std::vector<double> left, right;
        for (double s : ts) (s <= t ? left : right).push_back(s);
        right.insert(right.begin(), t);
        // Where the curve breaks (a knot of multiplicity p + 1) the first piece ends at the
        // left limit, while C(t) is the right limit (convention 3): compare inside only.
        if (geom::multiplicity(c.knots, t) == p + 1) left.pop_back();
        expect_same_curve(c, r2["pieces"][0], left, e, "split (first piece)");
        expect_same_curve(c, r2["pieces"][1], right, e, "split (second piece)");
    }
}

json surface_params(const std::vector<double>& us, const std::vector<double>& vs) {
    json params = json::array();
    for (double u : us)
        for (double v : vs) params.push_back({u, v});
    return params;
}

void expect_same_surface(const Surface& s, const json& result, const std::vector<double>& us,
                         const std::vector<double>& vs, const Expect& e, const char* what) {
    const json r =
        ask({{"op", "evaluate"}, {"surface", result}, {"params", surface_params(us, vs)}});
    ASSERT_TRUE(ok(r)) << what << " gave a surface that does not evaluate: " << brief(r);
    if (!e.positive_weights) return;
    const double tol = e.shape_tolerance * std::max(extent(s.points), 1e-300);
    std::size_t k = 0;
    for (double u : us)
        for (double v : vs) {
            const json& p = r["points"][k++];
            const auto want = geom::surface_point(s, u, v);
            ASSERT_TRUE(want.has_value() && !p.is_null());
            EXPECT_LE(glm::length(glm::dvec3(p[0], p[1], p[2]) - *want), tol)
                << what << " moved S(" << u << ", " << v << ")";
        }
}

// Every operation on a surface, at every pair of knots and between them.
void surface_battery(const Surface& s, const Expect& e = {}) {
    ASSERT_TRUE(geom::validate_surface(s).ok()) << geom::validate_surface(s).error().message;
    const json sj = json_io::surface_to_json(s);
    const auto us = samples(s.knots_u, s.degree_u, s.n_u);
    const auto vs = samples(s.knots_v, s.degree_v, s.n_v);

    const json r = ask({{"op", "evaluate"},
                        {"surface", sj},
                        {"params", surface_params(us, vs)},
                        {"derivatives", 3},
                        {"normals", true}});
    ASSERT_TRUE(ok(r)) << brief(r);
    std::size_t k = 0;
    for (double u : us)
        for (double v : vs) {
            const bool missing = r["points"][k].is_null();
            if (missing) {
                const auto d = surface_denominator(s, u, v);
                EXPECT_TRUE(d.vanishes())
                    << "S(" << u << ", " << v << ") is null, denominator " << d.value;
                EXPECT_TRUE(r["normals"][k].is_null());
            }
            if (e.positive_weights) {
                EXPECT_FALSE(missing) << "S(" << u << ", " << v << ")";
            }
            // A renderer's normal always exists and is a unit vector.
            const glm::dvec3 nrm = geom::surface_normal_or_limit(s, u, v);
            EXPECT_TRUE(std::isfinite(nrm.x) && std::isfinite(nrm.y) && std::isfinite(nrm.z));
            EXPECT_NEAR(glm::length(nrm), 1.0, 1e-9) << "at (" << u << ", " << v << ")";
            ++k;
        }
    for (double u : {us.front(), us[us.size() / 2], us.back()})
        for (double v : {vs.front(), vs[vs.size() / 2], vs.back()})
            EXPECT_TRUE(ok(ask({{"op", "deboor"}, {"surface", sj}, {"u", u}, {"v", v}})));

    // tessellate: finite positions and unit normals; triangles only over existing vertices.
    const json t = ask({{"op", "tessellate"}, {"surface", sj}, {"samples", {7, 5}}});
    ASSERT_TRUE(ok(t)) << brief(t);
    for (const auto& tri : t["triangles"])
        for (const auto& index : tri)
            EXPECT_FALSE(t["positions"][index.get<std::size_t>()].is_null());
    const geom::Mesh mesh = geom::tessellate(s, 7, 5);
    for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
        if (!mesh.vertex_exists(v)) continue;
        EXPECT_NEAR(glm::length(mesh.normals[v]), 1.0, 1e-9) << "vertex " << v;
        EXPECT_TRUE(std::isfinite(mesh.positions[v].x + mesh.positions[v].y + mesh.positions[v].z));
    }

    for (const Dir dir : {Dir::u, Dir::v}) {
        const char* d = dir == Dir::u ? "u" : "v";
        const auto& ts = dir == Dir::u ? us : vs;
        const int p = s.degree(dir);
        for (double x : ts) {
            const json r2 =
                ask({{"op", "insert_knot"}, {"surface", sj}, {"direction", d}, {"knot", x}},
                    {"weights", "multiplicity", "limit"});
            const int room = p - geom::multiplicity(s.knots(dir), x);
            if (room <= 0) {
                EXPECT_FALSE(ok(r2));
            } else if (e.positive_weights) {
                ASSERT_TRUE(ok(r2)) << brief(r2);
            }
            if (ok(r2)) expect_same_surface(s, r2["surface"], us, vs, e, "insert_knot");
        }
        const json r3 = ask({{"op", "elevate_degree"}, {"surface", sj}, {"direction", d}},
                            {"weights", "limit"});
        if (e.positive_weights) {
            ASSERT_TRUE(ok(r3)) << brief(r3);
        }
        if (ok(r3)) expect_same_surface(s, r3["surface"], us, vs, e, "elevate_degree");
        for (double x : interior(ts)) {
            const json r4 = ask({{"op", "split"}, {"surface", sj}, {"direction", d}, {"param", x}},
                                {"weights"});
            if (e.positive_weights) {
                ASSERT_TRUE(ok(r4)) << brief(r4);
            }
            if (!ok(r4)) continue;
            for (const auto& piece : r4["pieces"])
                EXPECT_TRUE(ok(ask(
                    {{"op", "evaluate"},
                     {"surface", piece},
                     {"params", json::array({json::array({dir == Dir::u ? x : us.front(),
                                                          dir == Dir::v ? x : vs.front()})})}})))
                    << "a split piece does not evaluate at the split parameter";
        }
    }
}

Curve make_curve(int p, std::vector<glm::dvec3> points, std::vector<double> weights,
                 geom::Knots knots) {
    Curve c;
    c.type = geom::SplineType::nurbs;
    c.degree = p;
    c.points = std::move(points);
    c.weights = std::move(weights);
    c.knots = std::move(knots);
    return c;
}

} // namespace

// ---------------------------------------------------------------------------------------
// Weights.

TEST(EdgeWeights, ZeroSumIsANullPointNeverNaN) {
    // Degree 2, weights 1, -1, 1: sum N_i w_i = 0.25 - 0.5 + 0.25 = 0 exactly at t = 0.5.
    const Curve c =
        make_curve(2, {{0, 0, 0}, {1, 1, 0}, {2, 0, 0}}, {1, -1, 1}, {0, 0, 0, 1, 1, 1});
    EXPECT_FALSE(geom::curve_point(c, 0.5).has_value());
    EXPECT_FALSE(geom::curve_derivatives(c, 0.5, 3).has_value());
    const json cj = json_io::curve_to_json(c);
    const json r =
        ask({{"op", "evaluate"}, {"curve", cj}, {"params", {0.25, 0.5, 0.75}}, {"derivatives", 2}});
    ASSERT_TRUE(ok(r));
    EXPECT_TRUE(r["points"][1].is_null());
    EXPECT_TRUE(r["derivatives"][1].is_null());
    EXPECT_FALSE(r["points"][0].is_null());
    const json d = ask({{"op", "deboor"}, {"curve", cj}, {"param", 0.5}});
    ASSERT_TRUE(ok(d));
    EXPECT_TRUE(d["levels"].back()[0].is_null()) << "the point at zero weight is null";
    // The rational basis has no value where its denominator vanishes: it still answers.
    ask({{"op", "basis"},
         {"degree", 2},
         {"knots", c.knots},
         {"param", 0.5},
         {"weights", c.weights}},
        {"weights"});
    // Splitting or inserting there needs a control point at infinity (convention 6).
    const json s = ask({{"op", "split"}, {"curve", cj}, {"param", 0.5}}, {"weights"});
    ASSERT_FALSE(ok(s));
    EXPECT_EQ(s["error"]["code"], "weights");
    const json i = ask({{"op", "insert_knot"}, {"curve", cj}, {"knot", 0.5}}, {"weights"});
    ASSERT_FALSE(ok(i));
    EXPECT_EQ(i["error"]["code"], "weights");
    curve_battery(c, {.positive_weights = false});
}

TEST(EdgeWeights, ZeroSumAlongALineOfASurface) {
    // Bilinear with weights 1 (j = 0) and -1 (j = 1): the denominator 1 - 2v is 0 on v = 0.5.
    Surface s;
    s.type = geom::SplineType::nurbs;
    s.n_u = s.n_v = 2;
    s.knots_u = s.knots_v = {0, 0, 1, 1};
    s.points = {{0, 0, 0}, {0, 1, 1}, {1, 0, 0}, {1, 1, 2}};
    s.weights = {1, -1, 1, -1};
    for (double u : {0.0, 0.3, 1.0}) EXPECT_FALSE(geom::surface_point(s, u, 0.5).has_value());
    const json sj = json_io::surface_to_json(s);
    const json r = ask({{"op", "evaluate"},
                        {"surface", sj},
                        {"params", {{0.3, 0.5}, {0.3, 0.25}}},
                        {"derivatives", 1},
                        {"normals", true}});
    ASSERT_TRUE(ok(r));
    EXPECT_TRUE(r["points"][0].is_null());
    EXPECT_TRUE(r["derivatives"][0].is_null());
    EXPECT_TRUE(r["normals"][0].is_null());
    EXPECT_FALSE(r["points"][1].is_null());
    // The middle row of a 3 x 3 tessellation does not exist; no triangle uses it.
    const json t = ask({{"op", "tessellate"}, {"surface", sj}, {"samples", {3, 3}}});
    ASSERT_TRUE(ok(t));
    for (int i = 0; i < 3; ++i) EXPECT_TRUE(t["positions"][i * 3 + 1].is_null()) << i;
    surface_battery(s, {.positive_weights = false});
}

TEST(EdgeWeights, RandomCurvesWithZeroAndNegativeWeights) {
    Random g(101);
    const double choices[] = {-2, -1, -0.5, 0, 0, 0.5, 1, 2};
    for (int trial = 0; trial < 150; ++trial) {
        SCOPED_TRACE("trial " + std::to_string(trial));
        const int p = g.integer(1, 5);
        Curve c = g.curve(p, p + 1 + g.integer(0, 4), true, trial % 3 != 0, std::max(1, p - 1));
        for (double& w : c.weights) w = choices[g.integer(0, 7)];
        curve_battery(c, {.positive_weights = false});
    }
}

TEST(EdgeWeights, RandomSurfacesWithZeroAndNegativeWeights) {
    Random g(202);
    const double choices[] = {-2, -1, -0.5, 0, 0, 0.5, 1, 2};
    for (int trial = 0; trial < 40; ++trial) {
        SCOPED_TRACE("trial " + std::to_string(trial));
        const int p = g.integer(1, 3), q = g.integer(1, 3);
        Surface s = g.surface(p, q, p + 1 + g.integer(0, 2), q + 1 + g.integer(0, 2), true,
                              trial % 3 != 0, 2);
        for (double& w : s.weights) w = choices[g.integer(0, 7)];
        surface_battery(s, {.positive_weights = false});
    }
}

TEST(EdgeWeights, AllWeightsZeroIsNullEverywhere) {
    const Curve c = make_curve(1, {{0, 0, 0}, {1, 0, 0}}, {0, 0}, {0, 0, 1, 1});
    // Every weight may be zero (the spec allows any finite weight): no point exists anywhere.
    for (double t : {0.0, 0.5, 1.0}) EXPECT_FALSE(geom::curve_point(c, t).has_value());
    curve_battery(c, {.positive_weights = false});
}

// ---------------------------------------------------------------------------------------
// Control points and knots.

TEST(EdgeGeometry, CoincidentControlPoints) {
    // A curve whose points all coincide, and one with a repeated pair.
    curve_battery(make_curve(3, std::vector<glm::dvec3>(5, glm::dvec3(1, 2, 3)), {1, 2, 0.5, 1, 1},
                             geom::clamped_uniform_knots(5, 3)));
    curve_battery(make_curve(2, {{0, 0, 0}, {1, 1, 0}, {1, 1, 0}, {2, 0, 0}}, {1, 1, 1, 1},
                             geom::clamped_uniform_knots(4, 2)));
    // A surface collapsed to a point: no strict normal, yet a unit normal for the renderer.
    Surface s;
    s.type = geom::SplineType::bspline;
    s.degree_u = s.degree_v = 2;
    s.n_u = s.n_v = 3;
    s.knots_u = s.knots_v = {0, 0, 0, 1, 1, 1};
    s.points.assign(9, glm::dvec3(0.5, -0.5, 2));
    s.weights.assign(9, 1.0);
    EXPECT_FALSE(geom::surface_normal(s, 0.5, 0.5).has_value());
    surface_battery(s);
    // A pole: the whole first row at one point (a sphere's pole, a cone's tip).
    Random g(7);
    Surface pole = g.surface(3, 2, 5, 4, true);
    for (int j = 0; j < pole.n_v; ++j) pole.point(0, j) = glm::dvec3(0, 0, 1);
    surface_battery(pole);
}

TEST(EdgeKnots, FullyRepeatedInteriorKnots) {
    Random g(11);
    for (int p = 1; p <= 4; ++p)
        for (int mult : {p, p + 1}) {
            SCOPED_TRACE("degree " + std::to_string(p) + ", multiplicity " + std::to_string(mult));
            // p + 1 points before the knot, then enough after it for one more span.
            const int n = p + 1 + mult;
            geom::Knots U(p + 1, 0.0);
            for (int k = 0; k < mult; ++k) U.push_back(0.5);
            U.insert(U.end(), p + 1, 1.0);
            ASSERT_EQ(static_cast<int>(U.size()), n + p + 1);
            Curve c = g.curve(p, n, true);
            c.knots = U;
            curve_battery(c);
            if (mult == p + 1) {
                // A break at the knot: the value there is the right limit (convention 3),
                // the first point of the second piece.
                const auto at = geom::curve_point(c, 0.5);
                ASSERT_TRUE(at.has_value());
                EXPECT_LE(glm::length(*at - c.points[p + 1]), 1e-12 * extent(c.points));
            }
            Surface s = g.surface(p, p, n, n, true);
            s.knots_u = s.knots_v = U;
            surface_battery(s);
        }
}

// ---------------------------------------------------------------------------------------
// Degrees.

TEST(EdgeDegrees, OneToFifteen) {
    Random g(31);
    for (int p : {1, 2, 3, 4, 5, 7, 9, 10, 12, 15}) {
        for (bool clamped : {true, false}) {
            SCOPED_TRACE("degree " + std::to_string(p) + (clamped ? " clamped" : " unclamped"));
            // Elevation of a high degree loses a few digits (binomial coefficients).
            const Expect e{.positive_weights = true, .shape_tolerance = p > 9 ? 1e-6 : 1e-9};
            curve_battery(g.curve(p, p + 1, true, clamped), e);
            curve_battery(g.curve(p, p + 4, true, clamped, std::max(1, p - 1)), e);
        }
    }
    for (auto [p, q] : {std::pair{1, 1}, {1, 9}, {9, 1}, {9, 9}, {12, 2}}) {
        SCOPED_TRACE("degrees " + std::to_string(p) + ", " + std::to_string(q));
        surface_battery(g.surface(p, q, p + 2, q + 2, true),
                        {.positive_weights = true, .shape_tolerance = 1e-7});
    }
}

TEST(EdgeDegrees, BezierOfDegreeTwenty) {
    Random g(41);
    Curve c = g.curve(20, 21, true);
    c.type = geom::SplineType::rational_bezier;
    c.knots = geom::bezier_knots(20);
    curve_battery(c, {.positive_weights = true, .shape_tolerance = 1e-6});
}

// Regression: raising a cubic to degree 1030 or more used to fail with a `weights` error on a
// curve whose weights are all 1, because the Bezier elevation coefficients were formed from
// binomials C(p + t, i) that overflow a double near degree 1030 (now through log-gamma there).
TEST(EdgeDegrees, ElevationToDegreeAboveAThousand) {
    const Curve c = make_curve(3, {{0, 0, 0}, {1, 1, 0}, {2, 0, 0}, {3, 1, 0}}, {1, 1, 1, 1},
                               {0, 0, 0, 0, 1, 1, 1, 1});
    for (int times : {1100, 2000}) {
        const json r =
            ask({{"op", "elevate_degree"}, {"curve", json_io::curve_to_json(c)}, {"times", times}},
                {"limit"});
        if (ok(r)) {
            expect_same_curve(c, r["curve"], {0, 0.25, 0.5, 1}, {.shape_tolerance = 1e-6},
                              "elevate_degree");
        }
    }
}

// ---------------------------------------------------------------------------------------
// Coordinates and parameters far from 1.

TEST(EdgeScale, TinyAndHugeCoordinates) {
    for (double scale : {1e-9, 1e9}) {
        Random g(53);
        for (int trial = 0; trial < 4; ++trial) {
            SCOPED_TRACE("scale " + geom::format_number(scale) + ", trial " +
                         std::to_string(trial));
            Curve c = g.curve(3, 6, true, trial % 2 == 0);
            for (auto& pt : c.points) pt *= scale;
            curve_battery(c);
            Surface s = g.surface(2, 3, 4, 5, true, trial % 2 == 0);
            Surface unit = s;
            for (auto& pt : s.points) pt *= scale;
            surface_battery(s);
            // Normals do not depend on the scale: a tiny surface is not "degenerate".
            for (double u : {0.2, 0.5, 0.9})
                for (double v : {0.1, 0.5, 0.7}) {
                    const auto dom_u = geom::domain(s.knots_u, 2, 4);
                    const auto dom_v = geom::domain(s.knots_v, 3, 5);
                    const double uu = dom_u.lo + u * (dom_u.hi - dom_u.lo);
                    const double vv = dom_v.lo + v * (dom_v.hi - dom_v.lo);
                    const auto a = geom::surface_normal(unit, uu, vv);
                    const auto b = geom::surface_normal(s, uu, vv);
                    ASSERT_EQ(a.has_value(), b.has_value()) << "at (" << uu << ", " << vv << ")";
                    if (a) {
                        EXPECT_LE(glm::length(*a - *b), 1e-9);
                    }
                }
        }
    }
}

TEST(EdgeScale, MixedMagnitudesInOneObject) {
    Random g(59);
    Curve c = g.curve(3, 7, true);
    c.points[1] *= 1e9;
    c.points[4] *= 1e-9;
    c.weights[2] = 1e-9;
    c.weights[5] = 1e9;
    curve_battery(c, {.positive_weights = true, .shape_tolerance = 1e-6});
}

TEST(EdgeScale, TinyAndHugeParameterDomains) {
    for (auto [a, b] : {std::pair{0.0, 1e-9}, {-1e9, 1e9}, {1e9, 1e9 + 1}}) {
        SCOPED_TRACE("domain [" + geom::format_number(a) + ", " + geom::format_number(b) + "]");
        Random g(61);
        Curve c = g.curve(3, 6, true);
        c.knots = geom::clamped_uniform_knots(6, 3, a, b);
        curve_battery(c, {.positive_weights = true, .shape_tolerance = 1e-6});
        Surface s = g.surface(2, 2, 4, 4, true);
        s.knots_u = geom::clamped_uniform_knots(4, 2, a, b);
        surface_battery(s, {.positive_weights = true, .shape_tolerance = 1e-6});
    }
}

// ---------------------------------------------------------------------------------------
// Random valid surfaces, every operation.

TEST(EdgeProperties, RandomValidSurfaces) {
    Random g(97);
    for (int trial = 0; trial < 60; ++trial) {
        SCOPED_TRACE("trial " + std::to_string(trial));
        const int p = g.integer(1, 4), q = g.integer(1, 4);
        surface_battery(g.surface(p, q, p + 1 + g.integer(0, 3), q + 1 + g.integer(0, 3),
                                  trial % 2 == 0, trial % 4 < 2, std::max(1, std::min(p, q))),
                        {.positive_weights = true, .shape_tolerance = 1e-9});
    }
}
