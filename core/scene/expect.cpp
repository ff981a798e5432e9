// Expectations: strict reading, and every way a document can differ from one.
#include "core/scene/expect.hpp"

#include <algorithm>
#include <cmath>

#include "core/doc/patches.hpp"
#include "core/geom/basis.hpp"
#include "core/geom/curvature.hpp"
#include "core/geom/evaluate.hpp"
#include "core/geom/knots.hpp"
#include "core/json/fields.hpp"
#include "core/json/shapes.hpp"
#include "core/scene/scene_io.hpp"

namespace isoparm::scene {

using namespace isoparm::json_io;
using geom::Expected;
using nlohmann::json;

namespace {

Expected<std::vector<double>> read_numbers(const json& v, const std::string& at,
                                           std::string_view what) {
    if (!v.is_array()) return schema_error(std::string(what) + " is an array of numbers", at);
    std::vector<double> out;
    for (std::size_t k = 0; k < v.size(); ++k) {
        auto x = read_finite(v[k], at + "/" + std::to_string(k), "a number");
        if (!x) return x.error();
        out.push_back(*x);
    }
    return out;
}

bool near(double got, double want, double tolerance) {
    return std::abs(got - want) <= tolerance * std::max(1.0, std::abs(want));
}

bool near(const glm::dvec3& got, const glm::dvec3& want, double tolerance) {
    return near(got.x, want.x, tolerance) && near(got.y, want.y, tolerance) &&
           near(got.z, want.z, tolerance);
}

std::string vec_text(const glm::dvec3& p) {
    return "(" + geom::format_number(p.x) + ", " + geom::format_number(p.y) + ", " +
           geom::format_number(p.z) + ")";
}

std::string list_text(const std::vector<double>& v) {
    std::string out = "[";
    for (std::size_t k = 0; k < v.size(); ++k) out += (k ? ", " : "") + geom::format_number(v[k]);
    return out + "]";
}

// A triangular patch: its degree and its control point b_ijk (i, j), k = n - i - j; it has
// no knots and no tensor-product type.
std::vector<std::string> unmet_on_triangle(const ExpectStep& e, const std::string& object_name,
                                           const geom::TrianglePatch& t) {
    std::vector<std::string> out;
    const std::string tol = " (tolerance " + geom::format_number(e.tolerance) + ")";
    const std::string name = "'" + object_name + "'";
    if (e.knots || e.type)
        out.push_back(name + " is a triangular patch: it has no knots and no spline type");
    if (e.at)
        out.push_back(name + " is a triangular patch: its parameters are barycentric, not (u, v)");
    if (e.degree && t.degree != *e.degree)
        out.push_back("expected " + name + "'s degree to be " + std::to_string(*e.degree) +
                      ", it is " + std::to_string(t.degree));
    if (!e.i) return out;
    const int i = *e.i, j = e.j.value_or(-1);
    const std::string label =
        "b" + std::to_string(i) + "," + std::to_string(j) + "," + std::to_string(t.degree - i - j);
    if (i < 0 || j < 0 || i + j > t.degree) {
        out.push_back(name + " has no control point b_ijk with i = " + std::to_string(i) +
                      ", j = " + std::to_string(j));
        return out;
    }
    const auto at = static_cast<std::size_t>(geom::TrianglePatch::index(t.degree, i, j));
    const glm::dvec3 p = t.points[at];
    if (e.position && !near(p, *e.position, e.tolerance))
        out.push_back("expected " + label + " of " + name + " at " + vec_text(*e.position) +
                      ", found " + vec_text(p) + tol);
    if (e.weight && !near(t.weights[at], *e.weight, e.tolerance))
        out.push_back("expected the weight of " + label + " of " + name + " to be " +
                      geom::format_number(*e.weight) + ", found " +
                      geom::format_number(t.weights[at]) + tol);
    return out;
}

// Which side of the surface's trim e.at lies on (an untrimmed surface keeps its whole domain).
void unmet_side(const ExpectStep& e, const std::string& name, const doc::Object& o,
                const geom::Surface* s, std::vector<std::string>& out) {
    if (!s) {
        out.push_back(name + " is a curve: only a surface is trimmed");
        return;
    }
    const auto* surface = std::get_if<doc::SurfaceObject>(&o.shape);
    geom::TrimSide side = geom::TrimSide::kept;
    if (surface && !surface->trim.empty())
        side = geom::TrimClassifier(surface->trim, geom::domain(*s)).classify(*e.at);
    if (side != *e.side)
        out.push_back("expected (u, v) = (" + geom::format_number(e.at->x) + ", " +
                      geom::format_number(e.at->y) + ") to be " + geom::name_of(*e.side) + " on " +
                      name + ", it is " + geom::name_of(side));
}

// What the surface or curve is at e.at: its point, R_ij (or R_i), the sum of all of them and
// the curvatures, each compared with what the expectation names.
void unmet_at_parameter(const ExpectStep& e, const std::string& name, const geom::Surface* s,
                        const geom::Curve* c, std::vector<std::string>& out) {
    const std::string tol = " (tolerance " + geom::format_number(e.tolerance) + ")";
    const double u = e.at->x, v = e.at->y;
    const std::string where =
        s ? "(u, v) = (" + geom::format_number(u) + ", " + geom::format_number(v) + ")"
          : "t = " + geom::format_number(u);
    const bool inside = s ? geom::domain(*s).contains({u, v}) : geom::domain(*c).contains(u);
    if (!inside) {
        out.push_back(where + " is outside the domain of " + name);
        return;
    }
    const std::optional<glm::dvec3> p =
        s ? geom::surface_point(*s, u, v) : geom::curve_point(*c, u);
    if (!p) {
        out.push_back(name + " has no point at " + where + " (its denominator is zero there)");
        return;
    }
    if (e.position && !e.i && !near(*p, *e.position, e.tolerance))
        out.push_back("expected the point of " + name + " at " + where + " to be " +
                      vec_text(*e.position) + ", found " + vec_text(*p) + tol);
    if (e.basis || e.basis_sum) {
        // R_ij(u, v) (R_i(t)) of every control point: one of them, or their sum.
        double sum = 0, one = 0;
        if (s) {
            for (int a = 0; a < s->n_u; ++a)
                for (int b = 0; b < s->n_v; ++b) {
                    const double r = geom::rational_basis_ij(*s, a, b, u, v).value_or(0);
                    sum += r;
                    if (e.i && a == *e.i && b == e.j.value_or(-1)) one = r;
                }
        } else if (auto R = geom::rational_basis(c->knots, c->degree, c->weights, u)) {
            for (int a = 0; a < c->count(); ++a) {
                sum += (*R)[0][static_cast<std::size_t>(a)];
                if (e.i && a == *e.i) one = (*R)[0][static_cast<std::size_t>(a)];
            }
        }
        if (e.basis_sum && !near(sum, *e.basis_sum, e.tolerance))
            out.push_back("expected the basis functions of " + name + " to sum to " +
                          geom::format_number(*e.basis_sum) + " at " + where + ", found " +
                          geom::format_number(sum) + tol);
        if (e.basis && e.i && !near(one, *e.basis, e.tolerance)) {
            const std::string label =
                "R" + std::to_string(*e.i) + (s ? "," + std::to_string(e.j.value_or(-1)) : "");
            out.push_back("expected " + label + " of " + name + " at " + where + " to be " +
                          geom::format_number(*e.basis) + ", found " + geom::format_number(one) +
                          tol);
        }
    }
    if ((e.gaussian || e.mean) && s) {
        const auto k = geom::surface_curvature(*s, u, v);
        if (!k) {
            out.push_back(name + " has no curvature at " + where + " (a degenerate normal)");
        } else {
            if (e.gaussian && !near(k->gaussian, *e.gaussian, e.tolerance))
                out.push_back("expected the Gaussian curvature of " + name + " at " + where +
                              " to be " + geom::format_number(*e.gaussian) + ", found " +
                              geom::format_number(k->gaussian) + tol);
            if (e.mean && !near(k->mean, *e.mean, e.tolerance))
                out.push_back("expected the mean curvature of " + name + " at " + where +
                              " to be " + geom::format_number(*e.mean) + ", found " +
                              geom::format_number(k->mean) + tol);
        }
    }
}

// An expect object's members, read one by one with the paths their errors name.
struct MemberReader {
    const json& v;
    const std::string& at;

    const json* member(std::string_view name) const { return find_member(v, name); }
    std::string path(std::string_view name) const { return member_path(at, name); }
    geom::Status number(std::string_view name, std::optional<double>& into) const {
        if (const json* m = member(name)) {
            auto x = read_finite(*m, path(name), name);
            if (!x) return x.error();
            into = *x;
        }
        return geom::Ok{};
    }
};

// What the expect names: the object count, the object, its kind, point, position, weight and
// knots.
geom::Status read_object_members(const MemberReader& r, ExpectStep& e) {
    auto member = [&](std::string_view name) { return r.member(name); };
    auto path = [&](std::string_view name) { return r.path(name); };
    if (const json* m = member("objects")) {
        auto n = read_integer(*m, path("objects"), "objects", 0, 1 << 30);
        if (!n) return n.error();
        e.objects = static_cast<std::size_t>(*n);
    }
    if (const json* m = member("id")) {
        auto n = read_integer(*m, path("id"), "an object id", 1,
                              static_cast<std::int64_t>(max_object_id));
        if (!n) return n.error();
        e.id = static_cast<std::uint64_t>(*n);
    }
    if (const json* m = member("kind")) {
        const auto k = enum_value<doc::ObjectKind>(*m);
        if (!k) return schema_error("kind is surface, curve, implicit or triangle", path("kind"));
        e.kind = *k;
    }
    if (const json* m = member("point")) {
        if (!m->is_array() || m->empty() || m->size() > 2)
            return schema_error("point is [i, j] (a surface's) or [i] (a curve's)", path("point"));
        for (std::size_t k = 0; k < m->size(); ++k) {
            auto n = read_integer((*m)[k], path("point") + "/" + std::to_string(k),
                                  "a control point index", 0, 1 << 30);
            if (!n) return n.error();
            (k == 0 ? e.i : e.j) = static_cast<int>(*n);
        }
    }
    if (const json* m = member("position")) {
        auto p = read_point(*m, path("position"), "a position");
        if (!p) return p.error();
        e.position = *p;
    }
    if (auto st = r.number("weight", e.weight); !st) return st.error();
    if (const json* m = member("direction")) {
        const auto d = enum_value<geom::Dir>(*m);
        if (!d) return schema_error("direction is \"u\" or \"v\"", path("direction"));
        e.direction = *d;
    }
    if (const json* m = member("knots")) {
        auto k = read_numbers(*m, path("knots"), "knots");
        if (!k) return k.error();
        e.knots = *k;
    }
    return geom::Ok{};
}

// The degree, type, patch group, borders, the parameter and the values expected there.
geom::Status read_value_members(const MemberReader& r, ExpectStep& e) {
    auto member = [&](std::string_view name) { return r.member(name); };
    auto path = [&](std::string_view name) { return r.path(name); };
    if (const json* m = member("degree")) {
        auto n = read_integer(*m, path("degree"), "degree", 1, 1 << 20);
        if (!n) return n.error();
        e.degree = static_cast<int>(*n);
    }
    if (const json* m = member("type")) {
        const auto t = enum_value<geom::SplineType>(*m);
        if (!t)
            return schema_error("type is bezier, rational_bezier, bspline or nurbs", path("type"));
        e.type = *t;
    }
    if (const json* m = member("group")) {
        auto n = read_integer(*m, path("group"), "a patch group id", 1,
                              static_cast<std::int64_t>(max_object_id));
        if (!n) return n.error();
        e.group = static_cast<std::uint64_t>(*n);
    }
    if (const json* m = member("borders")) {
        auto c = continuity_from_json(*m, path("borders"));
        if (!c) return c.error();
        e.borders = *c;
    }
    if (const json* m = member("at")) {
        auto a = read_numbers(*m, path("at"), "at");
        if (!a) return a.error();
        if (a->empty() || a->size() > 2)
            return schema_error("at is [u, v] (a surface's parameters) or [t] (a curve's)",
                                path("at"));
        e.at = glm::dvec2((*a)[0], a->size() > 1 ? (*a)[1] : 0.0);
    }
    for (auto [name, into] : {std::pair{"basis", &e.basis}, std::pair{"basis_sum", &e.basis_sum},
                              std::pair{"gaussian", &e.gaussian}, std::pair{"mean", &e.mean}})
        if (auto st = r.number(name, *into); !st) return st.error();
    if (const json* m = member("side")) {
        const auto side = enum_value<geom::TrimSide>(*m);
        if (!side) return schema_error("side is kept, cut or boundary", path("side"));
        e.side = *side;
    }
    if (const json* m = member("tolerance")) {
        auto t = read_finite(*m, path("tolerance"), "tolerance");
        if (!t) return t.error();
        if (*t < 0) return schema_error("tolerance is 0 or more", path("tolerance"));
        e.tolerance = *t;
    }
    return geom::Ok{};
}

// The members that only make sense together.
geom::Status check_expect_members(const ExpectStep& e, const std::string& at) {
    const bool about_object = e.i || e.position || e.weight || e.knots || e.degree || e.type ||
                              e.kind || e.at || e.basis || e.basis_sum || e.gaussian || e.mean ||
                              e.side;
    if (about_object && !e.id)
        return schema_error("an expect about an object's point, weight, knots, degree, kind, type "
                            "or values at a parameter names the object: add \"id\"",
                            at);
    if ((e.weight || (e.position && !e.at)) && !e.i)
        return schema_error("an expected position or weight belongs to a point: add \"point\" "
                            "(or \"at\" for the object's point at a parameter)",
                            at);
    if ((e.basis || e.basis_sum || e.gaussian || e.mean || e.side) && !e.at)
        return schema_error("a basis function, a curvature or the side of a trim is taken at a "
                            "parameter: add \"at\"",
                            at);
    if (e.basis && !e.i)
        return schema_error("a basis function belongs to a control point: add \"point\"", at);
    if (e.at && e.position && e.i)
        return schema_error("with \"at\", position is the object's point there: leave out "
                            "\"point\" (or \"at\" for the control point's position)",
                            at);
    if (e.borders && !e.group)
        return schema_error("an expect about borders names the patch group: add \"group\"", at);
    return geom::Ok{};
}

} // namespace

Expected<ExpectStep> expect_from_json(const json& v, const std::string& at) {
    if (auto st = expect_object(v, at, "expect"); !st) return st.error();
    if (auto st = check_members(v, at, "expect",
                                {"objects", "id", "kind", "point", "position", "weight",
                                 "direction", "knots", "degree", "type", "group", "borders", "at",
                                 "basis", "basis_sum", "gaussian", "mean", "side", "tolerance"});
        !st)
        return st.error();
    ExpectStep e;
    const MemberReader r{v, at};
    if (auto st = read_object_members(r, e); !st) return st.error();
    if (auto st = read_value_members(r, e); !st) return st.error();
    if (auto st = check_expect_members(e, at); !st) return st.error();
    return e;
}

json expect_to_json(const ExpectStep& e) {
    json j = json::object();
    if (e.objects) j["objects"] = *e.objects;
    if (e.id) j["id"] = *e.id;
    if (e.kind) j["kind"] = geom::name_of(*e.kind);
    if (e.i) {
        j["point"] = json::array({*e.i});
        if (e.j) j["point"].push_back(*e.j);
    }
    if (e.position) j["position"] = point_to_json(*e.position);
    if (e.weight) j["weight"] = *e.weight;
    if (e.knots || e.degree) j["direction"] = geom::name_of(e.direction);
    if (e.knots) j["knots"] = *e.knots;
    if (e.degree) j["degree"] = *e.degree;
    if (e.type) j["type"] = geom::name_of(*e.type);
    if (e.group) j["group"] = *e.group;
    if (e.borders) j["borders"] = doc::continuity_name(*e.borders);
    if (e.at) j["at"] = {e.at->x, e.at->y};
    if (e.basis) j["basis"] = *e.basis;
    if (e.basis_sum) j["basis_sum"] = *e.basis_sum;
    if (e.gaussian) j["gaussian"] = *e.gaussian;
    if (e.mean) j["mean"] = *e.mean;
    if (e.side) j["side"] = geom::name_of(*e.side);
    if (e.tolerance != 1e-9) j["tolerance"] = e.tolerance;
    return j;
}

std::vector<std::string> unmet_expectations(const ExpectStep& e, const doc::Document& d) {
    std::vector<std::string> out;
    const std::string tol = " (tolerance " + geom::format_number(e.tolerance) + ")";
    if (e.objects && d.objects.size() != *e.objects)
        out.push_back("expected " + std::to_string(*e.objects) + " objects, found " +
                      std::to_string(d.objects.size()));
    if (e.borders) {
        if (!doc::continuity_holds(d, *e.group, *e.borders, e.tolerance))
            out.push_back("expected the borders of patch group " + std::to_string(*e.group) +
                          " to hold " + doc::continuity_name(*e.borders) + tol);
    }
    if (!e.id) return out;
    const doc::Object* o = d.find(*e.id);
    if (!o) {
        out.push_back("expected an object with id " + std::to_string(*e.id) + ", found none");
        return out;
    }
    const std::string name = "'" + o->name + "'";
    if (e.kind && o->kind() != *e.kind) {
        out.push_back("expected " + name + " to be a " + doc::kind_name(*e.kind) + ", it is a " +
                      doc::kind_name(o->kind()));
        return out;
    }
    const geom::Surface* s = o->surface();
    const geom::Curve* c = o->curve();
    if (const geom::TrianglePatch* t = o->triangle()) {
        auto more = unmet_on_triangle(e, o->name, *t);
        out.insert(out.end(), more.begin(), more.end());
        return out;
    }
    if (!s && !c) {
        if (e.i || e.knots || e.degree || e.type || e.at)
            out.push_back(name + " is an implicit surface: it has no points, knots or degree");
        return out;
    }
    if (e.type) {
        const geom::SplineType t = s ? s->type : c->type;
        if (t != *e.type)
            out.push_back("expected " + name + " to be " + geom::name_of(*e.type) + ", it is " +
                          geom::name_of(t));
    }
    if (e.degree) {
        const int p = s ? s->degree(e.direction) : c->degree;
        if (p != *e.degree)
            out.push_back("expected " + name + "'s degree" +
                          (s ? std::string(" in ") + geom::name_of(e.direction) : "") + " to be " +
                          std::to_string(*e.degree) + ", it is " + std::to_string(p));
    }
    if (e.knots) {
        const geom::Knots& U = s ? s->knots(e.direction) : c->knots;
        bool same = U.size() == e.knots->size();
        for (std::size_t k = 0; same && k < U.size(); ++k)
            same = near(U[k], (*e.knots)[k], e.tolerance);
        if (!same)
            out.push_back("expected " + name + "'s knots" +
                          (s ? std::string(" in ") + geom::name_of(e.direction) : "") + " " +
                          list_text(*e.knots) + ", found " + list_text(U) + tol);
    }
    if (e.i) {
        const int i = *e.i, j = e.j.value_or(-1);
        const bool in_range = s ? (i < s->n_u && j >= 0 && j < s->n_v) : (i < c->count() && j < 0);
        const std::string label =
            "P" + std::to_string(i) + (j >= 0 ? "," + std::to_string(j) : std::string());
        if (!in_range) {
            out.push_back(name + " has no control point " + label);
            return out;
        }
        const std::size_t index = static_cast<std::size_t>(s ? s->index(i, j) : i);
        const glm::dvec3 p = s ? s->points[index] : c->points[index];
        const double w = s ? s->weights[index] : c->weights[index];
        if (e.position && !e.at && !near(p, *e.position, e.tolerance))
            out.push_back("expected " + label + " of " + name + " at " + vec_text(*e.position) +
                          ", found " + vec_text(p) + tol);
        if (e.weight && !near(w, *e.weight, e.tolerance))
            out.push_back("expected the weight of " + label + " of " + name + " to be " +
                          geom::format_number(*e.weight) + ", found " + geom::format_number(w) +
                          tol);
    }
    if (e.at) unmet_at_parameter(e, name, s, c, out);
    if (e.side) unmet_side(e, name, *o, s, out);
    return out;
}

} // namespace isoparm::scene
