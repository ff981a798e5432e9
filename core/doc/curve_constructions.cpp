// The Construct menu's constructions on document curves, errors re-worded with curve names.
#include "core/doc/curve_constructions.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>

#include "core/doc/commands_common.hpp"
#include "core/doc/recipe_build.hpp"
#include "core/geom/coons.hpp"
#include "core/geom/gordon.hpp"
#include "core/geom/validate.hpp"

namespace isoparm::doc {

using geom::ErrorCode;
using geom::make_error;

namespace {

// How many curves each construction takes: [min, max].
std::pair<std::size_t, std::size_t> curve_count(Construction kind) {
    switch (kind) {
    case Construction::revolve:
        return {1, 1};
    case Construction::skin:
        return {2, static_cast<std::size_t>(geom::max_points_per_direction)};
    case Construction::coons:
        return {4, 4};
    case Construction::gordon:
        return {4, 2 * static_cast<std::size_t>(geom::max_points_per_direction)};
    default:
        return {2, 2};
    }
}

// The role of curve k in the request, for messages: "profile", "trajectory", "curve 2".
std::string role(Construction kind, std::size_t k, int gordon_u_count = 0) {
    static const char* coons_roles[] = {"boundary S(u, 0)", "boundary S(u, 1)", "boundary S(0, v)",
                                        "boundary S(1, v)"};
    switch (kind) {
    case Construction::coons:
        return coons_roles[std::min<std::size_t>(k, 3)];
    case Construction::gordon:
        return static_cast<int>(k) < gordon_u_count
                   ? "u-curve " + std::to_string(k + 1)
                   : "v-curve " + std::to_string(k + 1 - static_cast<std::size_t>(gordon_u_count));
    case Construction::revolve:
        return "profile";
    case Construction::swing:
    case Construction::sweep:
    case Construction::oriented_sweep:
        return k == 0 ? "profile" : "trajectory";
    default:
        return "curve " + std::to_string(k + 1);
    }
}

// A geometry error re-homed at the request: "/profile/..." and "/trajectory/..." become
// "/curves/0/..." and "/curves/1/..."; an error about one curve names it; an error about all
// of them lists them in order.
geom::Error rehome(geom::Error e, const std::vector<const Object*>& objects,
                   int gordon_u_count = 0) {
    if (!e.has_path) return e;
    auto starts = [&](const std::string& p) {
        return e.path == p || e.path.compare(0, p.size() + 1, p + "/") == 0;
    };
    if (starts("/profile"))
        e.path = "/curves/0" + e.path.substr(8);
    else if (gordon_u_count > 0 && (starts("/u_curves") || starts("/v_curves"))) {
        // Gordon's two families are one list here: the u-curves, then the v-curves.
        const std::size_t offset = e.path[1] == 'v' ? static_cast<std::size_t>(gordon_u_count) : 0;
        const std::string rest = e.path.substr(9); // "" or "/k..."
        if (rest.empty()) {
            e.path = "/curves";
        } else {
            const std::size_t end = rest.find('/', 1);
            const std::string digits = rest.substr(1, end == std::string::npos ? end : end - 1);
            std::size_t k = 0;
            std::from_chars(digits.data(), digits.data() + digits.size(), k);
            e.path = "/curves/" + std::to_string(k + offset) +
                     (end == std::string::npos ? std::string() : rest.substr(end));
        }
    } else if (starts("/trajectory"))
        e.path = "/curves/1" + e.path.substr(11);
    const std::string prefix = "/curves/";
    if (e.path.compare(0, prefix.size(), prefix) == 0) {
        const std::size_t end = e.path.find('/', prefix.size());
        const std::string digits = e.path.substr(prefix.size(), end - prefix.size());
        std::size_t k = objects.size();
        std::from_chars(digits.data(), digits.data() + digits.size(), k);
        if (k < objects.size()) e.message = "curve '" + objects[k]->name + "': " + e.message;
    } else if (e.path == "/curves") {
        std::string names;
        for (std::size_t k = 0; k < objects.size(); ++k)
            names += (k ? ", '" : "'") + objects[k]->name + "'";
        e.message += " (curves in order: " + names + ")";
    }
    return e;
}

geom::Expected<ConstructionResult> build_from_curves(const Document& doc,
                                                     const ConstructionRequest& request);

std::string join_names(const std::vector<const Object*>& objects) {
    std::string s;
    for (std::size_t k = 0; k < objects.size(); ++k) s += (k ? "-" : "") + objects[k]->name;
    return s;
}

} // namespace

geom::Expected<ConstructionResult> build_construction(const Document& doc,
                                                      const ConstructionRequest& request) {
    auto built = request.kind == Construction::isocurve ? detail::build_isocurve(doc, request)
                                                        : build_from_curves(doc, request);
    if (!built) return built;
    if (auto st = detail::apply_refinements(*built, request.refinements); !st) return st.error();
    return built;
}

namespace {

// The request's curves, checked: as many as the construction takes, each a curve.
struct Chosen {
    std::vector<const Object*> objects;
    std::vector<geom::Curve> curves;
};
geom::Expected<Chosen> chosen_curves(const Document& doc, const ConstructionRequest& request) {
    const Construction kind = request.kind;
    const auto [lo, hi] = curve_count(kind);
    const std::size_t n = request.curves.size();
    if (n < lo || n > hi) {
        std::string want = lo == hi ? std::to_string(lo) : "at least " + std::to_string(lo);
        if (kind == Construction::swing || kind == Construction::sweep ||
            kind == Construction::oriented_sweep)
            want += " (a profile and a trajectory)";
        return make_error(ErrorCode::schema,
                          std::string(construction_label(kind)) + " takes " + want + " curve" +
                              (lo == 1 && hi == 1 ? "" : "s") + ", got " + std::to_string(n),
                          "/curves");
    }
    Chosen out;
    for (std::size_t k = 0; k < n; ++k) {
        const std::string at = "/curves/" + std::to_string(k);
        const Object* o = doc.find(request.curves[k]);
        if (!o)
            return make_error(ErrorCode::schema,
                              "there is no object with id " + std::to_string(request.curves[k]),
                              at);
        const CurveObject* c = o->curve_object();
        if (!c)
            return make_error(ErrorCode::schema,
                              "the " + role(kind, k, request.gordon_u_count) + " '" + o->name +
                                  "' is " + kind_noun(o->kind()) + ", not a curve",
                              at);
        out.objects.push_back(o);
        out.curves.push_back(c->curve);
    }
    return out;
}

// The surface the construction builds from the chosen curves, and the note it leaves.
geom::Expected<geom::Surface> construct_surface(const ConstructionRequest& request,
                                                const Chosen& chosen, std::string& note) {
    const Construction kind = request.kind;
    const std::vector<geom::Curve>& curves = chosen.curves;
    const std::vector<const Object*>& objects = chosen.objects;
    const std::size_t n = curves.size();
    geom::Surface surface;
    switch (kind) {
    case Construction::ruled: {
        auto r = geom::ruled(curves[0], curves[1]);
        if (!r) return rehome(r.error(), objects);
        surface = std::move(r).value();
        break;
    }
    case Construction::revolve: {
        auto r = geom::revolve(curves[0], request.angle);
        if (!r)
            return rehome(r.error().under(r.error().path == "/angle" ? "" : "/curves/0"), objects);
        surface = std::move(r).value();
        break;
    }
    case Construction::swing: {
        auto r = geom::swing(curves[0], curves[1], request.scale);
        if (!r) return rehome(r.error(), objects);
        surface = std::move(r).value();
        break;
    }
    case Construction::sweep: {
        auto r = geom::sweep(curves[0], curves[1]);
        if (!r) return rehome(r.error(), objects);
        surface = std::move(r).value();
        break;
    }
    case Construction::oriented_sweep: {
        geom::OrientedSweepOptions options;
        options.sections = request.sections;
        auto r = geom::oriented_sweep(curves[0], curves[1], options);
        if (!r) return rehome(r.error(), objects);
        surface = std::move(r->skinned.surface);
        note = "oriented sweep of " + std::to_string(r->sections + 1) +
               " profile copies: largest deviation from the ideal sweep " +
               geom::format_short(r->max_deviation) + " at (u, v) = (" +
               geom::format_short(r->deviation_u) + ", " + geom::format_short(r->deviation_v) +
               "); more sections make it smaller";
        break;
    }
    case Construction::skin: {
        const int count = static_cast<int>(n);
        const int degree =
            request.skin_degree == 0 ? geom::default_skin_degree(count) : request.skin_degree;
        if (degree < 1 || degree > count - 1)
            return make_error(ErrorCode::schema,
                              "the skin's v-degree must be 1.." + std::to_string(count - 1) +
                                  " for " + std::to_string(count) + " curves, got " +
                                  std::to_string(degree) + " (more curves allow a higher degree)",
                              "/degree");
        auto r = geom::skin(curves, degree, request.parametrization);
        if (!r) return rehome(r.error(), objects);
        surface = std::move(r->surface);
        note = std::string("skin of ") + std::to_string(count) + " curves, v-degree " +
               std::to_string(degree) + ", " + geom::parametrization_name(request.parametrization) +
               " parameters v =";
        for (double v : r->params) note += " " + geom::format_short(v);
        break;
    }
    case Construction::coons: {
        auto r = geom::coons({curves[0], curves[1], curves[2], curves[3]});
        if (!r) return rehome(r.error(), objects);
        surface = std::move(r).value();
        note = "Coons patch: the ruled surfaces between opposite boundaries, added, minus "
               "the bilinear patch of the corners; it keeps all four boundaries exactly";
        break;
    }
    case Construction::isocurve: // built by build_isocurve
        break;
    case Construction::gordon: {
        const int nu = request.gordon_u_count;
        if (nu < 2 || static_cast<int>(n) - nu < 2)
            return make_error(
                ErrorCode::schema,
                "a Gordon network needs at least 2 u-curves and 2 v-curves: " + std::to_string(nu) +
                    " of the " + std::to_string(n) + " curves were named u-curves",
                "/gordon_u_count");
        const std::vector<geom::Curve> u_curves(curves.begin(), curves.begin() + nu);
        const std::vector<geom::Curve> v_curves(curves.begin() + nu, curves.end());
        auto r = geom::gordon(u_curves, v_curves);
        if (!r) return rehome(r.error(), objects, nu);
        surface = std::move(r->surface);
        note = "Gordon surface through " + std::to_string(nu) + " u-curves (at v =";
        for (double v : r->v_params) note += " " + geom::format_short(v);
        note += ") and " + std::to_string(n - nu) + " v-curves (at u =";
        for (double u : r->u_params) note += " " + geom::format_short(u);
        note += ")";
        break;
    }
    }
    return surface;
}

geom::Expected<ConstructionResult> build_from_curves(const Document& doc,
                                                     const ConstructionRequest& request) {
    auto chosen = chosen_curves(doc, request);
    if (!chosen) return chosen.error();
    ConstructionResult out;
    auto surface = construct_surface(request, *chosen, out.note);
    if (!surface) return surface.error();
    std::string name = construction_label(request.kind);
    std::transform(name.begin(), name.end(), name.begin(),
                   [](unsigned char ch) { return static_cast<char>(std::tolower(ch)); });
    out.object.name = name + " " + join_names(chosen->objects);
    out.object.shape = SurfaceObject{std::move(surface).value()};
    return out;
}

} // namespace

} // namespace isoparm::doc
